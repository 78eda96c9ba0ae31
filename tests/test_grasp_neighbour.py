"""Grasping an object that stands against a taller neighbour: the hand leans away from it, and the
transit ends in the pre-grasp posture found clear."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from realsim.robot import Robot
from realsim.scene import SceneObject
from tests.test_robot import TABLE_Z, box_object, build, loaded

BASE = (-0.62, 0.0, 0.0)  # the robot faces +x
TALL = (0.11, 0.19, 0.27)  # a cereal box: 11 cm deep along the side it stands on


def can(xy: tuple[float, float], r: float = 0.034, h: float = 0.125, mass: float = 0.35) -> SceneObject:
    """A soup can standing at ``xy``."""
    mesh = trimesh.creation.cylinder(radius=r, height=h, sections=32)
    mesh.apply_translation([0, 0, h / 2])
    inertia = np.diag(mass * np.array([(3 * r * r + h * h) / 12, (3 * r * r + h * h) / 12, r * r / 2]))
    return SceneObject(id=1, name="small", label="can", position=np.array([xy[0], xy[1], TABLE_Z]), quat=np.array([1.0, 0, 0, 0]),
                       size=np.array([2 * r, 2 * r, h]), support_id=1, visual=mesh, collision=[mesh], mass=mass,
                       com=np.array([0, 0, h / 2]), inertia=inertia)


def against(small: SceneObject, half: float, side_deg: float) -> list[SceneObject]:
    """``small`` with the tall box touching it on the side ``side_deg`` (world yaw) away, its face turned to it."""
    a = np.radians(side_deg)
    d = np.array([np.cos(a), np.sin(a)])
    xy = small.position[:2] + d * (half + TALL[0] / 2 + 0.001)
    return [small, box_object(2, "tall", xy, TALL, mass=0.4, yaw=a)]


def _robot(objects: list[SceneObject]) -> Robot:
    model, data = loaded(build(objects, pose=BASE), "initial")
    return Robot(model, data)


@pytest.fixture(scope="module")
def can_beside() -> Robot:
    """The can with the tall box on its left (as the robot sees it)."""
    return _robot(against(can((-0.05, 0.0)), 0.034, 90.0))


def test_an_upright_hand_that_would_touch_the_neighbour_is_not_reachable(can_beside: Robot) -> None:
    robot = can_beside
    cands = robot._grasp_candidates("small")
    blockers: set[str] = set()
    assert not robot._reachable("small", cands, 0.0, 0.0, blockers)  # every upright pinch puts the hand or wrist in the box
    assert blockers == {"tall"}
    leaning = [robot._reachable("small", cands, lean, 0.0, set()) for lean in robot.params.pick.reach_tilts[1:]]
    assert any(leaning)
    for found in leaning:
        for _, q_pre, res in found:
            assert not robot._touches(q_pre) and not robot._touches(res.q, {"small"})


def test_a_can_against_a_tall_box_is_grasped_without_shoving_it(can_beside: Robot) -> None:
    robot = can_beside
    tall = robot.object_pose("tall")[0].copy()
    res = robot.grasp("small")
    assert res.success, res.reason
    assert robot.holding("small")
    assert np.linalg.norm(robot.object_pose("tall")[0] - tall) < 0.01


def test_a_small_box_with_a_tall_box_behind_it_is_grasped() -> None:
    """The straight transit lines over the tall box end out of reach; the transit is planned into the clear pre-grasp posture."""
    robot = _robot(against(box_object(1, "small", (-0.05, 0.0), (0.05, 0.05, 0.11), mass=0.2), 0.025, 0.0))
    tall = robot.object_pose("tall")[0].copy()
    res = robot.grasp("small")
    assert res.success, res.reason
    assert np.linalg.norm(robot.object_pose("tall")[0] - tall) < 0.01
