"""Completed neighbours that still overlap are parted by the plane that costs the least.

:func:`realsim.completion.neighbours.separate_neighbours` parts neighbours standing side by side.
An object leaning on another (a book with one edge on the table and the other on a second book,
a box tipped against a box) has its hidden underside extruded down to the table, through the
object it lies on; the simulation then pushes the two apart by centimetres. Its true underside is
a plane touching the other object: among planes touching one of the two shapes, the one that keeps
what the camera saw of the other and removes the least of it parts them.
"""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from realsim.completion.clipvolume import clipped_volumes
from realsim.completion.hull import trimesh_hull, volume, within_convex
from realsim.completion.neighbours import MIN_PART_VOLUME, clip_convex, kept_points, unique_edges
from realsim.completion.params import CompletionParams
from realsim.completion.stacking import set_shape
from realsim.scene import SceneObject

DIRECTIONS = 192  # candidate plane normals spread over the sphere (plus the other shape's face normals)
KEEP_SEEN = 0.995  # a cut must keep this share of the cut object's observed points
SEEN_TOLERANCE = 0.003  # m an observed point may lie beyond the cut and still count as kept
ROUGH_MARGIN = 1e-7  # share of a piece's volume a closed-form or Qhull-only estimate of a cut's loss is trusted to


def _sphere(count: int) -> np.ndarray:
    """``count`` unit vectors spread evenly over the sphere (a Fibonacci lattice)."""
    i = np.arange(count) + 0.5
    z = 1.0 - 2.0 * i / count
    r = np.sqrt(1.0 - z * z)
    phi = np.pi * (3.0 - np.sqrt(5.0)) * i
    return np.column_stack([r * np.cos(phi), r * np.sin(phi), z])


def _apart(a: trimesh.Trimesh, b: trimesh.Trimesh) -> bool:
    """True when a face plane of either convex shape separates them (or their bounds do not meet)."""
    if np.any(a.bounds[0] > b.bounds[1]) or np.any(b.bounds[0] > a.bounds[1]):
        return True
    for one, two in ((a, b), (b, a)):
        normals = one.face_normals
        if np.any((two.vertices @ normals.T).min(axis=0) >= (one.vertices @ normals.T).max(axis=0) - 1e-5):
            return True
    return False


def _rough_volume(points: np.ndarray) -> float:
    """The volume of the hull of ``points`` from Qhull alone (infinite when it cannot tell, 0 for too
    few): within ``ROUGH_MARGIN`` of the exact hull's, at a fraction of the cost."""
    if len(points) < 4:
        return 0.0
    try:
        return float(ConvexHull(points).volume)
    except QhullError:
        return float("inf")


def _removed_estimates(moved: trimesh.Trimesh, normals: np.ndarray, offsets: np.ndarray,
                       whole: float) -> tuple[np.ndarray, float] | None:
    """Per cut, the volume it removes from ``moved`` (of volume ``whole``) from closed forms, and how far
    the exact hull's may differ; None when ``moved`` is not a closed convex mesh."""
    clipped = clipped_volumes(moved, normals, offsets) if len(normals) else None
    if clipped is None:
        return None
    kept, excess = clipped
    return whole - kept, ROUGH_MARGIN * whole + excess


