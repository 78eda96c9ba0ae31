"""Clusters that continue the surface behind them are backdrop; objects' outlines step or crease."""

from __future__ import annotations

import numpy as np

from realsim.perception.backdrop_patch import continues_backdrop


def _grid_pairs(h: int, w: int) -> tuple[np.ndarray, np.ndarray]:
    idx = np.arange(h * w).reshape(h, w)
    return (np.concatenate([idx[:, :-1].ravel(), idx[:-1].ravel()]),
            np.concatenate([idx[:, 1:].ravel(), idx[1:].ravel()]))


def _wall_with(patch_depth: float, upright: bool = False) -> tuple[np.ndarray, ...]:
    """A 40 x 40 view of a wall at 1 m (label 0) with a 10 x 10 cluster (label 1) at ``patch_depth``,
    facing the camera or (``upright``) square to the wall."""
    h = w = 40
    labels = np.zeros((h, w), dtype=np.int64)
    labels[15:25, 15:25] = 1
    depth = np.full((h, w), 1.0)
    depth[15:25, 15:25] = patch_depth
    normals = np.tile([0.0, 0.0, -1.0], (h * w, 1))
    if upright:
        normals[labels.ravel() == 1] = [0.0, -1.0, 0.0]
    return labels.ravel(), depth.ravel(), normals


def test_a_patch_of_the_wall_is_backdrop() -> None:
    labels, depth, normals = _wall_with(1.0)
    a, b = _grid_pairs(40, 40)
    out = continues_backdrop(labels, a, b, depth, normals, min_jump=0.008, max_turn_deg=40.0, share=0.5)
    assert out[1] and not out[0]


def test_an_object_in_front_is_no_backdrop() -> None:
    labels, depth, normals = _wall_with(0.95)
    a, b = _grid_pairs(40, 40)
    assert not continues_backdrop(labels, a, b, depth, normals, 0.008, 40.0, 0.5)[1]


def test_a_face_meeting_the_surface_at_a_crease_is_no_backdrop() -> None:
    labels, depth, normals = _wall_with(1.0, upright=True)  # level with it but square to it: a crease
    a, b = _grid_pairs(40, 40)
    assert not continues_backdrop(labels, a, b, depth, normals, 0.008, 40.0, 0.5)[1]


def test_a_cluster_bordering_only_other_objects_is_no_backdrop() -> None:
    labels, depth, normals = _wall_with(1.0)
    labels = np.where(labels == 0, 2, labels)  # the surface around is an object, not backdrop
    a, b = _grid_pairs(40, 40)
    assert not continues_backdrop(labels, a, b, depth, normals, 0.008, 40.0, 0.5)[1]


def test_a_cluster_continuing_into_its_own_foot_is_no_backdrop() -> None:
    """The pixels of a support's top (an object's foot under the height threshold) are marked < 0 by
    the caller: a low object continuing into them is no patch of the backdrop."""
    labels, depth, normals = _wall_with(1.0)
    labels = np.where(labels == 0, -1, labels)
    a, b = _grid_pairs(40, 40)
    assert not continues_backdrop(labels, a, b, depth, normals, 0.008, 40.0, 0.5)[1]
