"""Cut volumes from closed forms (completion/clipvolume.py) and the cheapest parting cut made with them."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from scipy.spatial import ConvexHull

from realsim.completion import overlaps
from realsim.completion.clipvolume import clipped_volumes
from realsim.completion.hull import trimesh_hull, volume
from realsim.completion.neighbours import clip_convex, kept_points, unique_edges


def _hulls(seed: int, count: int) -> list[trimesh.Trimesh]:
    rng = np.random.default_rng(seed)
    return [trimesh_hull(rng.normal(size=(int(rng.integers(6, 300)), 3)) * rng.uniform(0.01, 0.2, 3) + rng.normal(size=3))
            for _ in range(count)]


def _planes(mesh: trimesh.Trimesh, rng: np.random.Generator, count: int) -> tuple[np.ndarray, np.ndarray]:
    normals = rng.normal(size=(count, 3))
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    lo, hi = (mesh.vertices @ normals.T).min(axis=0), (mesh.vertices @ normals.T).max(axis=0)
    return normals, lo + rng.uniform(-0.2, 1.2, count) * (hi - lo)  # some planes miss the body on either side


def test_clipped_volumes_are_the_hull_volumes_of_the_kept_corners() -> None:
    rng = np.random.default_rng(1)
    for mesh in _hulls(2, 25) + [trimesh.creation.box([0.1, 0.2, 0.3]), trimesh.creation.icosphere(2)]:
        normals, offsets = _planes(mesh, rng, 60)
        found = clipped_volumes(mesh, normals, offsets)
        assert found is not None
        mine, excess = found
        v, edges = np.asarray(mesh.vertices), unique_edges(mesh.faces)
        for j in range(len(normals)):
            corners = kept_points(v, edges, normals[j], float(offsets[j]))
            try:
                hull = ConvexHull(corners).volume if len(corners) >= 4 else 0.0
            except Exception:
                hull = 0.0  # flat: nothing kept
            assert mine[j] == pytest.approx(hull, abs=1e-12 * volume(mesh) + excess + 1e-18)


def test_open_or_inside_out_meshes_get_no_closed_form() -> None:
    box = trimesh.creation.box([0.1, 0.1, 0.1])
    normals, offsets = np.array([[0.0, 0.0, 1.0]]), np.array([0.0])
    assert clipped_volumes(trimesh.Trimesh(box.vertices, box.faces[:-1], process=False), normals, offsets) is None
    assert clipped_volumes(trimesh.Trimesh(box.vertices, box.faces[:, ::-1], process=False), normals, offsets) is None
    whole = clipped_volumes(box, normals, offsets)
    assert whole is not None and whole[0][0] == pytest.approx(0.0005)


def _every_cut(moved: trimesh.Trimesh, fixed: trimesh.Trimesh, seen: np.ndarray) -> tuple[float, np.ndarray, float] | None:
    """The reference: every allowed cut's exact hull, shallowest first, the first of least loss."""
    normals = np.vstack([overlaps._sphere(overlaps.DIRECTIONS), -fixed.face_normals[:: max(1, len(fixed.faces) // 64)]])
    offsets = (fixed.vertices @ normals.T).max(axis=0)
    low = (moved.vertices @ normals.T).min(axis=0)
    kept = np.mean(seen @ normals.T >= offsets - overlaps.SEEN_TOLERANCE, axis=0) >= overlaps.KEEP_SEEN if len(seen) else np.ones(len(normals), bool)
    best = None
    for j in np.argsort(offsets - low):
        part = clip_convex(moved, normals[j], float(offsets[j])) if kept[j] else None
        if part is not None and (best is None or volume(moved) - volume(part) < best[0]):
            best = (volume(moved) - volume(part), normals[j], float(offsets[j]))
    return best


def test_best_part_is_the_least_loss_of_every_cut_with_few_exact_hulls(monkeypatch: pytest.MonkeyPatch) -> None:
    calls = [0]
    clip = overlaps.clip_convex

    def counted(*args: object) -> trimesh.Trimesh | None:
        calls[0] += 1
        return clip(*args)  # type: ignore[arg-type]

    hulls, rng = _hulls(5, 24), np.random.default_rng(6)
    pairs = 0
    for k, (moved, fixed) in enumerate(zip(hulls[::2], hulls[1::2])):
        fixed = fixed.copy()
        shift = rng.normal(size=3)
        shift *= (0.3 if k % 2 else 0.7) * np.linalg.norm(moved.extents) / np.linalg.norm(shift)
        fixed.apply_translation(moved.centroid - fixed.centroid + shift)  # overlapping it in part
        seen = moved.vertices[rng.random(len(moved.vertices)) < 0.3]
        want = _every_cut(moved, fixed, seen)
        monkeypatch.setattr(overlaps, "clip_convex", counted)
        calls[0] = 0
        got = overlaps._best_part(moved, fixed, seen)
        monkeypatch.setattr(overlaps, "clip_convex", clip)
        assert (got is None) == (want is None)
        if got is not None and want is not None:
            pairs += 1
            assert got[0] == want[0] and np.array_equal(got[1], want[1]) and got[2] == want[2]
            assert calls[0] <= 12  # the closed forms leave only the cuts near the best to exact hulls
    assert pairs >= 5
