"""Completion uses what the camera saw: free-space carving, veils, neighbours cut apart."""

from __future__ import annotations

import numpy as np
import trimesh
from ball_drop import drop_ball

from realsim.completion import CompletionParams, DepthView, carve_free_space, clip_convex, mirror_hidden_half
from realsim.completion.carving import carve_pieces
from realsim.perception.intrinsics import Intrinsics

INTR = Intrinsics(fx=200.0, fy=200.0, cx=79.5, cy=59.5, width=160, height=120)


def _view(depth: np.ndarray, labels: np.ndarray | None = None) -> DepthView:
    """A camera at the origin looking down -z of the world (optical z = -world z, y flipped)."""
    world_to_optical = np.diag([1.0, -1.0, -1.0, 1.0])
    return DepthView(INTR, world_to_optical, 1.0, depth, labels)


def _depth_of_box(lo: np.ndarray, hi: np.ndarray, floor: float) -> np.ndarray:
    """What the camera above sees: the top of the box [lo, hi] (world, z up) on a floor at z = floor."""
    v, u = np.mgrid[0:INTR.height, 0:INTR.width]
    ray = np.stack([(u - INTR.cx) / INTR.fx, -(v - INTR.cy) / INTR.fy], axis=-1)  # world xy per unit depth
    depth = np.full(u.shape, -floor)
    top = -hi[2]
    xy = ray * top
    on_box = (xy[..., 0] >= lo[0]) & (xy[..., 0] <= hi[0]) & (xy[..., 1] >= lo[1]) & (xy[..., 1] <= hi[1])
    depth[on_box] = top
    return depth


def test_a_shape_grown_where_the_camera_saw_the_floor_is_carved_back() -> None:
    lo, hi = np.array([-0.05, -0.04, -1.0]), np.array([0.05, 0.04, -0.9])  # a 10 x 8 x 10 cm box, 0.9 m below the camera
    depth = _depth_of_box(lo, hi, floor=-1.0)
    view = _view(depth, np.where(depth < 0.95, 1, 0))  # object 1 where the camera saw the box top
    too_big = trimesh.creation.box(bounds=[[-0.05, -0.04, -1.0], [0.12, 0.04, -0.9]])  # extruded 7 cm too far in +x
    observed = np.array([[x, y, -0.9] for x in np.linspace(-0.05, 0.05, 11) for y in np.linspace(-0.04, 0.04, 9)])
    carved, fraction = carve_free_space(too_big, view, -1.0, observed, CompletionParams(), own=1)
    assert 0.3 < fraction < 0.5  # 7 of 17 cm were seen through
    assert carved.bounds[1][0] < 0.06 and carved.bounds[0][0] < -0.045
    assert abs(carved.bounds[0][2] + 1.0) < 1e-9  # still standing on its base
    right, f = carve_free_space(trimesh.creation.box(bounds=[lo, hi]), view, -1.0, observed, CompletionParams(), own=1)
    assert f < CompletionParams().carve_min_fraction and np.allclose(right.bounds, [lo, hi])  # a correct shape is left alone
    # the carved shape hides few pixels where the camera saw farther (a voxel's width along its outline)
    pts = carved.sample(20000, seed=0)
    bad = pts[view.seen_through(pts, 0.006)]
    bad_pixels = {tuple(p) for p in np.rint(INTR.project(bad * [1, -1, -1])).astype(int)}
    too_big_pts = too_big.sample(20000, seed=0)
    before = {tuple(p) for p in np.rint(INTR.project(too_big_pts[view.seen_through(too_big_pts, 0.006)] * [1, -1, -1])).astype(int)}
    assert len(bad_pixels) < 0.15 * len(before)


