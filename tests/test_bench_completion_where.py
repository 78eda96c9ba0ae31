"""bench/bench_completion.py's ``where_off``: a completed solid's misses and excesses against the truth,
placed by the pixel they project to (silhouette edge, hidden behind the seen surface, behind another
object, seen through, elsewhere). Ground truth: a 10 cm box 1 m in front of a pinhole camera looking
along +z (2 mm pixels there), a wall behind it and a nearer object hiding its right part."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import open3d as o3d
import trimesh

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "bench"))
from bench_completion import WHERE, silhouette_off, where_off  # noqa: E402

K = np.array([[500.0, 0.0, 64.0], [0.0, 500.0, 64.0], [0.0, 0.0, 1.0]])
TRUTH = trimesh.creation.box(bounds=[[-0.05, -0.05, 0.95], [0.05, 0.05, 1.05]])


def _capture() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Depth (128, 128) of the box before a wall at 2 m, the box's seen mask and the occluder's pixels
    (columns 85-127, depth 0.5 m: it hides the box's right edge)."""
    scene = o3d.t.geometry.RaycastingScene()
    scene.add_triangles(o3d.core.Tensor(TRUTH.vertices.astype(np.float32)), o3d.core.Tensor(TRUTH.faces.astype(np.uint32)))
    v, u = np.mgrid[0:128, 0:128]
    ray = np.stack([(u - K[0, 2]) / K[0, 0], (v - K[1, 2]) / K[1, 1], np.ones(u.shape)], axis=-1)
    rays = np.concatenate([np.zeros_like(ray), ray], axis=-1).reshape(-1, 6).astype(np.float32)
    t = scene.cast_rays(o3d.core.Tensor(rays))["t_hit"].numpy().reshape(128, 128)
    others = u >= 85
    depth = np.where(others, 0.5, np.where(np.isfinite(t), t, 2.0))
    return depth, np.isfinite(t) & ~others, others


def _where(completed: trimesh.Trimesh) -> dict[str, tuple[float, float]]:
    depth, mine, others = _capture()
    return where_off([completed], TRUTH, mine, others, depth, np.eye(4), K)


def test_the_truth_itself_misses_and_exceeds_nothing() -> None:
    assert all(m < 0.005 and e < 0.005 for m, e in _where(TRUTH.copy()).values())


def test_a_back_completed_too_deep_is_hidden_excess() -> None:
    where = _where(trimesh.creation.box(bounds=[[-0.05, -0.05, 0.95], [0.05, 0.05, 1.07]]))
    assert 0.12 < where["hidden"][1] < 0.2  # 20 % more, most of it behind the seen front (the rest at its edges)
    assert where["free"][1] < 0.005 and sum(m for m, _ in where.values()) < 0.005


def test_a_front_in_seen_space_is_free_excess() -> None:
    where = _where(trimesh.creation.box(bounds=[[-0.05, -0.05, 0.92], [0.05, 0.05, 1.05]]))
    assert 0.17 < where["free"][1] < 0.23  # 3 cm in front, the first 2 beyond the 1 cm tolerance


def test_a_shrunk_side_misses_behind_the_seen_front_and_the_occluder() -> None:
    where = _where(trimesh.creation.box(bounds=[[-0.046, -0.05, 0.95], [0.046, 0.05, 1.05]]))
    assert 0.035 < where["edge"][0] + where["hidden"][0] < 0.045  # the left 4 mm strip: at the silhouette only at the front
    assert 0.035 < where["occluded"][0] < 0.045  # the right one is behind the nearer object
    assert set(where) == set(WHERE)


def test_a_silhouette_short_by_two_pixels_a_side() -> None:
    depth, mine, others = _capture()
    solid = trimesh.creation.box(bounds=[[-0.046, -0.046, 0.95], [0.046, 0.046, 1.05]])  # 4 mm = 2.1 pixels short at 0.95 m
    short, over = silhouette_off([solid], mine, others, depth, np.eye(4), K)
    assert 1.6 < short < 2.4 and over == 0.0
    assert silhouette_off([TRUTH.copy()], mine, others, depth, np.eye(4), K) == (0.0, 0.0)
    wide = trimesh.creation.box(bounds=[[-0.054, -0.054, 0.95], [0.054, 0.054, 1.05]])  # 2 pixels over, partly behind the occluder
    assert 1.6 < silhouette_off([wide], mine, others, depth, np.eye(4), K)[1] < 2.4


def test_a_body_lying_on_another_has_its_whole_outline() -> None:
    depth, mine, others = _capture()
    behind = ~mine & (depth > 1.9)  # the wall as another object's surface, seen behind the box
    depth = np.where(behind, 1.2, depth)
    solid = trimesh.creation.box(bounds=[[-0.046, -0.046, 0.95], [0.046, 0.046, 1.05]])
    assert silhouette_off([solid], mine, others | behind, depth, np.eye(4), K) == (2.0, 0.0)