def _best_part(moved: trimesh.Trimesh, fixed: trimesh.Trimesh, seen: np.ndarray) -> tuple[float, np.ndarray, float] | None:
    """(volume removed, normal, offset) of the cheapest cut keeping ``moved`` where ``n . x >= offset``
    with the plane touching ``fixed`` from outside, keeping ``KEEP_SEEN`` of ``seen``; None if none does.
    Of cuts removing the same volume, the shallowest wins. Exact hulls are made only for cuts whose
    estimated loss is within the estimate's margin of the best so far, and of the cut estimated cheapest
    (a bound the winner cannot exceed)."""
    normals = np.vstack([_sphere(DIRECTIONS), -fixed.face_normals[:: max(1, len(fixed.faces) // 64)]])
    offsets = (fixed.vertices @ normals.T).max(axis=0)
    low = (moved.vertices @ normals.T).min(axis=0)
    kept = np.mean(seen @ normals.T >= offsets - SEEN_TOLERANCE, axis=0) >= KEEP_SEEN if len(seen) else np.ones(len(normals), bool)
    order = [int(j) for j in np.argsort(offsets - low) if kept[j]]  # shallow cuts first
    whole = volume(moved)
    v, edges = np.asarray(moved.vertices), unique_edges(moved.faces)
    estimates = _removed_estimates(moved, normals[order], offsets[order], whole)
    parts: dict[int, trimesh.Trimesh | None] = {}

    def part(i: int) -> trimesh.Trimesh | None:
        if estimates is not None and whole - estimates[0][i] + estimates[1] < MIN_PART_VOLUME:
            return None  # what clip_convex gives a part this small
        j = order[i]
        key = -1 if np.all(v @ normals[j] - offsets[j] >= 0) else i  # a plane missing the body keeps all its corners
        if key not in parts:
            parts[key] = clip_convex(moved, normals[j], float(offsets[j]))
        return parts[key]

    def estimate(i: int) -> tuple[float, float]:
        if estimates is not None:
            return float(estimates[0][i]), estimates[1]
        return whole - _rough_volume(kept_points(v, edges, normals[order[i]], float(offsets[order[i]]))), ROUGH_MARGIN * whole

    bound = float("inf")  # the exact loss of one valid cut: the winner loses at most this
    if estimates is not None:
        for i in np.argsort(estimates[0], kind="stable"):
            if (cut := part(int(i))) is not None:
                bound = whole - volume(cut)
                break
    best: tuple[float, np.ndarray, float] | None = None
    for i, j in enumerate(order):
        limit = min(bound, best[0]) if best is not None else bound
        if limit < float("inf"):
            loss, margin = estimate(i)
            if loss > limit + margin:
                continue  # surely loses more than a cut already found: not worth the exact hull
        cut = part(i)
        if cut is None:
            continue
        removed = whole - volume(cut)
        if best is None or removed < best[0]:
            best = (removed, normals[j], float(offsets[j]))
    return best


Part = tuple[float, np.ndarray | None, float]  # volume removed, the kept side's normal and offset (None: the piece dropped)


def _piece_part(piece: trimesh.Trimesh, other: trimesh.Trimesh, seen: np.ndarray) -> Part | None:
    """How ``piece`` gives way to the convex ``other``: the cheapest cut of :func:`_best_part` keeping
    what the camera saw in it, or, when it holds nothing seen and no cut leaves any of it, dropped."""
    found = _best_part(piece, other, seen)
    if found is not None:
        return found[0], found[1], found[2]
    return (volume(piece), None, 0.0) if not len(seen) else None


def _visual(obj: SceneObject, base: np.ndarray) -> trimesh.Trimesh | None:
    """The object's painted surface (world frame) kept through a parting, or None when it is its
    single hull (remade from the cut hull); a painted surface is visual only and stays as it was."""
    if obj.visual is None or (len(obj.collision) == 1 and obj.visual is obj.collision[0]):
        return None
    visual = obj.visual.copy()
    visual.apply_translation(base)
    return visual


def _part_pair(a: SceneObject, b: SceneObject, done: dict[int, trimesh.Trimesh], observed: dict[int, np.ndarray],
               params: CompletionParams, pieces: dict[int, list[trimesh.Trimesh]]) -> None:
    """Part every overlapping pair of convex pieces of ``a`` and ``b``: each time the one piece cut (or
    dropped, when it holds nothing the camera saw and lies wholly in the other) that loses the least."""
    seen = {o.id: [observed[o.id][within_convex(p, observed[o.id], SEEN_TOLERANCE)] for p in pieces.get(o.id, [done[o.id]])] for o in (a, b)}
    own: dict[int, list[trimesh.Trimesh | None]] = {o.id: list(pieces.get(o.id, [done[o.id]])) for o in (a, b)}
    for i in range(len(own[a.id])):
        for j in range(len(own[b.id])):
            p, q = own[a.id][i], own[b.id][j]
            if p is None or q is None or _apart(p, q):
                continue
            options = [(found, key, k) for (key, k, piece, fixed) in ((a.id, i, p, q), (b.id, j, q, p))
                       if (found := _piece_part(piece, fixed, seen[key][k])) is not None]
            if not options:
                continue
            (_, normal, offset), key, k = min(options, key=lambda o: o[0][0])
            piece = own[key][k]
            own[key][k] = None if normal is None or piece is None else clip_convex(piece, normal, offset)
    for obj in (a, b):
        parts = [p for p in own[obj.id] if p is not None]
        before = pieces.get(obj.id, [done[obj.id]])
        if not parts or (len(parts) == len(before) and all(p is q for p, q in zip(parts, before))):
            continue
        visual = _visual(obj, obj.position - np.array([0.0, 0.0, params.base_clearance]))
        whole = parts[0] if len(parts) == 1 else trimesh_hull(np.vstack([p.vertices for p in parts]))
        done[obj.id] = whole
        lo, hi = whole.bounds
        base = np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]])
        if obj.id in pieces:
            pieces[obj.id] = parts
            set_shape(obj, whole, base, params, parts, visual)
        else:
            set_shape(obj, whole, base, params)
        obj.notes.append(f"parted from object {(b if obj is a else a).id} by the plane touching it that keeps what the camera saw")


def part_overlapping(objects: list[SceneObject], done: dict[int, trimesh.Trimesh], observed: dict[int, np.ndarray],
                     params: CompletionParams, pieces: dict[int, list[trimesh.Trimesh]]) -> None:
    """Part every two completed shapes that still overlap (objects stacked on one another are left to
    :func:`realsim.completion.stacking.flatten_top`), piece by convex piece: of each two overlapping
    pieces, the one cut that loses the least volume while keeping what the camera saw of it (a body
    that is not convex gives way where it does, not across its hull)."""
    for i, a in enumerate(objects):
        for b in objects[i + 1:]:
            if a.resting_on == b.id or b.resting_on == a.id or _apart(done[a.id], done[b.id]):
                continue
            _part_pair(a, b, done, observed, params, pieces)