def test_a_carved_round_underside_stays_round() -> None:
    # a 6 cm bottle lying along y, 0.9-1 m below the camera, one piece of it completed 3 cm too high
    # over its round underside (the hull of its section and that section raised): carved back to what
    # the camera saw, it still touches the floor along a line, not on its lowest voxel row laid flat
    r, floor = 0.03, -1.0
    a = np.linspace(0.0, 2 * np.pi, 48, endpoint=False)
    ring = np.column_stack([r * np.cos(a), np.zeros(a.size), floor + r + r * np.sin(a)])
    ends = [ring + [0.0, y, dz] for dz in (0.0, 0.03) for y in (-0.06, 0.06)]
    too_high = trimesh.convex.convex_hull(np.vstack(ends))
    v, u = np.mgrid[0:INTR.height, 0:INTR.width]
    x, y = (u - INTR.cx) / INTR.fx * 0.94, -(v - INTR.cy) / INTR.fy * 0.94
    on_body = (np.abs(x) < r) & (np.abs(y) <= 0.06)
    depth = np.where(on_body, -(floor + r + np.sqrt(np.clip(r * r - x * x, 0.0, None))), -floor)
    view = _view(depth, np.where(on_body, 1, 0))
    widths = []
    for surface in (True, False):
        pieces, fraction = carve_pieces([too_high], view, floor, CompletionParams(carve_surface_ends=surface), own=1)
        assert fraction > 0.2 and len(pieces) == 1
        bottom = pieces[0].vertices[pieces[0].vertices[:, 2] < floor + 0.0005]
        widths.append(float(np.ptp(bottom[:, 0])))
    assert widths[0] < 0.011 and widths[0] < 0.7 * widths[1]  # laid flat: the chord where the lowest voxel centres lie


def test_veil_pixels_are_the_ones_seen_edge_on() -> None:
    depth = _depth_of_box(np.array([-0.05, -0.04, -1.0]), np.array([0.05, 0.04, -0.9]), floor=-1.0)
    veil = _view(depth).veil(80.0)
    assert veil.sum() > 0
    v, u = np.nonzero(veil)
    assert np.all(np.abs(np.diff(depth, axis=1, prepend=depth[:, :1]))[v, u] + np.abs(np.diff(depth, axis=0, prepend=depth[:1]))[v, u] > 0) \
        or veil.mean() < 0.05  # only along the box's silhouette
    assert veil.mean() < 0.05


def test_clip_convex_keeps_one_side() -> None:
    box = trimesh.creation.box(extents=[0.2, 0.1, 0.1])
    half = clip_convex(box, np.array([1.0, 0.0, 0.0]), 0.05)
    assert half is not None and np.isclose(half.bounds[0][0], 0.05) and np.isclose(half.volume, 0.05 * 0.1 * 0.1)
    assert clip_convex(box, np.array([1.0, 0.0, 0.0]), 0.2) is None


def _bowl_points(radius: float = 0.08, height: float = 0.055, seed: int = 0) -> np.ndarray:
    """What a camera above sees of a bowl on z = 0: its rim, its inside and part of its outside."""
    rng = np.random.default_rng(seed)
    a = rng.uniform(0, 2 * np.pi, 6000)
    s = np.sqrt(rng.uniform(0, 1, 6000))
    inside = np.column_stack([0.92 * radius * s * np.cos(a), 0.92 * radius * s * np.sin(a), 0.008 + (height - 0.008) * s**2])
    b = rng.uniform(-np.pi / 2, np.pi / 2, 3000)  # the near half of the outside
    h = rng.uniform(0, height, 3000)
    r_out = radius * (0.6 + 0.4 * np.sqrt(h / height))
    outside = np.column_stack([r_out * np.cos(b), r_out * np.sin(b), h])
    return np.vstack([inside, outside]) + rng.normal(0, 0.001, (9000, 3))


def test_an_open_bowl_is_completed_hollow_and_holds_a_ball() -> None:
    from realsim.completion.containers import complete_open_container, round_rim

    pts = _bowl_points()
    rim = round_rim(pts, 0.0, 0.055, 0.2)
    assert rim is not None and abs(rim[1] - 0.08) < 0.008
    bowl = complete_open_container(pts, rim[0], rim[1], 0.0, 0.055)
    assert bowl is not None and 0.002 <= bowl.wall <= 0.02 and bowl.floor_z < 0.02
    assert bowl.visual.is_volume and bowl.visual.volume < 0.5 * bowl.outer.volume  # hollow
    can = complete_open_container(np.column_stack([pts[:, :2], np.full(len(pts), 0.055)]), rim[0], rim[1], 0.0, 0.055)
    assert can is None  # a closed top is not a container
    x, y, z = drop_ball(bowl.pieces, np.array([0.02, 0.0, 0.15]), seconds=2.0)
    assert np.hypot(x - rim[0][0], y - rim[0][1]) < rim[1] - bowl.wall and bowl.floor_z - 0.003 < z - 0.015 < 0.05


