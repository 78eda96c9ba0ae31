"""Motion that avoids what it should not touch: collision-aware IK, planned transits, the tall-box push."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from test_robot import box_object, build, loaded

from realsim.robot import Robot
from realsim.robot.grasps import frame_from, rotate_about
from realsim.robot.motion import PathBlocked
from realsim.robot.result import PlanFailure
from realsim.robot.transit import TransitParams, plan_joint_path
from realsim.scene import Scene

TALL = (0.07, 0.16, 0.22)  # a cereal-box-like box: 7 cm deep along x, 22 cm tall
TCP_Z = 0.785  # push contact height over the 0.75 m table


@pytest.fixture(scope="module")
def tall_scene() -> Scene:
    return build([box_object(1, "tall_box", (0.05, 0.0), TALL, mass=0.3)])


def _tilt_deg(data: mujoco.MjData, body: int) -> float:
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, data.xquat[body])
    return float(np.degrees(np.arccos(np.clip(mat[8], -1.0, 1.0))))


@pytest.mark.parametrize("direction", [(1.0, 0.0), (-1.0, 0.0)])
def test_tall_box_pushed_along_its_thin_side_does_not_tip(tall_scene: Scene, direction) -> None:
    model, data = loaded(tall_scene)
    robot = Robot(model, data)
    b = model.body("tall_box").id
    start = data.xpos[b].copy()
    res = robot.push("tall_box", direction, 0.05)
    moved = data.xpos[b] - start
    assert res.success, res.reason
    assert 0.03 < float(moved[:2] @ np.asarray(direction)) < 0.08
    assert _tilt_deg(data, b) < 3.0  # upright: the forearm never caught the top


def test_collision_ik_stops_short_of_the_box_and_reaches_past_it(tall_scene: Scene) -> None:
    model, data = loaded(tall_scene)
    robot = Robot(model, data)
    home = np.array(robot.ik.home)

    def hand_rot(tilt: float) -> np.ndarray:  # fingertips leading toward +x
        return rotate_about(np.array([0.0, -1.0, 0.0]), tilt) @ frame_from(np.array([0, 0, -1.0]), np.array([0, 1.0, 0]))

    at_face = np.array([0.005, 0.0, TCP_Z])
    plain = robot._ik(at_face, hand_rot(0.4), home)
    assert plain.converged and robot.geometry.robot_hits(robot.qadr, plain.q, (), {"tall_box"}, robot.hand_bodies) == {"tall_box"}
    held_off = robot.avoid_ik.solve(data.qpos.copy(), at_face, hand_rot(0.4), home, hand_may_touch={"tall_box"})
    assert not held_off.converged  # the wrist would have to pass through the box's face
    assert not robot.geometry.robot_hits(robot.qadr, held_off.q, (), {"tall_box"}, robot.hand_bodies)
    leaning = robot.avoid_ik.solve(data.qpos.copy(), at_face, hand_rot(0.8), home, hand_may_touch={"tall_box"})
    assert leaning.converged and leaning.pos_error < 0.002
    assert not robot.geometry.robot_hits(robot.qadr, leaning.q, (), {"tall_box"}, robot.hand_bodies)


def test_joint_planner_goes_around_a_blocked_region_deterministically() -> None:
    lower, upper = -np.ones(7) * 2.0, np.ones(7) * 2.0
    q0, q1 = np.full(7, -1.0), np.full(7, 1.0)

    def valid(q: np.ndarray) -> bool:  # a slab across the straight line, open only where q[0] > 0.5
        return not (abs(q[1]) < 0.3 and q[0] < 0.5)

    path = plan_joint_path(q0, q1, lower, upper, valid, seed=3)
    assert np.allclose(path[-1], q1)
    pts = [q0, *path]
    for a, b in zip(pts[:-1], pts[1:]):
        assert all(valid(a + f * (b - a)) for f in np.linspace(0, 1, 200))
    assert all(np.allclose(p, r) for p, r in zip(path, plan_joint_path(q0, q1, lower, upper, valid, seed=3)))
    with pytest.raises(PlanFailure, match="no collision-free path"):
        plan_joint_path(q0, q1, lower, upper, lambda q: not (abs(q[1]) < 0.3), seed=3, params=TransitParams(max_checks=300))


def _facing(d: np.ndarray, tilt: float) -> np.ndarray:
    """A closed hand leaning back by ``tilt`` with its fingertips leading along ``d``."""
    return rotate_about(np.array([d[1], -d[0], 0.0]), tilt) @ frame_from(np.array([0, 0, -1.0]), np.array([-d[1], d[0], 0.0]))


def test_planned_moves_keep_the_arm_off_the_box(tall_scene: Scene) -> None:
    model, data = loaded(tall_scene)
    robot = Robot(model, data)
    b = model.body("tall_box").id
    start = data.xpos[b].copy()
    near = np.array([-0.02, 0.0, TCP_Z])  # low beside the tall box
    robot._plan_transit(near, _facing(np.array([1.0, 0, 0]), 0.8), set())
    assert np.linalg.norm(robot.tcp_pose()[0] - near) < 0.01
    far = np.array([0.12, 0.0, TCP_Z])  # low on its other side: straight across in joint space runs through it
    q_far = robot._ik_clear(far, _facing(np.array([-1.0, 0, 0]), 0.8), data.ctrl[robot.act].copy())
    assert q_far.converged
    q0 = data.ctrl[robot.act].copy()
    with pytest.raises(PathBlocked):
        robot._check_clear([q0 + f * (q_far.q - q0) for f in np.linspace(0.02, 1.0, 50)])
    robot._move_joints(q_far.q)
    assert np.linalg.norm(robot.tcp_pose()[0] - far) < 0.01
    assert np.linalg.norm(data.xpos[b] - start) < 0.002  # never touched on the way
    with pytest.raises(PathBlocked):  # a straight line into the box, kept clear of everything
        robot._straight(far - np.array([0.05, 0.0, 0.0]), clear_but=set())
    assert np.linalg.norm(data.xpos[b] - start) < 0.002


def test_clearance_gaps_are_mujocos_own_distances(tall_scene: Scene) -> None:
    """The arm-object gaps a planned transit keeps are MuJoCo's geom distances (ground truth from
    mj_geomDistance over every arm and box geom pair), nearer as the hand nears the box's face."""
    model, data = loaded(tall_scene)
    robot = Robot(model, data)
    box = [g for g in range(model.ngeom) if model.geom_bodyid[g] == model.body("tall_box").id and model.geom_contype[g]]
    arm = [g for g in range(model.ngeom) if int(model.geom_bodyid[g]) in robot.geometry.robot_bodies
           and (model.geom_contype[g] or model.geom_conaffinity[g])]
    reach = robot.transit_params.clearance
    scratch = mujoco.MjData(model)
    seen = []
    for x in (-0.06, -0.03, -0.02, -0.012):  # the box's face is at x = 0.015
        q = robot._ik(np.array([x, 0.0, TCP_Z]), _facing(np.array([1.0, 0, 0]), 0.4), np.array(robot.ik.home)).q
        scratch.qpos[:] = data.qpos
        scratch.qpos[robot.qadr] = q
        mujoco.mj_kinematics(model, scratch)
        truth = min(mujoco.mj_geomDistance(model, scratch, a, b, 0.2, None) for a in arm for b in box)
        gap = robot.gap_check.gaps(data.qpos, robot.qadr, q).get("tall_box", np.inf)
        assert (gap == np.inf and truth >= reach - 1e-4) or abs(gap - truth) < 1e-3, (x, gap, truth)
        seen.append(min(gap, truth))
    assert seen == sorted(seen, reverse=True) and seen[-1] < reach  # nearer, and the last within reach


def test_required_gaps_relax_only_to_an_end_posture_nearer_than_the_clearance() -> None:
    from realsim.robot.clearance import keeps, required_gaps

    need = required_gaps([{"box": 0.004, "can": 0.05}, {"bowl": -0.001}], 0.015)
    assert need == {"box": 0.004, "can": 0.015, "bowl": 0.0}
    assert keeps({"box": 0.005, "mug": 0.02}, need, 0.015)
    assert not keeps({"mug": 0.01}, need, 0.015)  # an object the ends keep clear of: the full clearance
    assert not keeps({"box": 0.002}, need, 0.015)
