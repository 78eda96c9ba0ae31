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
from realsim.completion.hull import trimesh_hull


@dataclass(frozen=True)
class ContainerParams:
    """How an open container is recognised and built."""

    enabled: bool = True
    min_depth: float = 0.3  # cavity depth (rim minus floor) as a share of the depth the camera could see inside that makes it open
    min_reach: float = 0.033  # m: that depth is taken as at least this (or the height): a grazing view must still see the inside 1 cm down
    bands: int = 12  # radial bins of the cavity's profile
    sectors: int = 12  # wall pieces around
    segments: int = 3  # wall pieces up: at least this many (when the profile has the points)
    max_bulge: float = 0.003  # m: a wall piece's profile strays at most this far from straight (more pieces up where it bends)
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
    outside: tuple[np.ndarray, np.ndarray]  # the outer wall's radius over height (heights ascending, radii)


def seeable_depth(centre: np.ndarray, radius: float, rim_z: float, height: float, camera_xy: np.ndarray | None,
                  camera_z: float | None) -> float:
    """How far below the rim the camera could see inside an open top: a line of sight over the near
    rim meets the far wall two radii on, so at most ``2 radius tan(elevation)`` down, and no deeper
    than ``height``; 0 when the camera is not above the rim (the opening cannot be seen). Without a
    camera, ``height``."""
    if camera_xy is None or camera_z is None:
        return height
    if camera_z <= rim_z:
        return 0.0
    run = float(np.linalg.norm(centre - camera_xy)) - radius  # from the camera to the near rim, across
    return height if run <= 0 else float(min(height, 2.0 * radius * (camera_z - rim_z) / run))


def cavity_floor(points: np.ndarray, centre: np.ndarray, radius: float, height: float, params: ContainerParams = ContainerParams(),
                 camera_xy: np.ndarray | None = None, camera_z: float | None = None) -> float | None:
    """The height of the cavity floor when the observed top is hollow, else None: the camera saw the
    inside lower than the rim around it, by ``params.min_depth`` of the depth it could see there
    (:func:`seeable_depth`: a deep mug seen at a grazing angle shows only the top of its far inner
    wall; a lid or a can's top, however seen, shows nothing below its rim). The floor is the lowest
    tenth of the points near the axis, or, when the camera saw too few there (a deep mug seen aslant),
    of the inside of the far wall (points within the rim on the side away from ``camera_xy``: from
    outside, the camera cannot see that side below the rim), a floor at least that deep. None when
    the camera (at height ``camera_z``) is not above the rim: the opening is not seen."""
    rel = points[:, :2] - centre
    r = np.linalg.norm(rel, axis=1)
    inner, rim = points[r < 0.7 * radius], points[(r > 0.8 * radius) & (r < 1.15 * radius)]
    if len(inner) < 20 and camera_xy is not None and np.linalg.norm(centre - camera_xy) > 1e-6:
        inner = points[(r < radius) & (rel @ (centre - camera_xy) > 0)]
    if len(inner) < 20 or len(rim) < 20:
        return None
    rim_z = float(np.percentile(rim[:, 2], 90))
    reach = seeable_depth(centre, radius, rim_z, height, camera_xy, camera_z)
    if reach <= 0.0 or rim_z - float(np.percentile(inner[:, 2], 25)) <= params.min_depth * min(height, max(reach, params.min_reach)):
        return None
    return float(np.percentile(inner[:, 2], 10))


def round_rim(points: np.ndarray, base_z: float, top_z: float, max_radius: float, max_rms: float = 0.08,
              min_arc_deg: float = 180.0, sectors: int = 48) -> tuple[np.ndarray, float] | None:
    """(centre, radius) of a circular rim seen from above (the top band of the points), or None.

    The band spans at least ``min_arc_deg`` about the centre: half a turn, as objects in front may hide
    the rest (over less, any bend fits a circle); whether the top is open is tested apart.

    The circle is fitted to the rim's crest (the highest points of each of ``sectors`` angular
    sectors), the middle of the wall on every side: the whole band would pull the centre toward the
    camera, which sees the outside of the near wall and the inside of the far one."""
    rim = points[points[:, 2] >= top_z - 0.15 * (top_z - base_z)]
    if len(rim) < 30:
        return None
    centre, radius, rms = fit_circle(rim[:, :2])
    if radius > max_radius or arc_coverage_deg(rim[:, :2], centre) < min_arc_deg:
        return None
    sector = ((np.arctan2(rim[:, 1] - centre[1], rim[:, 0] - centre[0]) + np.pi) / (2 * np.pi) * sectors).astype(np.int64) % sectors
    order = np.lexsort((-rim[:, 2], sector))
    rank = np.arange(len(order)) - np.searchsorted(sector[order], sector[order])
    crest = rim[order[rank < 3]]  # the three highest points of each sector
    if len(crest) >= 12:
        centre, radius, rms = fit_circle(crest[:, :2])
    if radius > max_radius or rms > max_rms * radius:
        return None
    return centre, radius


