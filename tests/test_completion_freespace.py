"""The free-space rule and hollow containers on generated ground truth (real YCB scans, ray-cast view).

A YCB object stands on a table; a Kinect-like camera (axial noise) sees it from the front and above.
Completed shapes may not cover a pixel where the camera saw farther away (1 cm, as in
bench/bench_completion.py), and may not lose what is truly there; the bowl keeps its cavity.
"""

from __future__ import annotations

import numpy as np
import open3d as o3d
import pytest
import trimesh
from ball_drop import drop_ball
from scipy.ndimage import binary_dilation

from realsim.completion import CompletionParams, DepthView, complete_hull, complete_open_container, round_rim
from realsim.completion.freespace import clip_pieces, free_drops, free_space_tolerance
from realsim.perception.intrinsics import Intrinsics
from realsim.synth import SceneSpec, backproject, kinect_noise, kinect_view, make_scene, render

pytestmark = pytest.mark.skipif(not __import__("realsim.synth", fromlist=["ycb_root"]).ycb_root().is_dir(), reason="needs the YCB scans")


def _capture(name: str, seed: int = 0) -> tuple[DepthView, np.ndarray, np.ndarray, trimesh.Trimesh, float, float]:
    """The object alone on a table, seen from the front: its view (denoised, as completion uses it),
    every pixel's world point, which are the object's, its true mesh, the table height and the
    free-space tolerance (from the captured noise)."""
    scene = make_scene(SceneSpec(layout="table", objects=(name,), n_objects=1, stacked=False, touching=False, seed=seed))
    rng = np.random.default_rng([seed, 11])
    cam = kinect_view(scene, rng, 320, 240)
    frame = render(scene, cam)
    depth = kinect_noise(frame.depth, rng)
    intr = Intrinsics(cam.fx, cam.fy, cam.cx, cam.cy, cam.width, cam.height)
    labels = np.where(np.isfinite(depth), frame.object_id, 0)
    raw = DepthView(intr, np.linalg.inv(cam.pose), 1.0, depth, labels)
    view = raw.denoised(5)
    optical = backproject(view.depth, cam).reshape(-1, 3)
    points = optical @ cam.pose[:3, :3].T + cam.pose[:3, 3]
    obj = scene.objects[0]
    tolerance = free_space_tolerance(raw, CompletionParams())
    return view, points, labels.ravel() == obj.id, obj.mesh(), scene.primary_support().height, tolerance


def _covered_pixels(pieces: list[trimesh.Trimesh], view: DepthView, tolerance: float = 0.01, beside: np.ndarray | None = None) -> int:
    """Pixels whose ray meets a piece more than ``tolerance`` before the captured depth (not counting
    those next to a pixel of the ``beside`` mask, where the object's edge may lie)."""
    rc = o3d.t.geometry.RaycastingScene()
    for p in pieces:
        v = p.vertices @ view.world_to_optical[:3, :3].T + view.world_to_optical[:3, 3]
        rc.add_triangles(o3d.core.Tensor(v.astype(np.float32)), o3d.core.Tensor(np.asarray(p.faces, np.uint32)))
    i = view.intrinsics
    v, u = np.mgrid[0:i.height, 0:i.width]
    ray = np.stack([(u - i.cx) / i.fx, (v - i.cy) / i.fy, np.ones(u.shape)], axis=-1)
    rays = np.concatenate([np.zeros_like(ray), ray], axis=-1).reshape(-1, 6).astype(np.float32)
    z = rc.cast_rays(o3d.core.Tensor(rays))["t_hit"].numpy().reshape(i.height, i.width)
    with np.errstate(invalid="ignore"):
        covered = np.isfinite(z) & (z < view.depth - tolerance)
    if beside is not None:
        covered &= ~binary_dilation(beside, np.ones((3, 3), bool))
    return int(np.count_nonzero(covered))


def _inside(pieces: list[trimesh.Trimesh], pts: np.ndarray) -> np.ndarray:
    out = np.zeros(len(pts), bool)
    for p in pieces:
        out |= np.all(pts @ p.face_normals.T - np.einsum("fk,fk->f", p.triangles[:, 0, :], p.face_normals)[None, :] <= 1e-9, axis=1)
    return out


