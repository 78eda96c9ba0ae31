"""A low body lying flat is mirrored behind its crest: the far side the camera above cannot see."""

from __future__ import annotations

import numpy as np

from realsim.completion import CompletionParams, DepthView
from realsim.completion.mirror import mirror_about_crest
from realsim.perception.intrinsics import Intrinsics

INTR = Intrinsics(fx=200.0, fy=200.0, cx=79.5, cy=59.5, width=160, height=120)
CAMERA = np.array([-1.0, 0.0, 0.6])  # in front of the body (along -x) and above it


def _view() -> DepthView:
    """A camera at CAMERA looking along +x (nothing captured: no free space to keep images out of)."""
    world_to_optical = np.eye(4)
    world_to_optical[:3, :3] = [[0, -1, 0], [0, 0, -1], [1, 0, 0]]  # optical +z = world +x
    world_to_optical[:3, 3] = world_to_optical[:3, :3] @ -CAMERA
    return DepthView(INTR, world_to_optical, 1.0, np.full((INTR.height, INTR.width), np.nan))


def _seen(points: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """The surface points facing the camera (a convex body hides the rest)."""
    return points[np.einsum("ij,ij->i", normals, CAMERA - points) > 0]


def test_a_lying_cylinder_gets_its_far_side_behind_the_crest() -> None:
    r = 0.03  # a bottle on its side: axis along y, 20 cm long, on the support at z = 0
    a, y = np.meshgrid(np.linspace(0, 2 * np.pi, 180, endpoint=False), np.linspace(-0.1, 0.1, 60))
    normals = np.column_stack([np.cos(a).ravel(), np.zeros(a.size), np.sin(a).ravel()])
    surface = np.column_stack([r * normals[:, 0], y.ravel(), r + r * normals[:, 2]])
    seen = _seen(surface, normals)
    assert seen[:, 0].max() < 0.8 * r  # the camera's line of sight grazes the far side above its widest line
    both = mirror_about_crest(seen, _view(), 0.0, 2 * r, CompletionParams())
    assert both is not None and abs(both[:, 0].max() - r) < 0.003 and abs(both[:, 0].min() + r) < 0.003


def test_a_flat_top_seen_whole_is_not_stretched_and_a_top_rising_away_is_no_crest() -> None:
    x, y = np.meshgrid(np.linspace(-0.05, 0.05, 41), np.linspace(-0.08, 0.08, 41))
    top = np.column_stack([x.ravel(), y.ravel(), np.full(x.size, 0.04)])  # a 10 x 16 x 4 cm box lying flat
    front = np.column_stack([np.full(x.size, -0.05), y.ravel(), 0.04 * (x.ravel() + 0.05) / 0.1])
    box = mirror_about_crest(np.vstack([top, front]), _view(), 0.0, 0.04, CompletionParams())
    assert box is None or box[:, 0].max() <= 0.05 + 1e-6  # its front face lands on the far edge at most
    tilted = np.column_stack([x.ravel(), y.ravel(), 0.03 + 0.1 * (x.ravel() + 0.05)])  # rising to its far edge
    assert mirror_about_crest(tilted, _view(), 0.0, 0.04, CompletionParams()) is None


def test_a_small_round_body_seen_just_over_its_crest_gets_its_far_side() -> None:
    r = 0.0095  # a marker on its side: seen from 30 degrees up, it falls only r (1 - cos 30) = 1.3 mm past its crest
    a, y = np.meshgrid(np.linspace(0, 2 * np.pi, 360, endpoint=False), np.linspace(-0.06, 0.06, 40))
    normals = np.column_stack([np.cos(a).ravel(), np.zeros(a.size), np.sin(a).ravel()])
    surface = np.column_stack([r * normals[:, 0], y.ravel(), r + r * normals[:, 2]])
    seen = _seen(surface, normals)
    seen = seen[seen[:, 2] > 0.008]  # its lowest 8 mm are taken for the support
    assert seen[:, 0].max() < 0.6 * r and r + r - seen[seen[:, 0] > 0, 2].min() < CompletionParams().mirror_crest_tolerance
    both = mirror_about_crest(seen, _view(), 0.0, 2 * r, CompletionParams())
    assert both is not None and abs(both[:, 0].max() - r) < 0.002
    assert mirror_about_crest(seen, _view(), 0.0, 2 * r, CompletionParams(mirror_crest_curved=False)) is None


def test_a_lying_box_turned_aslant_is_not_mirrored_at_its_corners() -> None:
    # a 16 x 22 x 7 cm box lying flat, turned 40 degrees: the slices across the line of sight at its
    # corners hold a near face rising into the flat top, curved in a parabola's fit but no round section
    step, (hw, hl, h) = 0.002, (0.08, 0.11, 0.07)
    u, v, z = np.arange(-hw, hw + 1e-9, step), np.arange(-hl, hl + 1e-9, step), np.arange(0.008, h + 1e-9, step)
    faces = [(np.column_stack([a.ravel(), b.ravel(), np.full(a.size, h)]), [0.0, 0.0, 1.0]) for a, b in [np.meshgrid(u, v)]]
    for sign in (-1.0, 1.0):
        faces += [(np.column_stack([np.full(a.size, sign * hw), a.ravel(), b.ravel()]), [sign, 0.0, 0.0]) for a, b in [np.meshgrid(v, z)]]
        faces += [(np.column_stack([a.ravel(), np.full(a.size, sign * hl), b.ravel()]), [0.0, sign, 0.0]) for a, b in [np.meshgrid(u, z)]]
    turn = np.array([[np.cos(0.7), -np.sin(0.7), 0], [np.sin(0.7), np.cos(0.7), 0], [0, 0, 1]])
    points = np.vstack([f for f, _ in faces]) @ turn.T
    normals = np.vstack([np.tile(n, (len(f), 1)) for f, n in faces]) @ turn.T
    box = _seen(points, normals)
    both = mirror_about_crest(box, _view(), 0.0, h, CompletionParams())
    plain = mirror_about_crest(box, _view(), 0.0, h, CompletionParams(mirror_crest_curved=False))
    assert both is not None and plain is not None and len(both) == len(plain)
