"""Shape families of completion on generated ground truth: revolved profiles, slabs, carved pieces."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
import trimesh

from realsim.completion import CompletionParams, DepthView, carving
from realsim.completion.carving import carve_pieces, carve_to_tiles
from realsim.completion.extrusion import complete_hull, complete_slabs
from realsim.completion.revolution import complete_revolved
from realsim.perception.intrinsics import Intrinsics

GRID = 0.002


def _inside(pieces: list[trimesh.Trimesh], pts: np.ndarray) -> np.ndarray:
    """Points inside the union of convex pieces (behind every face plane of one of them)."""
    out = np.zeros(len(pts), bool)
    for p in pieces:
        n, o = p.face_normals, p.triangles[:, 0, :]
        out |= np.all(pts @ n.T - np.einsum("fk,fk->f", o, n)[None, :] <= 1e-9, axis=1)
    return out


def _iou(pieces: list[trimesh.Trimesh], truth, lo: np.ndarray, hi: np.ndarray) -> float:
    axes = [np.arange(a + GRID / 2, b, GRID) for a, b in zip(lo, hi)]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    a, b = _inside(pieces, grid), truth(grid)
    return float(np.count_nonzero(a & b)) / max(np.count_nonzero(a | b), 1)


def _bottle_radius(z: np.ndarray) -> np.ndarray:
    """A bottle 20 cm tall: a 4 cm radius body up to 13 cm, a shoulder, a 1.5 cm neck from 16 cm."""
    return np.interp(z, [0.0, 0.13, 0.16, 0.2], [0.04, 0.04, 0.015, 0.015])


def _front_of_bottle(camera_xy: np.ndarray, seed: int = 0) -> np.ndarray:
    """What a camera at ``camera_xy`` sees of the bottle: its near half, its cap; 1 mm noise."""
    rng = np.random.default_rng(seed)
    toward = np.arctan2(camera_xy[1], camera_xy[0])
    a = toward + rng.uniform(-np.pi / 2, np.pi / 2, 8000)
    z = rng.uniform(0.0, 0.2, 8000)
    side = np.column_stack([_bottle_radius(z) * np.cos(a), _bottle_radius(z) * np.sin(a), z])
    r = 0.015 * np.sqrt(rng.uniform(0, 1, 500))
    b = rng.uniform(0, 2 * np.pi, 500)
    cap = np.column_stack([r * np.cos(b), r * np.sin(b), np.full(500, 0.2)])
    return np.vstack([side, cap]) + rng.normal(0, 0.001, (8500, 3))


def test_a_bottle_seen_from_one_side_is_its_profile_revolved() -> None:
    camera = np.array([-1.0, -0.3])
    solid = complete_revolved(_front_of_bottle(camera), 0.0, 0.2, CompletionParams(), camera)
    assert solid is not None and abs(solid.radius - 0.04) < 0.004

    def truth(p: np.ndarray) -> np.ndarray:
        return (p[:, 2] >= 0) & (p[:, 2] <= 0.2) & (np.hypot(p[:, 0], p[:, 1]) <= _bottle_radius(p[:, 2]))

    iou = _iou(solid.pieces, truth, np.array([-0.05, -0.05, 0.0]), np.array([0.05, 0.05, 0.2]))
    assert iou >= 0.85
    hull = complete_hull(_front_of_bottle(camera), 0.0, 0.2)[0]  # the visible half extruded: about half the bottle
    assert _iou([hull], truth, np.array([-0.05, -0.05, 0.0]), np.array([0.05, 0.05, 0.2])) < 0.7 < iou
    assert solid.visual.is_volume


def test_a_flat_body_narrower_than_its_circle_is_not_revolved() -> None:
    # an elliptic bottle (12 cm wide, 5 cm deep) seen from its narrow side: its front arc fits a
    # circle, but the silhouette across the line of sight is narrower than that circle
    rng = np.random.default_rng(1)
    a = rng.uniform(-np.pi / 2, np.pi / 2, 4000)
    z = rng.uniform(0, 0.15, 4000)
    pts = np.column_stack([-0.025 * np.cos(a), 0.06 * np.sin(a), z])
    pts = pts[np.abs(pts[:, 1]) < 0.03]  # the camera far along -x sees the middle of the flat side
    assert complete_revolved(pts, 0.0, 0.15, CompletionParams(), np.array([-1.0, 0.0])) is None


def _banana_top(seed: int = 0) -> tuple[np.ndarray, callable]:
    """The top of a curved bar lying on z = 0 (an arc of radius 12 cm over 120 degrees, 3.5 cm wide,
    3 cm tall) and its inside test."""
    rng = np.random.default_rng(seed)
    t = rng.uniform(np.radians(30), np.radians(150), 6000)
    w = rng.uniform(-0.0175, 0.0175, 6000)
    r = 0.12 + w
    top = np.column_stack([r * np.cos(t), r * np.sin(t), np.full(6000, 0.03)]) + rng.normal(0, 0.001, (6000, 3))

    def truth(p: np.ndarray) -> np.ndarray:
        rr, tt = np.hypot(p[:, 0], p[:, 1]), np.arctan2(p[:, 1], p[:, 0])
        return (np.abs(rr - 0.12) <= 0.0175) & (tt >= np.radians(30)) & (tt <= np.radians(150)) & (p[:, 2] >= 0) & (p[:, 2] <= 0.03)

    return top, truth


def test_a_curved_body_is_extruded_in_slabs_not_as_one_hull() -> None:
    top, truth = _banana_top()
    pieces = complete_slabs(top, 0.0, 0.03, 0.025, 8, 0.8)
    assert pieces is not None and len(pieces) >= 4
    lo, hi = np.array([-0.15, 0.0, 0.0]), np.array([0.15, 0.15, 0.03])
    hull = complete_hull(top, 0.0, 0.03)[0]
    assert _iou(pieces, truth, lo, hi) >= 0.7 > _iou([hull], truth, lo, hi)
    box = np.random.default_rng(0).uniform([-0.1, -0.05, 0.05], [0.1, 0.05, 0.05], (3000, 3))
    assert complete_slabs(box, 0.0, 0.05, 0.025, 8, 0.8) is None  # a box is its own hull


INTR = Intrinsics(fx=200.0, fy=200.0, cx=79.5, cy=59.5, width=160, height=120)


def test_pieces_grown_into_seen_free_space_are_carved_back() -> None:
    # a camera 1 m above the floor (z = -1) looking down at a 10 x 8 x 10 cm box; the two pieces of a
    # completed shape reach 7 cm past the box where the camera saw the floor
    v, u = np.mgrid[0:INTR.height, 0:INTR.width]
    x, y = (u - INTR.cx) / INTR.fx * 0.9, -(v - INTR.cy) / INTR.fy * 0.9
    on_box = (np.abs(x) <= 0.05) & (np.abs(y) <= 0.04)
    depth = np.where(on_box, 0.9, 1.0)
    view = DepthView(INTR, np.diag([1.0, -1.0, -1.0, 1.0]), 1.0, depth, np.where(on_box, 1, 0))
    pieces = [trimesh.creation.box(bounds=[[-0.05, -0.04, -1.0], [0.0, 0.04, -0.9]]), trimesh.creation.box(bounds=[[0.0, -0.04, -1.0], [0.12, 0.04, -0.9]])]
    carved, share = carve_pieces(pieces, view, -1.0, CompletionParams(), own=1)
    assert 0.25 < share < 0.5 and len(carved) == 2
    assert np.isclose(carved[0].bounds[0][0], -0.05, atol=0.003) and carved[1].bounds[1][0] < 0.06  # the seen floor is empty again
    pts = np.vstack([c.sample(5000, seed=0) for c in carved])
    assert view.seen_through(pts, 0.006).mean() < 0.02


def _two_blocks_seen_from_above() -> tuple[DepthView, trimesh.Trimesh, np.ndarray]:
    """Two 4 x 8 x 10 cm blocks 4 cm apart (a handle beside a body), 0.9 m below a camera looking
    down: the view, the hull that bridges the gap where the camera saw the floor, the seen top."""
    v, u = np.mgrid[0:INTR.height, 0:INTR.width]
    x, y = (u - INTR.cx) / INTR.fx * 0.9, -(v - INTR.cy) / INTR.fy * 0.9
    on_body = (np.abs(np.abs(x) - 0.04) <= 0.02) & (np.abs(y) <= 0.04)
    view = DepthView(INTR, np.diag([1.0, -1.0, -1.0, 1.0]), 1.0, np.where(on_body, 0.9, 1.0), np.where(on_body, 1, 0))
    hull = trimesh.creation.box(bounds=[[-0.06, -0.04, -1.0], [0.06, 0.04, -0.9]])
    top = np.column_stack([x[on_body], y[on_body], np.full(on_body.sum(), -0.9)])
    return view, hull, top


def test_a_body_with_a_gap_is_kept_as_tiles_that_leave_the_gap_empty() -> None:
    view, hull, top = _two_blocks_seen_from_above()
    pieces, share = carve_to_tiles(hull, view, -1.0, top, CompletionParams(), own=1)
    assert pieces is not None and 0.25 < share < 0.45
    gap = np.column_stack([np.zeros(9), np.linspace(-0.03, 0.03, 9), np.full(9, -0.95)])
    assert not _inside(pieces, gap).any()

    def truth(p: np.ndarray) -> np.ndarray:
        return (np.abs(np.abs(p[:, 0]) - 0.04) <= 0.02) & (np.abs(p[:, 1]) <= 0.04) & (p[:, 2] >= -1.0) & (p[:, 2] <= -0.9)

    assert _iou(pieces, truth, np.array([-0.07, -0.05, -1.0]), np.array([0.07, 0.05, -0.9])) >= 0.8


def test_the_refilled_share_is_measured_only_when_it_decides_tiling(monkeypatch: pytest.MonkeyPatch) -> None:
    view, hull, top = _two_blocks_seen_from_above()  # their carved hull fills the seen gap again
    measured = []
    inside = carving._inside_convex
    monkeypatch.setattr(carving, "_inside_convex", lambda mesh, pts: measured.append(len(pts)) or inside(mesh, pts))
    params = CompletionParams()
    assert carving.carve(hull, view, -1.0, top, params, own=1, tiles=False).tiles is None
    assert carving.carve(hull, view, -1.0, top, params, own=1).tiles is not None  # seen through enough to tile
    assert carving.carve(hull, view, -1.0, top, replace(params, tile_min_fraction=np.inf), own=1).tiles is None
    assert not measured  # none of these asked for it
    refill = replace(params, tile_min_fraction=np.inf, tile_when_refilled=True)
    assert carving.carve(hull, view, -1.0, top, refill, own=1).tiles is not None and measured  # it decides here