def _true_volume_points(truth: trimesh.Trimesh, step: float = 0.003) -> np.ndarray:
    lo, hi = truth.bounds
    grid = np.stack(np.meshgrid(*[np.arange(a, b, step) for a, b in zip(lo, hi)], indexing="ij"), axis=-1).reshape(-1, 3)
    rc = o3d.t.geometry.RaycastingScene()
    rc.add_triangles(o3d.core.Tensor(truth.vertices.astype(np.float32)), o3d.core.Tensor(truth.faces.astype(np.uint32)))
    return grid[rc.compute_occupancy(o3d.core.Tensor(grid.astype(np.float32))).numpy() > 0.5]


def test_a_completed_box_covers_no_pixel_the_camera_saw_past_and_keeps_what_is_there() -> None:
    view, points, mine, truth, table, tolerance = _capture("003_cracker_box")
    pts = points[mine]
    naive = complete_hull(pts, table, float(np.percentile(pts[:, 2], 98)))[0]  # every point extruded straight down
    assert 0.002 < tolerance < 0.01  # four sigmas of the ~1.3 mm noise at a metre
    drops = free_drops(pts, table, view, tolerance)
    hull = complete_hull(pts, table, float(np.percentile(pts[:, 2], 98)), drops=drops)[0]
    clipped, share = clip_pieces([hull], view, tolerance)
    naive_px, edge_px = _covered_pixels([naive], view), _covered_pixels(clipped, view)
    assert naive_px > 50 and edge_px <= 0.05 * naive_px  # what is left lies along the box's outline
    assert _covered_pixels(clipped, view, beside=mine.reshape(view.depth.shape)) == 0
    solid = _true_volume_points(truth)
    kept = np.mean(_inside(clipped, solid))
    assert kept >= 0.9 * np.mean(_inside([naive], solid)) and share < 0.15  # the cuts took free space, little of the box
    top = hull.bounds[1][2]
    stands = pts[pts[:, 2] >= top - 0.01] + [0, 0, 0.0005]  # the base of something standing on all its top
    held, _ = clip_pieces([hull], view, tolerance, keep=stands)
    assert np.mean(_inside(held, stands - [0, 0, 0.001])) >= 0.99  # no cut took the top from under it (without keep: 87 %)
    assert _covered_pixels(held, view) <= 0.1 * naive_px
    assert np.mean(_inside(held, solid)) >= 0.9 * np.mean(_inside([naive], solid))


def test_the_scanned_bowl_is_one_hollow_piece_set_that_holds_a_ball() -> None:
    view, points, mine, truth, table, tolerance = _capture("024_bowl", seed=2)
    pts = points[mine]
    top = float(np.percentile(pts[:, 2], 98))
    rim = round_rim(pts, table, top, 0.2)
    assert rim is not None
    centre, radius = rim
    true_centre = truth.bounds.mean(axis=0)[:2]
    assert np.linalg.norm(centre - true_centre) < 0.01 and abs(radius - 0.5 * truth.extents[:2].mean()) < 0.012
    within = (np.linalg.norm(points[:, :2] - centre, axis=1) < radius) & (points[:, 2] > table) & (points[:, 2] < top) & ~mine
    bowl = complete_open_container(pts, centre, radius, table, top, camera_xy=view.camera[:2], seen_inside=points[within])
    assert bowl is not None and bowl.floor_z - table < 0.01  # the floor seen inside the rim, not the wall's foot
    assert bowl.visual.is_volume and bowl.visual.volume < 0.4 * bowl.outer.volume  # hollow
    pieces, _ = clip_pieces(bowl.pieces, view, tolerance)
    assert _covered_pixels(pieces, view, beside=mine.reshape(view.depth.shape)) <= 20  # off its outline
    x, y, z = drop_ball(pieces, np.array([centre[0] + 0.02, centre[1], top + 0.05]), floor_z=table)
    assert np.hypot(x - centre[0], y - centre[1]) < radius and table < z - 0.015 < bowl.floor_z + 0.01  # resting on the cavity floor


