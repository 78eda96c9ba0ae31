"""Gravity does not depend on how a capture was held (generated ground truth, realsim.synth).

A counter against a wall with no floor in view, written as an unorganized cloud turned 40 degrees
off its file's axes (the wall's normal then lies nearer the file's +z than in an upright file), and
as a single camera view stored upside down: both are levelled on the counter, the plane the
objects rest on, never on the wall, and every object is found.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from realsim.metrics import matched_iou
from realsim.perception.pcd_io import write_pcd
from realsim.pipeline import run_pipeline
from realsim.scene import Scene
from realsim.synth import SceneSpec, SynthScene, kinect_view, make_scene
from realsim.synth.camera import view_cloud
from realsim.synth.exports import without_floor, write_cloud
from realsim.synth.forms import sample_cloud
from realsim.synth.scene import ycb_root

pytestmark = pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")


def _detect(path: Path, tmp_path: Path) -> Scene:
    """Load, level and segment a capture file."""
    pipeline = tmp_path / "detect.yaml"
    pipeline.write_text("name: detect\nstages:\n  - load\n  - planes\n  - segment\n")
    return run_pipeline(path, pipeline=pipeline)


def _check(gt: SynthScene, scene: Scene, to_world: np.ndarray, labels: np.ndarray) -> None:
    """Up within 0.5 degrees of the true up, the counter top within 5 mm, every object found."""
    m = scene.capture.input_to_world
    up, true_up = m[2, :3] / np.linalg.norm(m[2, :3]), to_world[2, :3] / np.linalg.norm(to_world[2, :3])
    assert math.degrees(math.acos(min(1.0, float(up @ true_up)))) < 0.5
    to_true = to_world @ np.linalg.inv(m)
    heights = [(to_true @ np.r_[p.rect_center, p.height, 1.0])[2] for p in scene.planes if p.observed]
    assert min(abs(h - gt.primary_support().height) for h in heights) < 0.005
    assert scene.labels is not None
    ious, _ = matched_iou(scene.labels, labels)
    assert len(ious) == len(gt.objects) and (ious >= 0.5).all(), ious


@pytest.mark.parametrize(("layout", "seed"), [("counter", 86), ("table", 87)])
def test_floorless_cloud_turned_40_degrees_is_levelled_on_its_support(layout: str, seed: int, tmp_path: Path) -> None:
    gt = without_floor(make_scene(SceneSpec(layout=layout, seed=seed, n_objects=3, wall=True)))
    points, colours, ids = sample_cloud(gt, 200_000, seed)
    rot = Rotation.from_rotvec(math.radians(40.0) * np.array([1.0, 0.3, 0.0]) / math.hypot(1.0, 0.3)).as_matrix()
    write_cloud(tmp_path / "scan.ply", points @ rot.T, colours, "ply")
    to_world = np.eye(4)
    to_world[:3, :3] = rot.T
    _check(gt, _detect(tmp_path / "scan.ply", tmp_path), to_world, ids)


@pytest.mark.parametrize(("layout", "seed", "roll"), [("counter", 88, 180.0), ("table", 89, 170.0), ("counter", 90, -135.0)])
def test_upside_down_view_with_a_wall_is_levelled_on_its_support(layout: str, seed: int, roll: float, tmp_path: Path) -> None:
    rng = np.random.default_rng(seed)
    gt = without_floor(make_scene(SceneSpec(layout=layout, seed=seed, n_objects=3, wall=True)))
    cam = kinect_view(gt, rng, pitch_deg=(30.0, 60.0), roll_deg=roll)
    points, frame = view_cloud(gt, cam, rng)
    write_pcd(tmp_path / "view.pcd", points, colors=frame.color.reshape(-1, 3), grid_shape=frame.depth.shape)
    labels = np.where(frame.part.reshape(-1) >= 10, frame.part.reshape(-1) // 10, 0)  # mOSD convention: objects 10 * id
    _check(gt, _detect(tmp_path / "view.pcd", tmp_path), cam.pose, labels)
