"""The Franka acts: attach + home keyframe, IK, grasp-lift-place, not-graspable, determinism."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh

from realsim.composition.compose import compose_scene
from realsim.composition.robot_placement import add_robot, choose_robot_pose
from realsim.composition.settle import settle_scene
from realsim.errors import InputError
from realsim.output import write_scene
from realsim.robot import Robot
from realsim.robot.ik import mat_to_quat
from realsim.robot.model import BASE_FOOTPRINT, HOME_ARM, menagerie_panda_dir
from realsim.scene import CaptureInfo, Scene, SceneObject, SupportPlane

TABLE_Z = 0.75
TOP_DOWN = np.array([0.0, 1.0, 0.0, 0.0])
ZONE = ((-0.25, -0.12), 0.08)


def _rect(c, size) -> np.ndarray:
    hx, hy = size[0] / 2, size[1] / 2
    return np.array([[c[0] - hx, c[1] - hy], [c[0] + hx, c[1] - hy], [c[0] + hx, c[1] + hy], [c[0] - hx, c[1] + hy]])


def box_object(i: int, name: str, xy, ext, mass: float = 0.2, yaw: float = 0.0) -> SceneObject:
    mesh = trimesh.creation.box(extents=ext)
    mesh.apply_translation([0, 0, ext[2] / 2])
    inertia = np.diag(mass / 12 * np.array([ext[1] ** 2 + ext[2] ** 2, ext[0] ** 2 + ext[2] ** 2, ext[0] ** 2 + ext[1] ** 2]))
    return SceneObject(id=i, name=name, label="box", position=np.array([xy[0], xy[1], TABLE_Z]), quat=np.array([np.cos(yaw / 2), 0, 0, np.sin(yaw / 2)]),
                       size=np.array(ext, float), support_id=1, visual=mesh, collision=[mesh], mass=mass, com=np.array([0, 0, ext[2] / 2]), inertia=inertia)


def table_scene(objects: list[SceneObject], seed: int = 0) -> Scene:
    cap = CaptureInfo(source=Path("hand-built"), kind="objects", environment_file=None, units="m", up="+z", units_detected=False, up_detected=False, input_to_world=np.eye(4))
    floor = SupportPlane(0, "floor", np.array([0, 0, 1.0]), 0.0, _rect((0, 0), (3, 3)), np.zeros(2), np.array([3.0, 3.0]), 0.0, 0, observed=False)
    table = SupportPlane(1, "table", np.array([0, 0, 1.0]), TABLE_Z, _rect((0, 0), (1.0, 0.7)), np.zeros(2), np.array([1.0, 0.7]), 0.0, 1000)
    return Scene(capture=cap, seed=seed, planes=[floor, table], objects=objects)


def build(objects: list[SceneObject], pose=None) -> Scene:
    scene = compose_scene(table_scene(objects))
    c, half = ZONE
    scene.spec.worldbody.add_geom(name="target_zone", type=mujoco.mjtGeom.mjGEOM_BOX, pos=[c[0], c[1], TABLE_Z + 0.0005], size=[half, half, 0.0005],
                                  group=2, contype=0, conaffinity=0, rgba=[0.1, 0.8, 0.2, 0.6])
    add_robot(scene, pose, extra_targets=[np.array([c[0], c[1], TABLE_Z + 0.15])])
    return settle_scene(scene)


def loaded(scene: Scene, key: str = "initial") -> tuple[mujoco.MjModel, mujoco.MjData]:
    model = scene.spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key(key).id)
    mujoco.mj_forward(model, data)
    return model, data


@pytest.fixture(scope="module")
def scene() -> Scene:
    return build([box_object(1, "box_a", (0.1, 0.05), (0.05, 0.05, 0.06)), box_object(2, "big_box", (-0.2, 0.15), (0.12, 0.12, 0.08), mass=0.3)])


def test_menagerie_root_missing_is_input_error(monkeypatch, tmp_path) -> None:
    monkeypatch.setenv("MENAGERIE_ROOT", str(tmp_path))
    with pytest.raises(InputError, match="MENAGERIE_ROOT"):
        menagerie_panda_dir()


def test_attach_compiles_home_holds_and_writes(scene: Scene, tmp_path) -> None:
    model, data = loaded(scene, "home")
    robot = Robot(model, data)
    assert np.allclose(data.qpos[robot.qadr], HOME_ARM)
    q0 = data.qpos.copy()
    for _ in range(int(1.0 / model.opt.timestep)):
        mujoco.mj_step(model, data)
    assert np.abs(data.qpos[robot.qadr] - q0[robot.qadr]).max() < 2e-3
    key = model.key("initial")
    assert np.allclose(key.ctrl[robot.act], HOME_ARM) and key.ctrl[robot.grip_act] == 255
    # the base stands outside the table rectangle, on a pedestal at table height
    x, y = robot.base_pos[:2]
    assert abs(x) > 0.5 + BASE_FOOTPRINT - 1e-6 or abs(y) > 0.35 + BASE_FOOTPRINT - 1e-6
    assert robot.base_pos[2] == pytest.approx(TABLE_Z)
    out = write_scene(scene, tmp_path / "out")
    written = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert written.nu == 8 and written.key("initial").id >= 0


def test_choose_robot_pose_override_and_footprint(scene: Scene) -> None:
    assert choose_robot_pose(scene, override=(1.0, 2.0, 0.5)) == (1.0, 2.0, 0.5)


def test_ik_reachable_and_unreachable(scene: Scene) -> None:
    model, data = loaded(scene)
    robot = Robot(model, data)
    ik = robot.ik
    _, home_rot = ik.fk(np.array(HOME_ARM))
    down = mat_to_quat(home_rot)  # top-down, the hand's yaw as at home
    yaw = 2 * np.arctan2(robot.base_quat[3], robot.base_quat[0])
    rot = np.array([[np.cos(yaw), -np.sin(yaw), 0], [np.sin(yaw), np.cos(yaw), 0], [0, 0, 1]])
    for local in ([0.45, 0.0, 0.15], [0.55, 0.2, 0.1], [0.35, -0.25, 0.3], [0.7, 0.0, 0.05]):
        target = robot.base_pos + rot @ np.array(local)
        res = ik.solve(np.array(target), down)
        assert res.converged, res.reason
        assert res.pos_error < ik.params.pos_tol and res.rot_error < ik.params.rot_tol
        pos, _ = ik.fk(res.q)
        assert np.linalg.norm(pos - target) < ik.params.pos_tol
    far = ik.solve(robot.base_pos + np.array([2.0, 0.0, 0.0]), TOP_DOWN)
    assert not far.converged and far.pos_error > ik.params.pos_tol and "did not converge" in far.reason
    pinned = ik.solve(robot.base_pos + rot @ np.array([0.5, 0.1, 0.2]), None, wrist_pin=0.3)
    assert pinned.converged and abs(pinned.q[6] - 0.3) < 0.05


def _pick_and_place(scene: Scene, seed: int) -> tuple[list, np.ndarray, mujoco.MjData]:
    model, data = loaded(scene)
    robot = Robot(model, data, seed=seed)
    results = [robot.grasp("box_a")]
    if results[0].success:
        results.append(robot.place_in("box_a", "target_zone"))
        results.append(robot.go_home())
    return results, robot.object_pose("box_a")[0], data


def test_grasp_lift_place_in_zone(scene: Scene) -> None:
    results, final, data = _pick_and_place(scene, seed=0)
    grasp, place, home = results
    assert grasp.success, grasp.reason
    assert grasp.values["lifted"] > 0.04
    assert place.success, place.reason
    c, half = ZONE
    assert abs(final[0] - c[0]) < half and abs(final[1] - c[1]) < half
    assert final[2] == pytest.approx(TABLE_Z, abs=0.005)
    assert home.success
    assert data.time < 40.0


def test_the_pads_hold_a_light_part_without_sinking_into_it(scene: Scene) -> None:
    """A 200 g, 50 mm box lifted and held still: the pads sink less than 0.2 mm into each face
    (firm pads: their contacts' own stiffness, not the object's mass-scaled default)."""
    model, data = loaded(scene)
    pads = [g for g in range(model.ngeom) if model.geom_bodyid[g] in (model.body("panda/left_finger").id, model.body("panda/right_finger").id)
            and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX]
    assert len(pads) == 10 and all(model.geom_solmix[g] > 100 and model.geom_solref[g][0] < 0.02 for g in pads)
    robot = Robot(model, data)
    assert robot.grasp("box_a").success
    robot._wait(1.0)
    assert (0.05 - robot.gripper_opening()) / 2 < 2e-4, robot.gripper_opening()  # 0.35 mm at the default contact, 0.05 mm with the pads' own


def test_not_graspable_object_is_reported(scene: Scene) -> None:
    model, data = loaded(scene)
    robot = Robot(model, data)
    res = robot.grasp("big_box")
    assert not res.success and "not graspable" in res.reason and "mm" in res.reason
    assert res.sim_time == 0.0


def test_determinism(scene: Scene) -> None:
    a, pose_a, data_a = _pick_and_place(scene, seed=3)
    b, pose_b, data_b = _pick_and_place(scene, seed=3)
    assert [r.success for r in a] == [r.success for r in b]
    assert np.array_equal(pose_a, pose_b) and np.array_equal(data_a.qpos, data_b.qpos)


def test_a_held_object_hanging_tilted_is_turned_back_to_how_it_stood(scene: Scene) -> None:
    model, data = loaded(scene)
    robot = Robot(model, data)
    up = robot._up("box_a")
    assert robot._upright("box_a") is None  # never grasped: nothing to compare with
    tilted = np.array([np.sin(np.radians(25.0)), 0.0, np.cos(np.radians(25.0))])
    robot.stood["box_a"] = tilted  # it stood tilted 25 degrees from how it is now
    fix = robot._upright("box_a")
    assert fix is not None and np.allclose(fix @ up, tilted, atol=1e-9) and np.allclose(fix @ fix.T, np.eye(3), atol=1e-9)
    robot.stood["box_a"] = np.array([np.sin(np.radians(3.0)), 0.0, np.cos(np.radians(3.0))])
    assert robot._upright("box_a") is None  # within stand_tilt: released as it hangs