def test_the_hidden_half_of_a_flat_bottle_is_mirrored_behind_its_silhouette() -> None:
    # an elliptic bottle (10 cm wide, 6 cm deep, 20 cm tall) seen from the front (camera far along -x, looking +x)
    t = np.linspace(-np.pi / 2, np.pi / 2, 60)
    z = np.linspace(0.0, 0.2, 40)
    tt, zz = np.meshgrid(t, z)
    front = np.column_stack([-0.03 * np.cos(tt).ravel(), 0.05 * np.sin(tt).ravel(), zz.ravel()])
    world_to_optical = np.eye(4)
    world_to_optical[:3, :3] = [[0, -1, 0], [0, 0, -1], [1, 0, 0]]  # optical +z = world +x
    world_to_optical[:3, 3] = world_to_optical[:3, :3] @ -np.array([-1.0, 0.0, 0.1])
    view = DepthView(INTR, world_to_optical, 1.0, np.full((INTR.height, INTR.width), np.nan))
    both = mirror_hidden_half(front, view, 0.0, 0.2, CompletionParams())
    assert both is not None and np.isclose(np.ptp(both[:, 0]), 0.06, atol=0.002)
    box_top = np.column_stack([np.tile(np.linspace(-0.03, 0.03, 30), 40), np.repeat(np.linspace(-0.05, 0.05, 40), 30), np.full(1200, 0.2)])
    assert mirror_hidden_half(np.vstack([front, box_top]), view, 0.0, 0.2, CompletionParams()) is None  # its whole top is seen


def test_free_space_is_certain_only_past_the_pixels_around_a_point() -> None:
    # the box top (10 cm wide, 0.9 m below) ends between pixel columns 90 (box) and 91 (floor)
    depth = _depth_of_box(np.array([-0.05, -0.04, -1.0]), np.array([0.05, 0.04, -0.9]), floor=-1.0)
    view = _view(depth, np.where(depth < 0.95, 1, 0))
    assert depth[60, 90] == 0.9 and depth[60, 91] == 1.0

    def at(u: float) -> np.ndarray:  # a point at the box top's height on the ray through column u, row 59.5
        return np.array([[(u - INTR.cx) / INTR.fx * 0.9, 0.0, -0.9]])

    edge, past = at(90.8), at(91.6)  # between the last box pixel and the first floor pixel; past the floor pixel
    assert view.seen_through(edge, 0.005, footprint=False)[0]  # its nearest pixel saw the floor...
    assert not view.seen_through(edge, 0.005)[0]  # ...but the box's edge may lie anywhere up to that pixel
    assert view.seen_through(past, 0.005)[0] and view.seen_through(past, 0.005, own=1)[0]


def test_edge_pixels_continuing_the_surface_are_kept_and_mixed_ones_dropped() -> None:
    depth = _depth_of_box(np.array([-0.05, -0.04, -1.0]), np.array([0.05, 0.04, -0.9]), floor=-1.0)
    labels = np.where(depth < 0.95, 1, 0)
    depth[50, 91], depth[55, 91] = 0.95, 0.902  # a mixed depth between box and floor; the box's own edge
    labels[50, 91] = labels[55, 91] = 1
    veil = np.zeros(depth.shape, bool)
    veil[50, 91] = veil[55, 91] = True
    out = _view(depth, labels).unveiled(veil, 0.005)
    assert np.isnan(out.depth[50, 91]) and out.depth[55, 91] == 0.902
    assert np.array_equal(out.depth[~veil], depth[~veil])
