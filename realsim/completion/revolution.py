"""Round objects: the visible profile revolved about a vertical axis fitted to the footprint's arc.

The axis is the centre of a circle fitted to the visible side; the check that the body is round is
the evidence itself: each height band a circle about that axis, the arc it covers, and (for a
camera view) the silhouette, whose width across the line of sight is the body's diameter (neither
narrower nor wider) and whose middle is the axis (an oval turned aslant is not). A straight side is
the fitted cylinder; otherwise the solid is the revolution of the observed outer radius per height
band (a bottle keeps its neck), built as one convex frustum per band so the collision shape follows
a profile that is not convex.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from realsim.completion.circles import arc_coverage_deg, corner_rms, fit_circle
from realsim.completion.hull import trimesh_hull
from realsim.completion.params import CompletionParams


@dataclass
class Revolved:
    """A solid of revolution (world frame): convex frustum pieces, the revolved visual, its hull."""

    pieces: list[trimesh.Trimesh]
    visual: trimesh.Trimesh
    outer: trimesh.Trimesh
    centre: np.ndarray  # (2,) axis position
    radius: float  # fitted radius of the visible side
    straight: bool = False  # the profile is straight: one cylinder of the fitted radius


def round_axis(points: np.ndarray, base_z: float, top_z: float, params: CompletionParams,
               camera_xy: np.ndarray | None = None) -> tuple[np.ndarray, float] | None:
    """(axis centre, radius) when the visible side is a circular arc whose silhouette is as wide as
    the circle (seen from ``camera_xy``), else None.

    The circle must also win against the alternatives the evidence allows: it fits the side closer
    than a box corner (two perpendicular faces, :func:`corner_rms`) does, and the solid it makes
    holds what was seen: at most ``params.round_max_outside`` of the points (a handle, a spout) lie
    beyond it (a top face reaching back past the circle is a body longer than it is wide). Seen from
    ``camera_xy``, the silhouette is the circle's: as wide (within ``params.silhouette_min_share``)
    and centred on it within the same share of the radius (the line of sight grazes a circle abreast
    of its centre on both sides; an oval turned across the line of sight fits a circle off its middle)."""
    side = points[points[:, 2] < top_z - 0.25 * (top_z - base_z)]
    xy = (side if len(side) >= params.min_points else points)[:, :2]
    centre, radius, rms = fit_circle(xy)
    if radius > params.cylinder_max_radius or _band_rms(points, centre, base_z, top_z, params.revolution_bands) > params.cylinder_max_rms * radius:
        return None
    if arc_coverage_deg(xy, centre) < params.cylinder_min_arc_deg:
        return None
    beyond = np.linalg.norm(points[:, :2] - centre, axis=1) > params.round_outside_margin * radius + params.round_outside_gap
    if np.mean(beyond) > params.round_max_outside or rms >= corner_rms(xy):
        return None
    if camera_xy is not None:
        d = centre - camera_xy
        if np.linalg.norm(d) > 1e-6:
            lateral = np.array([-d[1], d[0]]) / np.linalg.norm(d)
            left, right = np.percentile(points[:, :2] @ lateral - centre @ lateral, [1, 99])
            share = float(right - left) / (2 * radius)
            if not params.silhouette_min_share <= share <= 1 / params.silhouette_min_share:
                return None  # narrower or wider across the line of sight than the circle: not round
            if abs(0.5 * float(left + right)) > (1 - params.silhouette_min_share) * radius:
                return None  # the silhouette is not centred on the circle: the arc is a turned oval's
    return centre, radius


def silhouette_circle(side: np.ndarray, centre: np.ndarray, radius: float, camera_xy: np.ndarray,
                      grazing: float = 0.35) -> tuple[np.ndarray, float] | None:
    """The circle of a straight round side (``side``: its points) from its silhouette: the diameter is
    the side's width across the line of sight (a circle fitted to the near arc alone is as much as 2 mm
    off a 33 mm can, as the noise bends the arc), the axis midway between the two grazing lines and
    one radius behind the arc (the median over the points in the middle 70 % of the width). None when
    the silhouette does not end where the line of sight grazes the circle (the outermost points on a
    side are more than ``grazing`` radii in front of the axis: a neighbour hides that side)."""
    d = centre - camera_xy
    if len(side) < 20 or np.linalg.norm(d) < 1e-6:
        return None
    d = d / np.linalg.norm(d)
    lateral = np.array([-d[1], d[0]])
    w, s = side[:, :2] @ lateral, side[:, :2] @ d
    left, right = float(w.min()), float(w.max())
    r, mid = 0.5 * (right - left), 0.5 * (left + right)
    inner = np.abs(w - mid) < 0.7 * r
    if r <= 0 or inner.sum() < 10:
        return None
    axis_s = float(np.median(s[inner] + np.sqrt(r * r - (w[inner] - mid) ** 2)))
    for sign in (-1.0, 1.0):
        outer = sign * (w - mid) >= 0.98 * r
        if not outer.any() or float(np.median(s[outer])) < axis_s - grazing * r:
            return None
    return axis_s * d + mid * lateral, r


def silhouette_axis(points: np.ndarray, centre: np.ndarray, radius: float, base_z: float, top_z: float,
                    camera_xy: np.ndarray, bands: int, min_bands: int = 3) -> tuple[np.ndarray, float] | None:
    """The axis of a round body whose profile is not straight (a strawberry, a bottle's shoulder), from
    its silhouette band by band: each height band of the side (below the top quarter, which holds a cap)
    its :func:`silhouette_circle`, the axis the median of their centres and the radius the largest of
    theirs. A circle fitted to the near arc alone is pulled toward the camera and shrunk (a lumpy side
    seen over less than half a turn: a 22 mm strawberry fitted 5 mm short, its far side 6-13 mm
    short). None when fewer than ``min_bands`` bands show both grazing lines (``centre``, ``radius``:
    the fitted circle, for the line of sight)."""
    side = points[:, 2] < top_z - 0.25 * (top_z - base_z)
    edges = np.linspace(base_z, top_z, bands + 1)
    circles = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        band = points[side & (points[:, 2] >= lo) & (points[:, 2] < hi)]
        seen = silhouette_circle(band, centre, radius, camera_xy) if len(band) else None
        if seen is not None:
            circles.append(seen)
    if len(circles) < min_bands:
        return None
    return np.median([c for c, _ in circles], axis=0), float(max(r for _, r in circles))


def _band_rms(points: np.ndarray, centre: np.ndarray, base_z: float, top_z: float, bands: int) -> float:
    """RMS distance of the points from the circle about ``centre`` through their own height band (a
    solid of revolution: each band a circle about the common axis, whatever the profile)."""
    r = np.linalg.norm(points[:, :2] - centre, axis=1)
    band = np.clip(((points[:, 2] - base_z) / max(top_z - base_z, 1e-6) * bands).astype(np.int64), 0, bands - 1)
    side = points[:, 2] < top_z - 0.25 * (top_z - base_z)  # the top holds a cap or a lid (points inside the circle)
    if side.sum() < 10:
        return float("inf")
    medians = np.array([np.median(r[side & (band == b)]) if np.any(side & (band == b)) else 0.0 for b in range(bands)])
    return float(np.sqrt(np.mean((r[side] - medians[band[side]]) ** 2)))


def revolved_profile(points: np.ndarray, centre: np.ndarray, radius: float, base_z: float, top_z: float,
                     bands: int, percentile: float = 75.0, turn_in: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Outer radius (z, r) at the band boundaries: a high ``percentile`` of the points' distances from
    the axis per height band (a handle or spout, a minority of a band's points, is left out), bands without evidence interpolated, at most the fitted radius + 10 %.
    With ``turn_in``: when the lowest band seen is narrower than the widest by more than that share (the
    side was seen turning in below its widest: a round underside the camera above loses sight of), the
    unseen profile below it is no wider than its mirror image about the widest band's middle (the
    underside mirrors the upper side, as a lying body's does: :mod:`realsim.completion.underside`)."""
    r = np.linalg.norm(points[:, :2] - centre, axis=1)
    edges = np.linspace(base_z, top_z, bands + 1)
    mids = (edges[:-1] + edges[1:]) / 2
    radii = np.full(bands, np.nan)
    for i in range(bands):
        near = (points[:, 2] >= edges[i]) & (points[:, 2] < edges[i + 1] + 1e-9)
        if near.sum() >= 10:
            radii[i] = float(np.percentile(r[near], percentile))
    good = np.isfinite(radii)
    if not good.any():
        return edges, np.full(bands + 1, radius)
    radii = np.clip(np.interp(mids, mids[good], radii[good]), 0.15 * radius, 1.1 * radius)
    at_edges = np.interp(edges, mids, radii)  # ends take their band's radius
    seen = np.flatnonzero(good)
    widest = int(seen[np.argmax(radii[seen])])
    if turn_in is not None and seen[0] < widest and radii[seen[0]] < (1.0 - turn_in) * radii[widest]:
        below = edges < mids[seen[0]]  # the unseen underside
        mirrored = np.interp(np.minimum(2.0 * mids[widest] - edges[below], top_z), edges, at_edges)
        at_edges[below] = np.minimum(at_edges[below], mirrored)
    return edges, at_edges


def _ring(radius: float, z: float, centre: np.ndarray, sections: int) -> np.ndarray:
    a = np.linspace(0.0, 2 * np.pi, sections, endpoint=False)
    return np.column_stack([centre[0] + radius * np.cos(a), centre[1] + radius * np.sin(a), np.full(sections, z)])


def complete_revolved(points: np.ndarray, base_z: float, top_z: float, params: CompletionParams,
                      camera_xy: np.ndarray | None = None) -> Revolved | None:
    """The visible profile revolved about the fitted vertical axis, or None when the body is not round."""
    axis = round_axis(points, base_z, top_z, params, camera_xy)
    if axis is None:
        return None
    centre, radius = axis
    turn_in = params.straight_profile_share if params.revolution_underside else None
    z, r = revolved_profile(points, centre, radius, base_z, top_z, params.revolution_bands, params.revolution_percentile, turn_in)
    n = params.cylinder_sections
    if float(np.ptp(r[1:-1])) <= params.straight_profile_share * radius:  # a straight side: the fitted cylinder
        if camera_xy is not None and (seen := silhouette_circle(points[points[:, 2] < top_z - 0.25 * (top_z - base_z)], centre, radius, camera_xy)):
            centre, radius = seen
        height = top_z - base_z
        cylinder = trimesh.creation.cylinder(radius=radius, height=height, sections=n)
        cylinder.apply_translation([centre[0], centre[1], base_z + height / 2])
        return Revolved([cylinder], cylinder, cylinder, centre, radius, straight=True)
    if params.revolution_silhouette and camera_xy is not None and (seen := silhouette_axis(points, centre, radius, base_z, top_z, camera_xy, params.revolution_bands)):
        centre, radius = seen
        z, r = revolved_profile(points, centre, radius, base_z, top_z, params.revolution_bands, params.revolution_percentile, turn_in)
    pieces = [trimesh_hull(np.vstack([_ring(float(r[i]), float(z[i]), centre, n), _ring(float(r[i + 1]), float(z[i + 1]), centre, n)]))
              for i in range(len(z) - 1)]
    line = np.vstack([[0.0, base_z], np.column_stack([r, z]), [0.0, top_z]])
    visual = trimesh.creation.revolve(line, sections=n)
    visual.apply_translation([centre[0], centre[1], 0.0])
    if visual.volume < 0:
        visual.invert()
    outer = trimesh_hull(np.vstack([p.vertices for p in pieces]))
    return Revolved(pieces, visual, outer, centre, radius)


def complete_cylinder(points: np.ndarray, base_z: float, top_z: float, params: CompletionParams) -> tuple[trimesh.Trimesh, np.ndarray] | None:
    """An upright cylinder (world frame) when the footprint is a circular arc, else None."""
    axis = round_axis(points, base_z, top_z, params)
    if axis is None:
        return None
    centre, radius = axis
    height = top_z - base_z
    mesh = trimesh.creation.cylinder(radius=radius, height=height, sections=params.cylinder_sections)
    mesh.apply_translation([centre[0], centre[1], base_z + height / 2])
    return mesh, np.array([centre[0], centre[1], base_z])
