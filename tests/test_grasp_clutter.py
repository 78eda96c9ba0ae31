"""Grasping in clutter: hand poses whose hand or open fingers reach into a neighbour are dropped
before any IK (:mod:`realsim.robot.hand_hulls`), and a grasp with no clear pose fails without moving."""

from __future__ import annotations

import numpy as np

from realsim.robot.grasps import rotate_about
from realsim.robot.model import HOME_ARM
from tests.test_grasp_neighbour import _robot, can
from tests.test_robot import box_object

WALL = (0.08, 0.16, 0.24)  # two boxes 8 cm thick, 16 cm long, taller than the hand can reach past


def _in_gap(sides: tuple[float, float]) -> list:
    """The can with a tall box touching it on each of ``sides`` (world yaw, degrees)."""
    small = can((-0.05, 0.1))
    out = [small]
    for j, side in enumerate(sides):
        a = np.radians(side)
        xy = small.position[:2] + np.array([np.cos(a), np.sin(a)]) * (0.034 + WALL[0] / 2 + 0.001)
        out.append(box_object(2 + j, f"tall{j}", xy, WALL, mass=0.4, yaw=a))
    return out


def test_a_can_in_a_gap_narrower_than_the_open_hand_is_refused_without_moving() -> None:
    robot = _robot(_in_gap((90.0, 270.0)))  # 70 mm between the boxes: no finger fits beside the can, the hand not between them
    t0, q0 = robot.data.time, robot.data.ctrl[robot.act].copy()
    solved: list[int] = []
    solve = robot._clear_posture
    robot._clear_posture = lambda *a: solved.append(1) or solve(*a)  # type: ignore[method-assign]
    res = robot.grasp("small")
    assert not solved  # every pose dropped by the hull test, none solved for
    assert not res.success
    assert "tall0" in res.reason and "tall1" in res.reason
    assert robot.data.time == t0  # no attempt found a plan: nothing moved, no sim time spent resetting
    assert np.array_equal(robot.data.ctrl[robot.act], q0)


def test_the_hull_test_drops_only_poses_the_full_check_refuses() -> None:
    robot = _robot(_in_gap((0.0, 90.0)))  # a corner
    others = robot._neighbour_clouds("small")
    dropped = kept = 0
    for c in robot._grasp_candidates("small")[:8]:
        for lean in (0.0, 0.6):
            r = rotate_about(c.rot[:, 1], lean) @ c.rot
            if not robot._hand_hulls.touched(c.pos, r, others):
                kept += 1
                continue
            dropped += 1
            pre = robot._clear_posture(c.pos - r[:, 2] * robot.params.pregrasp, r, np.array(HOME_ARM), set(), set())
            grasp = pre and robot._clear_posture(c.pos, r, pre.q, {"small"}, set())
            assert grasp is None  # what the hulls drop, the IK and collision check refuse too
    assert dropped


def test_a_can_in_a_corner_is_grasped_by_a_hand_leaning_into_it() -> None:
    robot = _robot(_in_gap((0.0, 90.0)))  # boxes on its far and left sides: only a steep lean from the open corner clears them
    before = {n: robot.object_pose(n)[0].copy() for n in ("tall0", "tall1")}
    res = robot.grasp("small")
    assert res.success, res.reason
    assert max(float(np.linalg.norm(robot.object_pose(n)[0] - p)) for n, p in before.items()) < 0.005
