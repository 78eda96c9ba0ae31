"""Handle grasps: thin parts found from geometry, the pinch checks, the statics of a sideways
hand, and a lidded mug (too wide to pinch, no rim) lifted and carried by its handle in MuJoCo."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from realsim.procedural.parts import Shape, arc, cylinder, to_trimesh, tube, vessel
from realsim.robot import Robot
from realsim.robot.arm import QUINTIC_ACCEL
from realsim.robot.grasps import GraspCandidate, frame_from, grasp_candidates, twist_check
from realsim.robot.handles import handle_candidates, pinch_fit
from realsim.robot.model import HOME_ARM
from realsim.scene import SceneObject
from tests.test_robot import TABLE_Z, build, loaded

BASE = np.array([0.0, -0.6])


def lidded_mug(h: float = 0.10, dia: float = 0.09) -> Shape:
    """A closed 90 mm canister with a loop handle on +x: nothing to pinch but the handle."""
    r = dia / 2
    body = vessel([(r, 0.0), (r, h)], wall=0.005, bottom=0.008, segments=1, closed_top=0.006)
    path = arc((r - 0.002, 0.0, h * 0.52), h * 0.28, -75, 75, "xz", 7)
    path = np.vstack([[r - 0.004, 0.0, path[0, 2]], path, [r - 0.004, 0.0, path[-1, 2]]])
    return body + tube(path, 0.005, 8)


def _surface(shape: Shape, count: int = 6000) -> tuple[np.ndarray, np.ndarray]:
    mesh = to_trimesh(shape.solid)
    pts, faces = trimesh.sample.sample_surface(mesh, count, seed=0)
    return pts, mesh.face_normals[faces]


def test_the_handle_is_found_from_geometry_and_nothing_else_is() -> None:
    pts, nrm = _surface(lidded_mug())
    assert grasp_candidates(pts, 0.0, BASE, normals=nrm) == []  # 90 mm across, closed: no body pinch
    cands = handle_candidates(pts, nrm, 0.0, BASE)
    assert cands
    for c in cands:  # every pinch is on the loop (outside the body), across its 10 mm tube
        assert np.linalg.norm(c.pos[:2]) > 0.045 and abs(c.pos[1]) < 0.01, c.pos
        assert c.width < 0.02
    for closed in (cylinder(0.12, 0.04), cylinder(0.05, 0.09)):  # no thin part: no handle
        p, n = _surface(Shape(closed.solid, closed.hulls))
        assert handle_candidates(p, n, 0.0, BASE) == []


def test_a_pinch_that_would_put_the_hand_through_the_table_or_the_body_does_not_fit() -> None:
    pts, nrm = _surface(lidded_mug())
    top = frame_from(np.array([0.0, 0.0, -1.0]), np.array([0.0, 1.0, 0.0]))
    handle_top = np.array([0.062, 0.0, 0.071])  # the top of the loop
    fit = pinch_fit(pts, nrm, handle_top, top, 0.0)
    assert fit is not None and fit[1] < 0.015
    assert pinch_fit(pts, nrm, handle_top, top, 0.08) is None  # the fingertips would be under the support
    radial = frame_from(np.array([0.0, 0.0, -1.0]), np.array([1.0, 0.0, 0.0]))
    assert pinch_fit(pts, nrm, handle_top, radial, 0.0) is None  # the inner finger would hit the body


def test_statics_of_a_sideways_hand_count_the_turn_across_the_pads() -> None:
    """Closing vertically from the side with the weight hanging off beside the hand: the torque is
    about the approach axis, resisted only by the fingers' width."""
    side = GraspCandidate("handle", np.zeros(3), frame_from(np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])), 0.01, 1.0)
    ok, need, can = twist_check(side, np.array([0.0, 0.1, 0.0]), 1.0, 0.8, 70.0)
    assert not ok and need == pytest.approx(0.981, rel=0.01) and can < need
    assert twist_check(side, np.array([0.0, 0.01, 0.0]), 1.0, 0.8, 70.0)[0]


def test_a_lidded_mug_is_lifted_and_carried_by_its_handle() -> None:
    shape = lidded_mug()
    mesh = to_trimesh(shape.solid)
    mass = 0.12  # a mug's weight: its 6 cm lever is held with the safety the carry needs
    obj = SceneObject(id=1, name="lidded_mug", label="mug", position=np.array([0.1, 0.05, TABLE_Z]), quat=np.array([1.0, 0, 0, 0]),
                      size=mesh.extents, support_id=1, visual=mesh, collision=[trimesh.convex.convex_hull(np.asarray(h)) for h in shape.hulls],
                      mass=mass, com=np.asarray(mesh.center_mass), inertia=np.asarray(mesh.moment_inertia) * mass / mesh.mass)
    model, data = loaded(build([obj]))
    robot = Robot(model, data)
    ok, why = robot.graspability("lidded_mug")
    assert ok, why
    res = robot.grasp("lidded_mug")
    assert res.success, res.reason
    assert res.values["kind"] == "handle" and res.values["lifted"] > 0.04
    assert model.opt.noslip_iterations == robot.params.arm.hold_noslip  # held: static friction, no creep
    body = model.body("lidded_mug").id
    before = data.site_xmat[robot.tcp].reshape(3, 3).T @ data.xmat[body].reshape(3, 3)
    robot._wait(1.0)  # the hand still: the weight's torque on the pinch must not turn the mug in the fingers
    after = data.site_xmat[robot.tcp].reshape(3, 3).T @ data.xmat[body].reshape(3, 3)
    assert np.degrees(np.arccos(np.clip((np.trace(before.T @ after) - 1) / 2, -1, 1))) < 0.5
    lo, hi = robot.params.pick.carry_accel  # carried no faster than the handle pinch holds: the tcp's peak acceleration within the bounds
    path = np.array([data.ctrl[robot.act], HOME_ARM])
    length = float(np.linalg.norm(robot.ik.fk(path[1])[0] - robot.ik.fk(path[0])[0]))
    assert np.sqrt(QUINTIC_ACCEL * length / hi) - 1e-9 <= robot._carry_time(path) <= np.sqrt(QUINTIC_ACCEL * length / lo) + 1e-9
    placed = robot.place_in("lidded_mug", "target_zone")  # carried by the handle without slipping out
    assert placed.success, placed.reason
    up = data.xmat[model.body("lidded_mug").id].reshape(3, 3)[:, 2]
    assert up[2] > np.cos(np.radians(5.0))  # set down standing, let go without tipping it: the fingers backed out of the loop
    assert not robot.geometry.touching("lidded_mug") & {"robot"}
    assert robot._carry_time(path) == 0.0  # nothing held: the joint speed alone times a move
    assert model.opt.noslip_iterations == 0  # let go: the scene's own solver setting again
