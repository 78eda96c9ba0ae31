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
    bands: int = 12  # radial bins of the cavity's profile
    sectors: int = 12  # wall pieces around
    segments: int = 3  # wall pieces up (equal lengths along the profile)
    min_wall: float = 0.003  # m
    max_wall_share: float = 0.25  # of the rim radius
    min_floor: float = 0.002  # thinnest bottom (m)


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


def _inner_profile(points: np.ndarray, centre: np.ndarray, radius: float, floor: float, top_z: float, bins: int,
                   camera_xy: np.ndarray | None) -> tuple[np.ndarray, np.ndarray]:
    """The cavity's surface as heights over radii (r, z), r from the axis to ``radius``: per radial
    bin the median height of the points seen inside the rim (on the side away from the camera, where
    the camera sees the inner wall), non-decreasing outwards, from ``floor`` up to the rim at ``top_z``."""
    rel = points[:, :2] - centre
    r = np.linalg.norm(rel, axis=1)
    inside = r < radius
    if camera_xy is not None and np.linalg.norm(centre - camera_xy) > 1e-6:
        away = (centre - camera_xy) / np.linalg.norm(centre - camera_xy)
        far = inside & (rel @ away > 0)
        inside = far if far.sum() >= 20 else inside
    edges = np.linspace(0.0, radius, bins + 1)
    mids = (edges[:-1] + edges[1:]) / 2
    heights = np.full(bins, np.nan)
    for i in range(bins):
        near = inside & (r >= edges[i]) & (r < edges[i + 1])
        if near.sum() >= 5:
            heights[i] = float(np.median(points[near, 2]))
    good = np.isfinite(heights)
    heights = np.interp(mids, mids[good], heights[good]) if good.any() else np.full(bins, floor)
    heights = np.clip(np.maximum.accumulate(np.clip(heights, floor, top_z)), floor, top_z)
    return np.concatenate([[0.0], mids, [radius]]), np.concatenate([[heights[0]], heights, [top_z]])


def _offset(r: np.ndarray, z: np.ndarray, wall: float) -> tuple[np.ndarray, np.ndarray]:
    """The (r, z) polyline moved ``wall`` along its normal away from the cavity (outwards and down)."""
    dr, dz = np.gradient(r), np.gradient(z)
    length = np.maximum(np.hypot(dr, dz), 1e-12)
    return r + wall * dz / length, z - wall * dr / length


def _ring(radius: float, z: float, angles: np.ndarray, centre: np.ndarray) -> np.ndarray:
    return np.column_stack([centre[0] + radius * np.cos(angles), centre[1] + radius * np.sin(angles), np.full(len(angles), z)])


def complete_open_container(points: np.ndarray, centre: np.ndarray, radius: float, base_z: float, top_z: float,
                            params: ContainerParams = ContainerParams(), camera_xy: np.ndarray | None = None,
                            seen_inside: np.ndarray | None = None) -> OpenContainer | None:
    """The hollow solid of an open round container, or None when its observed top is not hollow.

    The cavity is the surface seen inside the rim (see :func:`_inner_profile`; ``seen_inside``: every
    point the camera saw within the rim, whatever object it was given to: a shallow floor is often
    taken for the support), the wall that surface moved outwards by the thickness scanned at the
    rim, the bottom solid down to the support."""
    if not params.enabled:
        return None
    height = top_z - base_z
    floor = cavity_floor(points, centre, radius, height, params.min_depth)
    if floor is None:
        return None
    cavity = points if seen_inside is None else np.vstack([points, seen_inside])
    inner = cavity[np.linalg.norm(cavity[:, :2] - centre, axis=1) < 0.7 * radius]
    floor = min(floor, float(np.percentile(inner[:, 2], 10))) if len(inner) >= 20 else floor
    floor = float(np.clip(floor, base_z + params.min_floor, top_z - 0.2 * height))
    rim = points[points[:, 2] >= top_z - 0.1 * height]
    rr = np.linalg.norm(rim[:, :2] - centre, axis=1) if len(rim) else np.array([radius])
    wall = float(np.clip(np.percentile(rr, 95) - np.percentile(rr, 5), params.min_wall, params.max_wall_share * radius))
    r_in, z_in = _inner_profile(cavity, centre, radius - wall / 2, floor, top_z, params.bands, camera_xy)
    r_out, z_out = _offset(r_in, z_in, wall)
    r_out[-1], z_out[-1] = r_in[-1] + wall, top_z  # the rim: flat, one wall wide
    wall_part = (z_out > base_z) & (r_out > r_in[1])
    r_out, z_out = r_out[wall_part], z_out[wall_part]
    foot = float(r_out[0]) if len(r_out) else radius
    # the visual: revolve the closed profile (axis -> foot -> outer wall -> rim -> inner wall -> floor -> axis)
    line = np.vstack([[0.0, base_z], [foot, base_z], np.column_stack([r_out, z_out]), np.column_stack([r_in[::-1], z_in[::-1]]), [0.0, z_in[0]]])
    visual = trimesh.creation.revolve(line, sections=32)
    visual.apply_translation([centre[0], centre[1], 0.0])
    if visual.volume < 0:
        visual.invert()
    # collision: the bottom (support to cavity floor) and wall pieces, ``sectors`` around, ``segments`` up
    angles = np.linspace(0.0, 2 * np.pi, params.sectors + 1)
    fine = np.linspace(0.0, 2 * np.pi, 4 * params.sectors + 1)[:-1]
    flat = z_in <= z_in[0] + 0.1 * (top_z - z_in[0])
    floor_r = float(r_in[flat].max()) if flat.any() else foot
    pieces = [trimesh.convex.convex_hull(np.vstack([_ring(foot, base_z, fine, centre), _ring(max(floor_r, 1e-3), float(z_in[0]), fine, centre)]))]
    wall_r, wall_z = r_in[r_in >= floor_r], z_in[r_in >= floor_r]  # from the floor's edge up to the rim
    out_r, out_z = _offset(wall_r, wall_z, wall)
    out_r[-1], out_z[-1] = wall_r[-1] + wall, top_z
    out_z = np.maximum(out_z, base_z)
    length = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(wall_r), np.diff(wall_z)))])
    cuts = np.linspace(0.0, length[-1], params.segments + 1)  # equal lengths along the profile: short where it bends
    for s0, s1 in zip(cuts[:-1], cuts[1:]):
        at = np.concatenate([[s0], length[(length > s0) & (length < s1)], [s1]])
        ring_r = np.concatenate([np.interp(at, length, wall_r), np.interp(at, length, out_r)])
        ring_z = np.concatenate([np.interp(at, length, wall_z), np.interp(at, length, out_z)])
        for a0, a1 in zip(angles[:-1], angles[1:]):
            arc = np.linspace(a0, a1, 3)
            pieces.append(trimesh.convex.convex_hull(np.vstack([_ring(float(x), float(zz), arc, centre) for x, zz in zip(ring_r, ring_z)])))
    outer = trimesh.convex.convex_hull(np.vstack([_ring(foot, base_z, fine, centre)] + [_ring(float(x), float(zz), fine, centre) for x, zz in zip(r_out, z_out)]))
    return OpenContainer(pieces, visual, outer, wall, float(z_in[0]))