def test_an_object_in_a_mug_rests_on_its_cavity_floor_not_through_it_on_the_table() -> None:
    """rest_inside: an object seen inside the completed (hollow) scanned mug stops at its cavity
    floor, one lying across the rim at the rim; neither is carried down through it to the table."""
    from realsim.completion.stacking import rest_inside

    view, points, mine, truth, table, tolerance = _capture("025_mug")
    pts = points[mine]
    top = float(np.percentile(pts[:, 2], 98))
    centre, radius = round_rim(pts, table, top, 0.2) or (np.zeros(2), 0.0)
    within = (np.linalg.norm(points[:, :2] - centre, axis=1) < radius) & (points[:, 2] > table) & (points[:, 2] < top) & ~mine
    mug = complete_open_container(pts, centre, radius, table, top, camera_xy=view.camera[:2], seen_inside=points[within])
    assert mug is not None and mug.floor_z - table > 0.01
    grid = np.stack(np.meshgrid(np.linspace(-0.01, 0.01, 5), np.linspace(-0.01, 0.01, 5)), axis=-1).reshape(-1, 2)
    block = np.column_stack([centre + grid, np.full(len(grid), mug.floor_z + 0.02)])  # the seen top of a 2 cm block on the floor
    assert abs(rest_inside(mug.pieces, block, tolerance) - mug.floor_z) < 0.002  # (before: the table)
    across = np.column_stack([centre[0] + np.linspace(-1.3, 1.3, 40) * radius, np.full(40, centre[1]), np.full(40, top + 0.01)])
    assert abs(rest_inside(mug.pieces, across, tolerance) - top) < 0.003  # a stick lying across the rim
    assert rest_inside(mug.pieces, block + [3 * radius, 0.0, 0.0], tolerance) is None  # nothing of the mug under it


def test_the_free_space_cuts_keep_what_the_camera_saw_of_the_object() -> None:
    view, points, mine, truth, table, tolerance = _capture("003_cracker_box", seed=1)
    pts = points[mine]
    ray = pts.mean(axis=0) - view.camera
    side = np.cross(ray, [0.0, 0.0, 1.0])
    side *= 0.03 / np.linalg.norm(side)  # a wrong guess: the box 3 cm wider across the line of sight
    guess = complete_hull(np.vstack([pts, pts + side]), table, float(np.percentile(pts[:, 2], 98)))[0]
    seen = pts[:: max(1, len(pts) // 2000)]
    inward = seen + (tolerance + 0.0005) * (guess.centroid - seen) / np.linalg.norm(guess.centroid - seen, axis=1, keepdims=True)
    kept, _ = clip_pieces([guess], view, tolerance, seen=seen)
    assert np.mean(_inside(kept, inward)) >= 0.99  # no cut takes off more than the noise of a face the camera saw
    beside = mine.reshape(view.depth.shape)
    assert _covered_pixels(kept, view, beside=beside) <= 0.05 * _covered_pixels([guess], view, beside=beside)  # the guess is cut


def test_the_cut_search_skips_no_direction_that_could_win() -> None:
    """best_cut (which counts only the directions that may win) picks the cut an exhaustive search
    over every direction and every cut below each bad sample picks, on generated pieces."""
    from realsim.completion.cutsearch import MISS_WEIGHT, best_cut
    from realsim.completion.freespace import _directions

    rng = np.random.default_rng(3)
    for trial in range(20):
        centre = rng.normal(size=3) * 0.1
        inside = centre + rng.normal(size=(int(rng.integers(300, 2000)), 3)) * rng.uniform(0.01, 0.05, 3)
        bad = centre + rng.normal(size=(int(rng.integers(2, 200)), 3)) * 0.03 + rng.normal(size=3) * 0.02
        ray = rng.normal(size=3)
        normals = _directions(ray / np.linalg.norm(ray))
        samples = 1530
        n, c, cost = best_cut(inside, bad, normals, samples)
        pi, pb = inside @ normals.T, bad @ normals.T
        cuts = np.sort(pb, axis=0) - 1e-6 * np.maximum(np.ptp(pi, axis=0), 1e-9)
        every = 1.0 - (pi[:, None, :] <= cuts[None]).mean(axis=0) + MISS_WEIGHT * np.arange(len(bad))[:, None] / samples
        none = MISS_WEIGHT * len(bad) / samples
        if every.min() >= none:
            assert not np.isfinite(c) and cost == none
            continue
        k, j = np.unravel_index(int(np.argmin(every)), every.shape)
        assert np.allclose(n, normals[j]) and c == cuts[k, j] and abs(cost - every[k, j]) < 1e-12, trial
