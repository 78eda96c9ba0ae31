"""A capture's own scale and frame: point spacing, working resolution, plausible units, up axis.

Every length the detection uses is in metres and derived from the capture itself, so the same
scene sampled at 50k or 10 M points, or written in m, cm or mm, gives the same result.
"""

from __future__ import annotations

import math

import numpy as np

from realsim.errors import InputError
from realsim.perception.unique_keys import distinct_rows

UNIT_SCALE = {"m": 1.0, "cm": 0.01, "mm": 0.001}
MIN_RESOLUTION = 0.003  # m: fine enough for 3 cm objects (10 cells across)
CELL_SPACINGS = 1.15  # a working cell is this many measured spacings: the grid count reads a uniformly
# sampled surface's 1/sqrt(density) about 15 % short (a cell cut by a tilted or curved surface holds more
# of it), and detection's lengths were tuned on a measure that read long
PLAUSIBLE_EXTENT = (0.1, 60.0)  # m: a captured scene is this large
TYPICAL_EXTENT = 2.0  # m: the scene size preferred when several units are plausible
SUPPORT_GAP = (0.4, 1.2)  # m: a table or counter top stands this high above the floor
TABLE_BONUS = 1.5  # log-extent units a table-high layer is worth (extents 4.5x apart still tie)
_SAMPLE = 200_000


def _subsample(points: np.ndarray, count: int, seed: int = 0) -> np.ndarray:
    pts = points[np.isfinite(points).all(axis=1)]
    if len(pts) > count:
        pts = pts[np.random.default_rng(seed).choice(len(pts), count, replace=False)]
    return pts


FAR_ORIGIN = 100.0  # a capture this many of its own extents from its origin is moved near it


def distant_origin(points: np.ndarray) -> np.ndarray | None:
    """The rounded median point of a capture far from its coordinate origin (an ARKit session
    that walked, a georeferenced scan km away), else None. Moving such a capture to near zero
    before any float32 step keeps its millimetres: float32 spacing at 500 km is 6 cm."""
    pts = _subsample(points, 50_000)
    if len(pts) == 0:
        return None
    centre = np.median(pts, axis=0)
    extent = float(np.max(np.percentile(pts, 99, axis=0) - np.percentile(pts, 1, axis=0)))
    if np.linalg.norm(centre) <= FAR_ORIGIN * max(extent, 1e-9):
        return None
    return np.round(centre)


def point_spacing(points: np.ndarray, seed: int = 0) -> float:
    """Typical distance between neighbouring surface points (same units as ``points``).

    Counted on a grid, in O(N): on a surface a cell of side ``v`` holds about ``(v / s)^2``
    points of spacing ``s``. Measured on a random subset and scaled back to the full count. The
    grid is anchored at the points' lower corner, so the measure moves and scales with the points
    (a floor lying on a grid plane of the input's axes would fill two layers of cells).
    """
    finite = int(np.isfinite(points).all(axis=1).sum())
    pts = _subsample(points, _SAMPLE, seed)
    if len(pts) < 10:
        return float("nan")
    extent = float(np.max(np.percentile(pts, 99, axis=0) - np.percentile(pts, 1, axis=0)))
    cell = max(extent / 100.0, 1e-12)
    per_cell = len(pts) / distinct_rows(np.floor((pts - pts.min(axis=0)) / cell).astype(np.int64))  # mean points per occupied cell
    spacing = cell / math.sqrt(max(per_cell, 1.0))
    return spacing * math.sqrt(len(pts) / max(finite, 1))


def working_resolution(spacing_m: float) -> float:
    """Resolution (m) detection works at: ``CELL_SPACINGS`` of the capture's own spacing, never finer than 3 mm."""
    if not np.isfinite(spacing_m):
        return MIN_RESOLUTION
    return max(CELL_SPACINGS * float(spacing_m), MIN_RESOLUTION)


def _layer_gaps(points: np.ndarray, up: np.ndarray) -> np.ndarray:
    """Heights (input units) of the large horizontal layers along ``up`` above the lowest one."""
    h = points @ up
    lo, hi = np.percentile(h, [0.5, 99.5])
    if hi <= lo:
        return np.zeros(0)
    counts, edges = np.histogram(h, bins=400, range=(lo, hi))
    idx = np.flatnonzero(counts > max(0.015 * len(h), 5 * np.median(counts)))
    if len(idx) < 2:
        return np.zeros(0)
    return edges[idx[1:]] - edges[idx[0]]


