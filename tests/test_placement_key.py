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


def _long_table(objects):
    from test_robot import _rect
    scene = table_scene(objects)
    scene.planes[1].rect_size = np.array([1.8, 0.7])
    scene.planes[1].polygon = _rect((0, 0), (1.8, 0.7))
    return compose_scene(scene)


def _reached(scene, pose) -> int:
    from realsim.composition.robot_placement import score_pose
    inputs = search_inputs(scene, scene.spec.compile(), PlacementParams())
    return score_pose(pose, inputs.rect[3], [np.array(t) for t in inputs.targets])[1]


def test_the_pose_reaches_objects_the_hand_cannot_hold_too():
    # a box to pick at one end, a crate too wide to hold (a place to put things on) toward the other:
    # a pose beside the middle reaches both, one at the near end only the box
    scene = _long_table([box_object(1, "obj1_box", (-0.35, 0.0), [0.05, 0.05, 0.08]),
                         box_object(2, "obj2_crate", (0.5, 0.05), [0.25, 0.25, 0.1])])
    assert _reached(scene, choose_robot_pose(scene, scene.spec.compile())) == 2


def test_no_pose_gives_up_an_object_the_hand_can_hold_for_others():
    # the box at one end and three crates at the other, too far apart for one pose: the box wins
    crates = [box_object(i, f"obj{i}_crate", (0.8, y), [0.2, 0.2, 0.1]) for i, y in ((2, -0.22), (3, 0.0), (4, 0.22))]
    scene = _long_table([box_object(1, "obj1_box", (-0.8, 0.0), [0.05, 0.05, 0.08]), *crates])
    pose = choose_robot_pose(scene, scene.spec.compile())
    from realsim.composition.robot_placement import score_pose
    box_top = np.array([-0.8, 0.0, 0.75 + 0.08 + 0.05])
    assert score_pose(pose, 0.75, [box_top])[1] == 1
