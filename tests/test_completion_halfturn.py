"""A body turned diagonally to the camera: its hidden half is its seen half turned about the axis
halfway between its grazing lines, not only reflected across the line of sight."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from scipy.spatial import ConvexHull, Delaunay

from realsim.completion import CompletionParams, DepthView, mirror_hidden_half
from realsim.completion.mirror import _axis_at
from realsim.perception.intrinsics import Intrinsics

INTR = Intrinsics(fx=200.0, fy=200.0, cx=79.5, cy=59.5, width=160, height=120)


def _oval(turn: float, n: int = 180) -> tuple[np.ndarray, np.ndarray]:
    """An oval section (12 x 5 cm) turned by ``turn`` about z, centred 1 m in front of the camera: its
    outline and outward normals (xy)."""
    t = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    c, s = np.cos(turn), np.sin(turn)
    rot = np.array([[c, -s], [s, c]])
    outline = np.column_stack([0.06 * np.cos(t), 0.025 * np.sin(t)]) @ rot.T
    normal = np.column_stack([np.cos(t) / 0.06, np.sin(t) / 0.025]) @ rot.T
    return outline + [1.0, 0.0], normal


def _view(background: float, turn: float) -> DepthView:
    """A camera at (0, 0, 0.1) looking along +x: it sees the oval's front (its nearest depth) in the
    columns it covers and ``background`` beside it."""
    world_to_optical = np.eye(4)
    world_to_optical[:3, :3] = [[0, -1, 0], [0, 0, -1], [1, 0, 0]]  # optical +z = world +x
    world_to_optical[:3, 3] = world_to_optical[:3, :3] @ -np.array([0.0, 0.0, 0.1])
    outline, _ = _oval(turn)
    y = -(np.arange(INTR.width) - INTR.cx) / INTR.fx * outline[:, 0].min()  # world y of each column at the front
    front = (y >= outline[:, 1].min()) & (y <= outline[:, 1].max())
    depth = np.full((INTR.height, INTR.width), background)
    depth[:, front] = outline[:, 0].min()
    return DepthView(INTR, world_to_optical, 1.0, depth)


def _seen_side(turn: float) -> np.ndarray:
    """The surface points of the upright oval prism (20 cm tall) whose normal faces the camera."""
    outline, normal = _oval(turn)
    facing = np.einsum("ij,ij->i", normal, -outline) > 0  # the camera at the xy origin
    z = np.linspace(0.0, 0.2, 30)
    return np.column_stack([np.repeat(outline[facing], len(z), axis=0), np.tile(z, facing.sum())])


def _covered(points: np.ndarray, turn: float) -> float:
    """The share of the oval's outline (at mid height) inside the hull of ``points`` (a little slack)."""
    outline, _ = _oval(turn)
    centre = np.array([1.0, 0.0])
    hull = Delaunay(points[:, :2])
    return float(np.mean(hull.find_simplex(centre + 0.97 * (outline - centre)) >= 0))


def _area_share(points: np.ndarray, turn: float) -> float:
    """The area of the hull of ``points`` (xy) as a share of the oval's."""
    return float(ConvexHull(points[:, :2]).volume / (np.pi * 0.06 * 0.025))


@pytest.mark.parametrize("deg", [20.0, 40.0, 60.0])
def test_a_diagonal_oval_is_completed_by_the_half_turn(deg: float) -> None:
    turn = np.radians(deg)
    seen = _seen_side(turn)
    params = CompletionParams()
    turned = mirror_hidden_half(seen, _view(5.0, turn), 0.0, 0.2, params)
    reflected = mirror_hidden_half(seen, _view(5.0, turn), 0.0, 0.2, dataclasses.replace(params, mirror_point=False))
    assert turned is not None and reflected is not None
    assert _covered(turned, turn) > 0.92  # the camera sees less than half: a little of the oval by its grazing lines is short
    assert _covered(reflected, turn) < 0.9  # the reflection alone misses the far end of a diagonal oval


