"""Gravity and support height from one organized view that shows no floor (generated ground truth).

A counter or table against a wall, seen by a hand-held camera looking 30-60 degrees down and
rolled up to 15 degrees: the wall facing the camera can be as large in the picture and as
tilted from the picture's up as the support top, but it faces away from the picture's up, so the
scene is levelled on the top. Its height above an assumed floor is unknown; its height below the
camera is measured.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from realsim.perception.capture import load_capture
from realsim.perception.pcd_io import write_pcd
from realsim.perception.planes import detect_planes
from realsim.scene import Scene
from realsim.synth import SceneSpec, SynthScene, kinect_view, make_scene
from realsim.synth.camera import Camera, view_cloud
from realsim.synth.exports import without_floor
from realsim.synth.scene import ycb_root

pytestmark = pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")
CASES = [("counter", 40), ("counter", 41), ("counter", 42), ("table", 43), ("table", 44), ("counter", 45)]


def _levelled(scene: SynthScene, cam: Camera, rng: np.random.Generator, seed: int, tmp_path: Path) -> tuple[Scene, float]:
    """The view rendered, loaded and levelled, and the angle (degrees) between its up and the true up."""
    points, frame = view_cloud(scene, cam, rng)
    write_pcd(tmp_path / "view.pcd", points, grid_shape=frame.depth.shape)
    converted = detect_planes(load_capture(tmp_path / "view.pcd", seed=seed))
    to_world = converted.capture.input_to_world
    up = to_world[2, :3] / np.linalg.norm(to_world[2, :3])  # the converter's up in the optical frame
    return converted, math.degrees(math.acos(min(1.0, float(up @ cam.pose[2, :3]))))


@pytest.mark.parametrize(("layout", "seed"), CASES)
def test_floorless_view_is_levelled_on_its_support(layout: str, seed: int, tmp_path: Path) -> None:
    rng = np.random.default_rng(seed)
    scene = without_floor(make_scene(SceneSpec(layout=layout, seed=seed, n_objects=3, wall=True)))
    cam = kinect_view(scene, rng, pitch_deg=(30.0, 60.0), roll_deg=float(rng.uniform(-15.0, 15.0)))
    converted, gravity_deg = _levelled(scene, cam, rng, seed, tmp_path)

    to_world = converted.capture.input_to_world
    assert gravity_deg < 0.2
    assert not any(p.kind == "floor" and p.observed for p in converted.planes)
    assert any(w.startswith("no floor in view") for w in converted.warnings)
    top = max((p for p in converted.planes if p.observed), key=lambda p: p.inlier_count)
    below_camera = to_world[2, 3] - top.height  # the camera's height above the top, converted
    assert abs(below_camera - (cam.pose[2, 3] - scene.primary_support().height)) < 0.003


@pytest.mark.parametrize("seed", [46, 47])
def test_upside_down_view_without_a_wall_is_levelled_on_its_support(seed: int, tmp_path: Path) -> None:
    """A picture stored upside down (a PCL tutorial scan is): no large plane faces its up, so the
    support is the large plane facing its down."""
    rng = np.random.default_rng(seed)
    scene = make_scene(SceneSpec(layout="table", seed=seed, n_objects=3))
    cam = kinect_view(scene, rng, roll_deg=180.0 + float(rng.uniform(-15.0, 15.0)))
    converted, gravity_deg = _levelled(scene, cam, rng, seed, tmp_path)
    assert gravity_deg < 0.2
    heights = sorted(p.height for p in converted.planes if p.observed)
    assert abs(heights[-1] - scene.primary_support().height) < 0.003  # the floor is in view: heights are absolute


@pytest.mark.parametrize(("layout", "seed", "pitch"), [("table", 48, 77.0), ("counter", 49, 83.0), ("table", 50, 89.0)])
def test_overhead_view_is_levelled_on_its_support(layout: str, seed: int, pitch: float, tmp_path: Path) -> None:
    """A camera looking (nearly) straight down on a counter against a wall: the top is tilted past
    the picture's up, faces back along the optical axis and is larger than any thing's top."""
    rng = np.random.default_rng(seed)
    scene = without_floor(make_scene(SceneSpec(layout=layout, seed=seed, n_objects=3, wall=True)))
    cam = kinect_view(scene, rng, pitch_deg=(pitch, pitch), roll_deg=float(rng.uniform(-15.0, 15.0)))
    converted, gravity_deg = _levelled(scene, cam, rng, seed, tmp_path)
    to_world = converted.capture.input_to_world
    assert gravity_deg < 0.2
    top = max((p for p in converted.planes if p.observed), key=lambda p: p.inlier_count)
    assert abs(to_world[2, 3] - top.height - (cam.pose[2, 3] - scene.primary_support().height)) < 0.003