def plausible_units(points: np.ndarray, up: np.ndarray | None = None) -> tuple[str, str]:
    """Units the capture is in (m, cm or mm) by physical plausibility, and why.

    A unit is plausible when the scene's extent in it is 0.1-60 m; among plausible ones the
    extent nearest a room-sized 2 m (in log scale) wins, and a large horizontal layer 0.4-1.2 m
    above the lowest (a table over a floor) decides between extents of similar plausibility. None plausible: an
    InputError naming ``--units``.
    """
    pts = _subsample(points, _SAMPLE)
    if len(pts) == 0:
        raise InputError("the capture has no finite points")
    extent = float(np.max(np.percentile(pts, 99, axis=0) - np.percentile(pts, 1, axis=0)))
    gaps = _layer_gaps(pts, up) if up is not None else np.zeros(0)
    plausible = {u: extent * s for u, s in UNIT_SCALE.items() if PLAUSIBLE_EXTENT[0] <= extent * s <= PLAUSIBLE_EXTENT[1]}
    if not plausible:
        raise InputError(
            f"the capture is {extent:.3g} units across, which is {extent:.3g} m, {extent / 100:.3g} m or {extent / 1000:.3g} m "
            f"in m, cm or mm: no plausible scene size ({PLAUSIBLE_EXTENT[0]}-{PLAUSIBLE_EXTENT[1]:.0f} m); "
            "rescale the capture or pass --units m|cm|mm")

    def table(u: str) -> float | None:
        fit = [g * UNIT_SCALE[u] for g in gaps if SUPPORT_GAP[0] <= g * UNIT_SCALE[u] <= SUPPORT_GAP[1]]
        return max(fit) if fit else None

    def score(u: str) -> float:  # a room-sized extent first; a table-high layer breaks near ties
        return -abs(math.log(plausible[u] / TYPICAL_EXTENT)) + (TABLE_BONUS if table(u) is not None else 0.0)

    best = max(plausible, key=score)
    why = f"{extent * UNIT_SCALE[best]:.2f} m across"
    if table(best) is not None:
        why += f", a support {table(best):.2f} m above the floor"
    others = [f"{u}: {plausible[u]:.3g} m across" for u in plausible if u != best]
    if others:
        why += " (also plausible " + ", ".join(others) + "; pass --units to choose)"
    return best, why


def check_scale(points_m: np.ndarray, given: str) -> None:
    """Refuse a scene too large to be real in the units the user gave (fast: percentiles of a subset)."""
    pts = _subsample(points_m, 50_000)
    if len(pts) == 0:
        return
    extent = float(np.max(np.percentile(pts, 99, axis=0) - np.percentile(pts, 1, axis=0)))
    if extent > PLAUSIBLE_EXTENT[1] * 10:  # tiny scenes are allowed when asked for; huge ones would run for minutes
        raise InputError(f"in {given} the capture is {extent:.3g} m across, which is not a plausible scene; "
                         "check --units (m, cm or mm) or rescale the capture")


def detect_up(points: np.ndarray, camera_view: bool, fmt_hint: str, seed: int) -> str:
    """Guess the input's up axis.

    Camera views (organized clouds) use the optical frame, +y down; glTF is Y-up; otherwise the
    axis nearest the normal of the plane bodies rest on (:func:`realsim.perception.up_axis.resting_up`:
    a counter under a wall larger than it, with no floor in view, however the file is turned; the
    planes stage then levels on that plane itself), and without such evidence the axis closest to
    the dominant plane's normal, signed so that most of what stands clear of that plane (farther
    than three RANSAC thresholds) lies above it: a scanned slab's underside is as large as its
    top, so the median point alone cannot tell them apart.
    """
    if fmt_hint in ("glb", "gltf"):
        return "+y"
    if camera_view:
        return "-y"
    from realsim.geometry import ransac_plane
    from realsim.perception.up_axis import axis_name, evidence_points, resting_up

    rng = np.random.default_rng(seed)
    pts, threshold = evidence_points(points, rng)
    resting = resting_up(pts, threshold, np.random.default_rng(seed))
    if resting is not None:
        return resting
    normal, offset, _ = ransac_plane(pts, threshold, 500, rng)  # the project's one (seeded) RANSAC
    height = pts @ normal + offset
    clear = height[np.abs(height) > 3 * threshold]
    below = (clear < 0).sum() > (clear > 0).sum() if len(clear) >= max(50, 0.001 * len(height)) else np.median(height) < 0
    return axis_name(-normal if below else normal)
