"""Up-axis detection of unorganized captures: the side things stand on is up, whichever axis
the file used and even when the scanned floor is a closed slab (its underside as large as its top)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from realsim.perception.capture import load_capture, sample_mesh
from realsim.perception.resolution import detect_up
from realsim.synth import SceneSpec, make_scene, sample_cloud, write_mesh
from realsim.synth.exports import up_matrix
from realsim.synth.scene import ycb_root

pytestmark = pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")
UP_AXES = ("+x", "-x", "+y", "-y", "+z", "-z")


@pytest.fixture(scope="module")
def floor_scene():
    return make_scene(SceneSpec(layout="floor", objects=None, seed=80))


def assert_up_found(scene, file_name: str, up: str) -> None:
    """The scene's closed mesh and a scan of it, turned so ``up`` is up: ``detect_up`` names ``up``."""
    mesh_points, _, _ = sample_mesh(scene.mesh, 60_000, 0, Path(file_name))
    scan_points, _, _ = sample_cloud(scene, 60_000)
    for points in (mesh_points, scan_points):
        assert detect_up(points @ up_matrix(up).T, False, "ply", 0) == up


@pytest.mark.parametrize("up", UP_AXES)
def test_up_of_a_closed_floor_slab_mesh_and_of_a_scan(floor_scene, up: str) -> None:
    assert_up_found(floor_scene, "room.ply", up)


def test_floor_mesh_converts_right_side_up(floor_scene, tmp_path: Path) -> None:
    write_mesh(floor_scene, tmp_path / "room.ply", units="m", up="+z")
    scene = load_capture(tmp_path / "room.ply")
    assert scene.capture.up == "+z" and scene.capture.up_detected
    world_z = scene.points @ scene.capture.input_to_world[2, :3] + scene.capture.input_to_world[2, 3]
    # the floor's top, not its underside, is at z = 0 once the planes stage levels it: here the
    # transform only rotates, so the objects (up to 25 cm tall) lie above the slab
    assert np.percentile(world_z, 99.9) > 0.1 and np.percentile(world_z, 0.1) > -0.06


@pytest.fixture(scope="module")
def floorless_counter():
    from realsim.synth.exports import without_floor

    return without_floor(make_scene(SceneSpec(layout="counter", objects=None, seed=85)))


@pytest.mark.parametrize("up", UP_AXES)
def test_up_of_a_counter_under_a_larger_wall_without_floor(floorless_counter, up: str) -> None:
    """The wall is the largest plane; the objects rest on the counter, so its normal is up."""
    assert_up_found(floorless_counter, "counter.obj", up)


def test_a_wall_with_nothing_resting_on_it_gives_no_resting_vote() -> None:
    """Two perpendicular planes and no body: the vote abstains (the dominant-plane rule decides)."""
    from realsim.perception.up_axis import resting_up

    rng = np.random.default_rng(3)
    wall = np.column_stack([rng.uniform(-1, 1, 20_000), np.zeros(20_000), rng.uniform(0, 1.5, 20_000)])
    top = np.column_stack([rng.uniform(-0.8, 0.8, 8_000), rng.uniform(-0.6, 0, 8_000), np.full(8_000, 0.9)])
    assert resting_up(np.vstack([wall, top]), 0.02, np.random.default_rng(0)) is None
    box = np.column_stack([rng.uniform(-0.05, 0.05, 3_000), rng.uniform(-0.35, -0.25, 3_000), rng.uniform(0.9, 1.1, 3_000)])
    assert resting_up(np.vstack([wall, top, box]), 0.02, np.random.default_rng(0)) == "+z"
