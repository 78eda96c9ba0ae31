"""A side edge bordering a nearer object is continued behind it; an edge the camera saw past is not
(generated ground truth: boxes on a table, ray-cast from a camera in front and above)."""

from __future__ import annotations

import numpy as np
from test_completion_fragments import INTR, TABLE, _box, _capture

from realsim.completion.occlusion import hidden_continuation, lateral_edges, seen_through_added
from realsim.completion.view import DepthView

CUBE = ((-0.01, 0.10), (0.08, 0.18))  # x and y ranges of a 9 x 8 cm box, 6 cm high, its left half hidden


def _view(occluder_y: tuple[float, float]) -> tuple[np.ndarray, np.ndarray, DepthView, np.ndarray]:
    """The box (object 2) behind or beside a tall narrow box (object 1) covering x < 0.045: world
    points, labels, the view and the box's seen points."""
    (x0, x1), (y0, y1) = CUBE
    cube = _box((x0, y0, TABLE), (x1, y1, TABLE + 0.06))
    occluder = _box((-0.06, occluder_y[0], TABLE), (0.045, occluder_y[1], TABLE + 0.3))
    world, which, depth, w2o = _capture([cube, occluder])
    labels = np.where(which == 1, 2, np.where(which == 2, 1, 0))
    view = DepthView(INTR, w2o, 1.0, depth, labels.reshape(INTR.height, INTR.width))
    return world, labels, view, world[labels == 2]


def _continued(occluder_y: tuple[float, float]) -> tuple[np.ndarray, np.ndarray, DepthView]:
    world, labels, view, seen = _view(occluder_y)
    hidden = hidden_continuation(view, labels, world, np.ones(len(labels), bool), 2, seen, TABLE, 0.004, 0.01, 2, 1.0)
    return hidden, seen, view


def test_a_box_half_hidden_behind_a_nearer_one_is_continued_behind_it() -> None:
    hidden, seen, view = _continued((-0.05, 0.0))  # in front of the box's left part
    assert seen[:, 0].min() > 0.04  # the camera saw only its right part
    assert len(hidden) and hidden[:, 0].min() < 0.02  # continued behind the occluder, most of the way to its true left side
    assert hidden[:, 0].min() > CUBE[0][0] - 0.03  # not far past it (the visible width, doubled, at most)
    assert np.all((hidden[:, 1] > CUBE[1][0] - 0.005) & (hidden[:, 1] < CUBE[1][1] + 0.005))  # across, not in depth
    assert seen_through_added(view, seen, hidden, TABLE, TABLE + 0.06, 2, 0.004) <= 0.01  # nothing seen through added


def test_an_edge_beside_a_farther_object_is_a_true_edge() -> None:
    hidden, _, _ = _continued((0.25, 0.30))  # the same narrow box, now behind it: the camera saw past its left edge
    assert len(hidden) == 0


def test_only_nearer_neighbours_beside_an_edge_occlude_it() -> None:
    _, labels, view, _ = _view((-0.05, 0.0))
    occluded, sides, clear, clear_sides = lateral_edges(labels.reshape(view.depth.shape), view.depth, 2, 0.01, 2)
    assert len(occluded) and np.all(sides == -1)  # the occluder is on its left in the image
    assert len(clear) and np.all(clear_sides == 1)  # its right side edge, the background beyond it
    assert len(lateral_edges(labels.reshape(view.depth.shape), view.depth, 2, 0.01, 2, stacked=(1,))[0]) == 0