def _inner_profile(points: np.ndarray, centre: np.ndarray, radius: float, floor: float, top_z: float, bins: int,
                   camera_xy: np.ndarray | None, shift: float = 0.0, wall: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """The cavity's surface as a polyline (r, z) from the axis up to the rim at (``radius``, ``top_z``),
    both non-decreasing: per radial bin the median height of the points seen inside the rim (on the
    side away from the camera, where the camera sees the inner wall), bins nearer the axis than any
    evidence the floor (a deep cavity seen only on its wall), and per height band the median radius
    of those points (a steep wall, straight down to the floor below the lowest band seen). The seen surface is moved ``shift`` outwards; ``radius`` is the
    rim's (the middle of its crest), the cavity ends half a ``wall`` inside it."""
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
    heights = np.interp(mids, mids[good], heights[good], left=floor) if good.any() else np.full(bins, floor)
    heights = np.clip(np.maximum.accumulate(np.clip(heights, floor, top_z)), floor, top_z)
    # a steep wall puts all its points in one radial bin: it is sampled by height too (its radius per band)
    levels = np.linspace(heights[0], top_z, bins + 1)
    walls = [(float(np.median(r[band])), (lo + hi) / 2) for lo, hi in zip(levels[:-1], levels[1:])
             if (band := inside & (points[:, 2] >= lo) & (points[:, 2] < hi)).sum() >= 5]
    walls += walls[:1] and [(walls[0][0], float(heights[0]))]  # unseen below its lowest band, the wall goes straight down
    rz = np.vstack([np.column_stack([mids, heights]), np.array(walls).reshape(-1, 2)])
    rz = rz[np.lexsort((rz[:, 0], rz[:, 1]))]  # up the wall: by height, then outwards
    edge = radius - wall / 2
    rz[:, 0] = np.clip(np.maximum.accumulate(rz[:, 0]) + shift, 0.0, edge)
    keep = np.r_[True, np.any(np.abs(np.diff(rz, axis=0)) > 0.5e-3, axis=1)]  # no points on top of each other
    rz = rz[keep]
    return np.concatenate([[0.0], rz[:, 0], [edge]]), np.concatenate([[rz[0, 1]], rz[:, 1], [top_z]])


def _offset(r: np.ndarray, z: np.ndarray, wall: float) -> tuple[np.ndarray, np.ndarray]:
    """The (r, z) polyline moved ``wall`` along its normal away from the cavity (outwards and down)."""
    dr, dz = np.gradient(r), np.gradient(z)
    length = np.maximum(np.hypot(dr, dz), 1e-12)
    return r + wall * dz / length, z - wall * dr / length


def _side_radii(points: np.ndarray, centre: np.ndarray, camera_xy: np.ndarray, facing: float, edges: np.ndarray) -> np.ndarray:
    """Per height band (``edges``) the median distance from the axis of the points on the side facing
    the camera (``facing`` 1: the near wall's outside) or away from it (-1: the far wall's inside seen
    over the rim); NaN where a band holds fewer than five."""
    rel = points[:, :2] - centre
    r = np.linalg.norm(rel, axis=1)
    side = facing * (rel @ ((camera_xy - centre) / np.linalg.norm(camera_xy - centre))) > 0.5 * r
    out = np.full(len(edges) - 1, np.nan)
    for i, (lo, hi) in enumerate(zip(edges[:-1], edges[1:])):
        band = side & (points[:, 2] >= lo) & (points[:, 2] < hi)
        if band.sum() >= 5:
            out[i] = float(np.median(r[band]))
    return out


def _seen_outside(points: np.ndarray, centre: np.ndarray, base_z: float, top_z: float, camera_xy: np.ndarray | None,
                  bands: int) -> tuple[np.ndarray, np.ndarray] | None:
    """The outside of the wall where the camera saw it: (heights, radii), per height band the median
    distance from the axis of the points on the side facing ``camera_xy`` (the near wall's outside,
    from a tenth of the height up: lower, points of the support may have been taken for the object's);
    None without a camera or such points."""
    if camera_xy is None or np.linalg.norm(centre - camera_xy) < 1e-6:
        return None
    edges = np.linspace(base_z + 0.1 * (top_z - base_z), top_z, bands + 1)
    radii = _side_radii(points, centre, camera_xy, 1.0, edges)
    good = np.isfinite(radii)
    return ((edges[:-1] + edges[1:])[good] / 2, radii[good]) if good.any() else None


def seen_wall(points: np.ndarray, centre: np.ndarray, floor: float, top_z: float, camera_xy: np.ndarray | None,
              bands: int) -> float | None:
    """How much farther from the axis the camera saw the near wall's outside than the far wall's
    inside, at the same heights (median over the bands, between the cavity floor and the rim, where
    both were seen): the wall's thickness, less twice any error of the axis along the line of sight
    (which moves the two sides' radii oppositely). None without a camera or bands seen on both sides."""
    if camera_xy is None or np.linalg.norm(centre - camera_xy) < 1e-6 or top_z <= floor:
        return None
    height = top_z - floor
    edges = np.linspace(floor + 0.15 * height, top_z - 0.15 * height, bands + 1)
    diff = _side_radii(points, centre, camera_xy, 1.0, edges) - _side_radii(points, centre, camera_xy, -1.0, edges)
    diff = diff[np.isfinite(diff)]
    return float(np.median(diff)) if len(diff) >= 2 else None


def _bulge(line: np.ndarray) -> float:
    """Largest distance of the (r, z) polyline's points from the chord joining its ends."""
    chord = line[-1] - line[0]
    length = float(np.hypot(*chord))
    if length < 1e-12:
        return float(np.max(np.linalg.norm(line - line[0], axis=1)))
    rel = line - line[0]
    return float(np.max(np.abs(rel[:, 0] * chord[1] - rel[:, 1] * chord[0])) / length)


def _straight_runs(inner: np.ndarray, outer: np.ndarray, max_bulge: float, least: int) -> list[tuple[int, int]]:
    """Index ranges (i, j) cutting a wall's (r, z) profile (``inner`` and ``outer`` polylines) into
    runs each nearly straight (neither polyline strays from its chord by more than ``max_bulge``: the
    convex hull of a run then fills little beyond the wall), at least ``least`` of them when the
    profile has the points, greedy from the foot."""
    n = len(inner)
    step = max(1, -(-(n - 1) // max(least, 1)))  # ceil: ``least`` runs on a straight profile
    runs, i = [], 0
    while i < n - 1:
        j = min(i + step, n - 1)
        while j > i + 1 and max(_bulge(inner[i:j + 1]), _bulge(outer[i:j + 1])) > max_bulge:
            j -= 1
        runs.append((i, j))
        i = j
    return runs


def _ring(radius: float, z: float, angles: np.ndarray, centre: np.ndarray) -> np.ndarray:
    return np.column_stack([centre[0] + radius * np.cos(angles), centre[1] + radius * np.sin(angles), np.full(len(angles), z)])


def complete_open_container(points: np.ndarray, centre: np.ndarray, radius: float, base_z: float, top_z: float,
                            params: ContainerParams = ContainerParams(), camera_xy: np.ndarray | None = None,
                            seen_inside: np.ndarray | None = None, camera_z: float | None = None) -> OpenContainer | None:
    """The hollow solid of an open round container, or None when its observed top is not hollow.

    The cavity is the surface seen inside the rim (see :func:`_inner_profile`; ``seen_inside``: every
    point the camera saw within the rim, whatever object it was given to: a shallow floor is often
    taken for the support), the wall that surface moved outwards by the thickness scanned at the
    rim, the bottom solid down to the support. ``camera_z``: the camera's height (with ``camera_xy``,
    how deep inside it could see: see :func:`cavity_floor`)."""
    if not params.enabled:
        return None
    height = top_z - base_z
    floor = cavity_floor(points, centre, radius, height, params, camera_xy, camera_z)
    if floor is None:
        return None
    cavity = points if seen_inside is None else np.vstack([points, seen_inside])
    rim = points[points[:, 2] >= top_z - 0.1 * height]
    rr = np.linalg.norm(rim[:, :2] - centre, axis=1) if len(rim) else np.array([radius])
    wall = float(np.clip(np.percentile(rr, 95) - np.percentile(rr, 5), params.min_wall, params.max_wall_share * radius))
    inner = cavity[np.linalg.norm(cavity[:, :2] - centre, axis=1) < 0.7 * radius]
    # the floor where it was seen; unseen (a deep cup seen aslant), the bottom as thick as the wall
    floor = min(floor, float(np.percentile(inner[:, 2], 10))) if len(inner) >= 20 else base_z + wall
    floor = float(np.clip(floor, base_z + params.min_floor, top_z - 0.2 * height))
    shift = 0.0
    sides = seen_wall(cavity, centre, floor, top_z, camera_xy, params.bands)
    if sides is not None:  # the seen sides set the wall (the rim band's spread also holds its slope and the noise)
        wall = float(np.clip(sides, params.min_wall, params.max_wall_share * radius))
        shift = min(0.0, (sides - wall) / 2)  # thinner than the least wall: that wall centred between the two sides
    r_in, z_in = _inner_profile(cavity, centre, radius, floor, top_z, params.bands, camera_xy, shift, wall)
    seen = _seen_outside(points, centre, base_z, top_z, camera_xy, params.bands)

    def outside(r: np.ndarray, z: np.ndarray) -> np.ndarray:  # no thinner than the wall the camera saw outside
        return r if seen is None else np.asarray(np.maximum(r, np.interp(z, *seen, left=0.0, right=0.0)))

    r_out, z_out = _offset(r_in, z_in, wall)
    r_out[-1], z_out[-1] = r_in[-1] + wall, top_z  # the rim: flat, one wall wide
    resting = z_out <= base_z + params.min_floor  # the outside of the bottom, on the support: the foot reaches its edge
    wall_part = ~resting & (r_out > max(float(r_in[1]), float(r_out[resting].max()) if resting.any() else 0.0))
    r_out, z_out = outside(r_out[wall_part], z_out[wall_part]), z_out[wall_part]
    foot = float(outside(np.array([r_out[0] if len(r_out) else radius]), np.array([base_z]))[0])
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
    wall_r, wall_z = r_in[r_in >= floor_r], z_in[r_in >= floor_r]  # from the floor's edge up to the rim
    out_r, out_z = _offset(wall_r, wall_z, wall)
    out_r[-1], out_z[-1] = wall_r[-1] + wall, top_z
    out_z = np.maximum(out_z, base_z)
    out_r = outside(out_r, out_z)
    rim_at_floor = float(np.interp(z_in[0], *zip(*sorted(zip(out_z, out_r)))))  # the outside at the floor's height
    bottom = [_ring(foot, base_z, fine, centre), _ring(max(floor_r, 1e-3), float(z_in[0]), fine, centre),
              _ring(max(rim_at_floor, 1e-3), float(z_in[0]), fine, centre)]
    pieces = [trimesh_hull(np.vstack(bottom))]
    for i, j in _straight_runs(np.column_stack([wall_r, wall_z]), np.column_stack([out_r, out_z]), params.max_bulge, params.segments):
        ring_r, ring_z = np.concatenate([wall_r[i:j + 1], out_r[i:j + 1]]), np.concatenate([wall_z[i:j + 1], out_z[i:j + 1]])
        for a0, a1 in zip(angles[:-1], angles[1:]):
            arc = np.linspace(a0, a1, 3)
            pieces.append(trimesh_hull(np.vstack([_ring(float(x), float(zz), arc, centre) for x, zz in zip(ring_r, ring_z)])))
    outer = trimesh_hull(np.vstack([_ring(foot, base_z, fine, centre)] + [_ring(float(x), float(zz), fine, centre) for x, zz in zip(r_out, z_out)]))
    order = np.argsort(np.concatenate([[base_z], z_out]), kind="stable")
    profile = (np.concatenate([[base_z], z_out])[order], np.concatenate([[foot], r_out])[order])
    return OpenContainer(pieces, visual, outer, wall, float(z_in[0]), profile)