@pytest.mark.parametrize("deg", [20.0, 40.0, 60.0])
def test_a_diagonal_oval_is_not_also_reflected(deg: float) -> None:
    """The reflection of a turned oval's front across the line of sight reaches past its far side: the
    half turn alone is the oval (within the axis' error), the hull of both images a quarter larger or more."""
    turn = np.radians(deg)
    seen = _seen_side(turn)
    params = CompletionParams()
    alone = mirror_hidden_half(seen, _view(5.0, turn), 0.0, 0.2, params)
    both = mirror_hidden_half(seen, _view(5.0, turn), 0.0, 0.2, dataclasses.replace(params, mirror_turn_alone=False))
    assert alone is not None and both is not None
    assert _area_share(alone, turn) < 1.12
    assert _area_share(both, turn) > 1.25


def test_the_axis_between_the_grazing_lines_follows_them_with_height() -> None:
    """A body narrowing toward one side (a bottle's shoulder toward an offset cap): the middles of its
    grazing lines move with height, and the axis follows them (a line), held at its ends beyond them."""
    z = np.linspace(0.02, 0.14, 7)
    middles = np.column_stack([1.0 + 0.05 * z, 0.2 * z, np.full(len(z), 0.02), z])  # depth, lateral, stagger, height
    s, w = _axis_at(middles, np.array([0.02, 0.08, 0.14, 0.2]))
    assert np.allclose(s, 1.0 + 0.05 * np.array([0.02, 0.08, 0.14, 0.14]))
    assert np.allclose(w, 0.2 * np.array([0.02, 0.08, 0.14, 0.14]))


def test_no_half_turn_the_camera_saw_through() -> None:
    turn = np.radians(40.0)
    seen = _seen_side(turn)
    view = _view(5.0, turn)
    view.depth[view.depth < 5.0] = 1.2  # the camera saw a wall 1.2 m away through where the turned back would be
    params = CompletionParams()
    refuted = mirror_hidden_half(seen, view, 0.0, 0.2, params)
    reflected = mirror_hidden_half(seen, view, 0.0, 0.2, dataclasses.replace(params, mirror_point=False))
    believed = mirror_hidden_half(seen, view, 0.0, 0.2, dataclasses.replace(params, mirror_turn_refuted=1.0))
    assert refuted is not None and reflected is not None and believed is not None
    assert np.array_equal(refuted, reflected)
    assert len(believed) == len(seen)  # believed, every turned point is trimmed by the free space


def test_a_half_turn_a_little_off_is_trimmed_not_refuted() -> None:
    """The camera saw through a few of the turned points (a cap or shoulder that is not symmetric, an axis
    a little off): those go, the rest stays, and the reflection is not added."""
    turn = np.radians(40.0)
    seen = _seen_side(turn)
    view = _view(5.0, turn)
    top_rows = np.arange(view.depth.shape[0]) < 41  # the rows of the oval's upper 1.5 cm
    view.depth[np.ix_(top_rows, view.depth[0] < 5.0)] = 1.2  # the camera saw past the top of the oval there
    params = CompletionParams()
    done = mirror_hidden_half(seen, view, 0.0, 0.2, params)
    clear = mirror_hidden_half(seen, _view(5.0, turn), 0.0, 0.2, params)
    assert done is not None and clear is not None
    trimmed = len(clear) - len(done)
    assert 0 < trimmed < params.mirror_turn_refuted * (len(clear) - len(seen))
    assert _area_share(done, turn) < 1.12  # turned, not also reflected
    assert not np.any(view.seen_through(done[len(seen):], params.carve_tolerance))


def test_no_half_turn_where_a_nearer_body_hides_the_sides() -> None:
    turn = np.radians(40.0)
    seen = _seen_side(turn)
    params = CompletionParams()
    hidden = mirror_hidden_half(seen, _view(0.5, turn), 0.0, 0.2, params)  # something nearer beside both ends
    reflected = mirror_hidden_half(seen, _view(0.5, turn), 0.0, 0.2, dataclasses.replace(params, mirror_point=False))
    assert hidden is not None and reflected is not None and np.array_equal(hidden, reflected)
