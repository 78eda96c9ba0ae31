"""The Panda's meshes compiled by a thread begun after load: the robot stage's compile then finds
every one of them in MuJoCo's asset cache (nothing processed again), and its model is unchanged."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from realsim.composition import robot_ahead, robot_placement
from realsim.composition.compose import ComposeParams, new_spec
from realsim.pipeline import BEGUN_AFTER
from realsim.robot.model import attach_robot


def _scene_with_robot() -> mujoco.MjModel:
    """A table-height box and the Panda attached as the robot stage attaches it: the compiled model."""
    spec = new_spec(ComposeParams())
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.4, 0.3, 0.02], pos=[0.0, 0.0, 0.7])
    return attach_robot(spec, (-0.6, 0.0, 0.0), base_z=0.0, pedestal_height=0.7).model


def _cached_bytes() -> int:
    return int(mujoco.mj_getCacheSize(mujoco.mj_getCache()))


def test_begun_thread_caches_what_the_robot_stage_compiles(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    mujoco.mj_clearCache(mujoco.mj_getCache())
    robot_placement.bare_panda.cache_clear()
    robot_placement._scoring_ik.cache_clear()
    robot_ahead.begin()
    robot_ahead.finish()
    warmed = _cached_bytes()
    assert warmed > 0 and not robot_ahead._begun
    assert robot_placement._scoring_ik.cache_info().currsize == 1  # the pose search's IK is built too
    model = _scene_with_robot()
    assert _cached_bytes() == warmed  # every Panda mesh came from the cache
    mujoco.mj_clearCache(mujoco.mj_getCache())
    cold = _scene_with_robot()  # processed here instead: the same model
    assert _cached_bytes() == warmed
    assert model.nmesh == cold.nmesh > 0
    assert np.array_equal(model.mesh_vert, cold.mesh_vert) and np.array_equal(model.mesh_face, cold.mesh_face)
    assert np.array_equal(model.geom_size, cold.geom_size) and np.array_equal(model.body_inertia, cold.body_inertia)


@pytest.mark.parametrize(("workers", "enabled"), [("1", True), ("2", False)])
def test_no_thread_without_a_second_core_or_a_robot(monkeypatch: pytest.MonkeyPatch, workers: str, enabled: bool) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", workers)
    robot_ahead.begin(enabled)
    assert not robot_ahead._begun


def test_begun_after_load_for_the_robot_stage() -> None:
    later, _ = BEGUN_AFTER["load"]
    assert later == "robot"


def test_a_failed_conversion_leaves_no_thread_running(monkeypatch: pytest.MonkeyPatch) -> None:
    import threading
    from dataclasses import replace

    from conftest import DATA
    from realsim.pipeline import run_pipeline
    from realsim.stages import STAGES

    monkeypatch.setenv("REALSIM_WORKERS", "2")
    release = threading.Event()
    monkeypatch.setattr(robot_ahead, "_compile_panda", lambda *_: release.wait(5.0))  # still compiling when planes fails

    def fail(scene, params):
        release.set()
        raise RuntimeError("planes failed")

    monkeypatch.setitem(STAGES, "planes", replace(STAGES["planes"], run=fail))
    with pytest.raises(RuntimeError, match="planes failed"):
        run_pipeline(DATA / "pcl_scenes" / "mOSD" / "test0.pcd")
    assert not robot_ahead._begun  # joined before the error left the conversion
