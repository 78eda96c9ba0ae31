"""Open round containers (bowls, cups, mugs without their handle) completed hollow by revolution.

A round object whose observed top is hollow (the points near its axis lie well below those at
its rim) is an open container. Its outer wall is the revolution of the visible profile (the
outer radius of the observed points per height band, made monotone so the solid stays convex),
its cavity the same profile moved inward by the wall thickness scanned at the rim (the radial
spread of the rim points), down to the observed cavity floor. Collision is a bottom disc and
``sectors`` convex wall pieces; the visual mesh is the revolved profile itself.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from realsim.completion.circles import arc_coverage_deg, fit_circle


@dataclass(frozen=True)
class ContainerParams:
    """How an open container is recognised and built."""

    enabled: bool = True
    min_depth: float = 0.3  # cavity depth (rim minus floor) as a share of the height that makes it open
    bands: int = 8  # height bands of the revolved profile
    sectors: int = 16  # convex wall pieces
    min_wall: float = 0.003  # m
    max_wall_share: float = 0.25  # of the rim radius
    min_floor: float = 0.004  # thinnest bottom (m)


@dataclass
class OpenContainer:
    """A hollow round solid (world frame): convex collision pieces and the revolved visual."""

    pieces: list[trimesh.Trimesh]
    visual: trimesh.Trimesh
    outer: trimesh.Trimesh  # the convex outer solid (for stacking, carving and neighbours)
    wall: float
    floor_z: float


def cavity_floor(points: np.ndarray, centre: np.ndarray, radius: float, height: float, min_depth: float) -> float | None:
    """The height of the cavity floor (the lowest tenth of the points inside the rim) when the
    observed top is hollow (most of them lie well below the rim), else None."""
    r = np.linalg.norm(points[:, :2] - centre, axis=1)
    inner, rim = points[r < 0.7 * radius], points[(r > 0.8 * radius) & (r < 1.15 * radius)]
    if len(inner) < 20 or len(rim) < 20:
        return None
    rim_z = float(np.percentile(rim[:, 2], 90))
    if rim_z - float(np.percentile(inner[:, 2], 25)) <= min_depth * height:
        return None
    return float(np.percentile(inner[:, 2], 10))


def round_rim(points: np.ndarray, base_z: float, top_z: float, max_radius: float, max_rms: float = 0.08,
              min_arc_deg: float = 240.0) -> tuple[np.ndarray, float] | None:
    """(centre, radius) of a circular rim seen from above (the top band of the points), or None."""
    rim = points[points[:, 2] >= top_z - 0.15 * (top_z - base_z)]
    if len(rim) < 30:
        return None
    centre, radius, rms = fit_circle(rim[:, :2])
    if radius > max_radius or rms > max_rms * radius or arc_coverage_deg(rim[:, :2], centre) < min_arc_deg:
        return None
    return centre, radius


def _profile(points: np.ndarray, centre: np.ndarray, radius: float, base_z: float, top_z: float, bands: int) -> tuple[np.ndarray, np.ndarray]:
    """Outer radius per height (z, r), non-decreasing upwards and concave so the solid is convex."""
    r = np.linalg.norm(points[:, :2] - centre, axis=1)
    z = np.linspace(base_z, top_z, bands + 1)
    radii = np.full(bands + 1, np.nan)
    for i in range(bands + 1):
        near = np.abs(points[:, 2] - z[i]) <= (top_z - base_z) / bands
        if near.sum() >= 10:
            radii[i] = float(np.percentile(r[near], 90))
    good = np.isfinite(radii)
    if good.sum() < 2:
        return z, np.full(bands + 1, radius)
    radii = np.interp(z, z[good], radii[good])
    radii = np.minimum(np.maximum.accumulate(radii), radius * 1.05)
    # the upper concave envelope of (z, r): a convex solid of revolution
    hull = [0]
    for i in range(1, len(z)):
        while len(hull) >= 2:
            a, b = hull[-2], hull[-1]
            if (radii[b] - radii[a]) * (z[i] - z[a]) <= (radii[i] - radii[a]) * (z[b] - z[a]):
                hull.pop()
            else:
                break
        hull.append(i)
    return z, np.interp(z, z[hull], radii[hull])


def _ring(radius: float, z: float, angles: np.ndarray, centre: np.ndarray) -> np.ndarray:
    return np.column_stack([centre[0] + radius * np.cos(angles), centre[1] + radius * np.sin(angles), np.full(len(angles), z)])


def complete_open_container(points: np.ndarray, centre: np.ndarray, radius: float, base_z: float, top_z: float,
                            params: ContainerParams = ContainerParams()) -> OpenContainer | None:
    """The hollow solid of an open round container, or None when its observed top is not hollow."""
    if not params.enabled:
        return None
    height = top_z - base_z
    floor = cavity_floor(points, centre, radius, height, params.min_depth)
    if floor is None:
        return None
    floor = float(np.clip(floor, base_z + params.min_floor, top_z - 0.2 * height))
    z, r_out = _profile(points, centre, radius, base_z, top_z, params.bands)
    rim = points[points[:, 2] >= top_z - 0.1 * height]
    rr = np.linalg.norm(rim[:, :2] - centre, axis=1) if len(rim) else np.array([radius])
    wall = float(np.clip(np.percentile(rr, 95) - np.percentile(rr, 5), params.min_wall, params.max_wall_share * r_out[-1]))
    r_in = np.maximum(r_out - wall, 0.2 * r_out)
    # the visual: revolve the closed profile (axis -> outer wall -> rim -> inner wall -> floor -> axis)
    inner = z >= floor
    zin = np.concatenate([[floor], z[inner]])
    rin = np.interp(zin, z, r_in)
    line = np.vstack([[0.0, base_z], np.column_stack([r_out, z]), np.column_stack([rin[::-1], zin[::-1]]), [0.0, floor]])
    visual = trimesh.creation.revolve(line, sections=32)
    visual.apply_translation([centre[0], centre[1], 0.0])
    if visual.volume < 0:
        visual.invert()
    # collision: a bottom disc and wall sectors between the outer and inner profiles
    angles = np.linspace(0.0, 2 * np.pi, params.sectors + 1)
    fine = np.linspace(0.0, 2 * np.pi, 4 * params.sectors + 1)[:-1]
    bottom = np.vstack([_ring(float(np.interp(zz, z, r_out)), zz, fine, centre) for zz in (base_z, floor)])
    pieces = [trimesh.convex.convex_hull(bottom)]
    for a0, a1 in zip(angles[:-1], angles[1:]):
        arc = np.linspace(a0, a1, 3)
        cloud = np.vstack([_ring(float(ro), float(zz), arc, centre) for zz, ro in zip(zin, np.interp(zin, z, r_out))] +
                          [_ring(float(ri), float(zz), arc, centre) for zz, ri in zip(zin, rin)])
        pieces.append(trimesh.convex.convex_hull(cloud))
    outer = trimesh.convex.convex_hull(np.vstack([_ring(float(ro), float(zz), fine, centre) for zz, ro in zip(z, r_out)]))
    return OpenContainer(pieces, visual, outer, wall, floor)
