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

from realsim.completion.hull import volume
from realsim.completion.neighbours import clip_convex
from realsim.completion.params import CompletionParams
from realsim.completion.stacking import set_shape
from realsim.scene import SceneObject

DIRECTIONS = 192  # candidate plane normals spread over the sphere (plus the other shape's face normals)
KEEP_SEEN = 0.995  # a cut must keep this share of the cut object's observed points
SEEN_TOLERANCE = 0.003  # m an observed point may lie beyond the cut and still count as kept


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


def _best_part(moved: trimesh.Trimesh, fixed: trimesh.Trimesh, seen: np.ndarray) -> tuple[float, np.ndarray, float] | None:
    """(volume removed, normal, offset) of the cheapest cut keeping ``moved`` where ``n . x >= offset``
    with the plane touching ``fixed`` from outside, keeping ``KEEP_SEEN`` of ``seen``; None if none does."""
    normals = np.vstack([_sphere(DIRECTIONS), -fixed.face_normals[:: max(1, len(fixed.faces) // 64)]])
    offsets = (fixed.vertices @ normals.T).max(axis=0)
    low = (moved.vertices @ normals.T).min(axis=0)
    kept = np.mean(seen @ normals.T >= offsets - SEEN_TOLERANCE, axis=0) >= KEEP_SEEN
    best: tuple[float, np.ndarray, float] | None = None
    whole = volume(moved)
    for j in np.argsort(offsets - low):  # shallow cuts first
        if not kept[j]:
            continue
        part = clip_convex(moved, normals[j], float(offsets[j]))
        if part is None:
            continue
        removed = whole - volume(part)
        if best is None or removed < best[0]:
            best = (removed, normals[j], float(offsets[j]))
    return best


def part_overlapping(objects: list[SceneObject], done: dict[int, trimesh.Trimesh], observed: dict[int, np.ndarray],
                     params: CompletionParams, pieces: dict[int, list[trimesh.Trimesh]]) -> None:
    """Cut one of every two completed shapes that still overlap (objects stacked on one another
    are left to :func:`realsim.completion.stacking.flatten_top`): the cut that removes the least
    volume while keeping what the camera saw of the object cut."""
    for i, a in enumerate(objects):
        for b in objects[i + 1:]:
            if a.resting_on == b.id or b.resting_on == a.id or _apart(done[a.id], done[b.id]):
                continue
            options = [(found, obj, other) for obj, other in ((a, b), (b, a))
                       if (found := _best_part(done[obj.id], done[other.id], observed[obj.id])) is not None]
            if not options:
                continue
            (_, normal, offset), obj, other = min(options, key=lambda o: o[0][0])
            cut = clip_convex(done[obj.id], normal, offset)
            if cut is None:
                continue
            done[obj.id] = cut
            lo, hi = cut.bounds
            base = np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]])
            parts = None
            if obj.id in pieces:
                parts = [p for p in (clip_convex(q, normal, offset) for q in pieces[obj.id]) if p is not None]
                pieces[obj.id] = parts
            set_shape(obj, cut, base, params, parts or None)
            obj.notes.append(f"parted from object {other.id} by the plane touching it that keeps what the camera saw")
