"""The robot pose search is keyed by exactly what it reads: a visual-only change keeps the key and
the cached pose, a moved object or another support rectangle changes it."""

from __future__ import annotations

import mujoco
import numpy as np
from test_robot import box_object, table_scene

from realsim.composition.compose import compose_scene
from realsim.composition.robot_mount import RobotStageParams, _placement_key, robot_scene
from realsim.composition.robot_placement import PlacementParams, choose_robot_pose, search_inputs


def _scene(x: float = 0.1):
    return compose_scene(table_scene([box_object(1, "obj1_box", (x, 0.05), [0.05, 0.05, 0.1])]))


def _key(scene) -> str:
    return _placement_key(scene, PlacementParams(), search_inputs(scene, scene.spec.compile(), PlacementParams()))


def test_key_follows_what_the_search_reads():
    scene = _scene()
    key = _key(scene)
    scene.spec.worldbody.add_geom(name="poster", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.1, 0.01, 0.1], pos=[0, 1, 1],
                                  group=2, contype=0, conaffinity=0)
    assert _key(scene) == key  # a visual-only geom: the search reads nothing of it
    assert _key(_scene(x=0.12)) != key
    wider = _scene()
    wider.planes[1].rect_size = np.array([1.1, 0.7])
    assert _key(wider) != key


def test_searched_pose_equals_the_direct_search_and_is_reused(monkeypatch):
    scene = _scene()
    direct = choose_robot_pose(scene, scene.spec.compile())
    robot_scene(scene, RobotStageParams())
    assert tuple(scene.robot["base_pose_xy_yaw"]) == direct
    again = _scene()
    again.spec.worldbody.add_geom(name="poster", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.1, 0.01, 0.1], pos=[0, 1, 1],
                                  group=2, contype=0, conaffinity=0)
    def no_search(*args, **kwargs):
        raise AssertionError("the pose was searched again")

    monkeypatch.setattr("realsim.composition.robot_mount.add_robot", no_search)
    robot_scene(again, RobotStageParams())
    assert again.robot["base_pose_xy_yaw"] == scene.robot["base_pose_xy_yaw"]
