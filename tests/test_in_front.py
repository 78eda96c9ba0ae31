"""Segments lying in front of their neighbours (objects on objects) versus pieces of a surface."""

from __future__ import annotations

import numpy as np

from realsim.perception.in_front import in_front


def _grid_pairs(h: int, w: int) -> tuple[np.ndarray, np.ndarray]:
    idx = np.arange(h * w).reshape(h, w)
    a = np.concatenate([idx[:, :-1].ravel(), idx[:-1].ravel()])
    b = np.concatenate([idx[:, 1:].ravel(), idx[1:].ravel()])
    return a, b


def _scene(patch_depth: float, touch_cols: int = 0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A 40 x 40 view of one surface at depth 1 m (segment 0) with a 10 x 10 patch (segment 1) at
    ``patch_depth``; ``touch_cols`` columns of the patch's left edge lie on the surface (a contact)."""
    h = w = 40
    labels = np.zeros((h, w), dtype=np.int64)
    labels[15:25, 15:25] = 1
    depth = np.full((h, w), 1.0)
    depth[15:25, 15:25] = patch_depth
    depth[15:25, 15:15 + touch_cols] = 1.0
    normals = np.tile([0.0, 0.0, -1.0], (h * w, 1))  # every surface faces the camera
    return labels.ravel(), depth.ravel(), normals


def test_an_object_lying_on_a_surface_is_in_front_of_it() -> None:
    labels, depth, normals = _scene(0.97, touch_cols=1)  # 3 cm nearer, touching along one edge
    a, b = _grid_pairs(40, 40)
    front = in_front(labels, a, b, depth, normals, min_jump=0.008, max_turn_deg=40.0, share=0.6)
    assert front[1] and not front[0]  # the surface around is not in front of the object


def test_a_piece_of_the_surface_is_not_in_front() -> None:
    labels, depth, normals = _scene(1.0)  # the same surface, cut off by a colour edge or a fold
    a, b = _grid_pairs(40, 40)
    assert not in_front(labels, a, b, depth, normals, 0.008, 40.0, 0.6).any()


def test_a_piece_seen_past_a_rim_is_not_in_front() -> None:
    labels, depth, normals = _scene(1.05)  # farther: a container's inside, hidden by its rim all round
    a, b = _grid_pairs(40, 40)
    assert not in_front(labels, a, b, depth, normals, 0.008, 40.0, 0.6)[1]


def test_an_object_mostly_touching_its_neighbour_is_not_in_front() -> None:
    labels, depth, normals = _scene(0.97, touch_cols=8)  # nearly all of it lies on the surface's level
    a, b = _grid_pairs(40, 40)
    assert not in_front(labels, a, b, depth, normals, 0.008, 40.0, 0.6)[1]


def test_an_object_standing_on_a_surface_meets_it_at_a_crease() -> None:
    """Touching along a whole edge, where its upright face meets the surface at a right angle: the
    contact is a crease, not the surface continuing, so it still lies in front."""
    labels, depth, normals = _scene(0.97, touch_cols=8)
    normals[labels == 1] = [0.0, -1.0, 0.0]  # the object's face stands upright
    a, b = _grid_pairs(40, 40)
    assert in_front(labels, a, b, depth, normals, 0.008, 40.0, 0.6)[1]


def test_absorb_keeps_segments_marked_whole() -> None:
    """A small piece joins its large neighbour, unless it is marked as an object in front of it."""
    from realsim.perception.segment import absorb_small

    labels = np.repeat(np.arange(3), [30, 500, 40])
    a = np.arange(len(labels) - 1)
    b = a + 1
    assert len(np.unique(absorb_small(labels, a, b, 100, among_small=True))) == 1
    out = absorb_small(labels, a, b, 100, among_small=True, whole=labels == 0)
    assert len(np.unique(out)) == 2 and len(np.unique(out[:30])) == 1 and out[0] != out[30]
