"""`realsim export`: self-contained MJCF (scene and per object) and USD stages of real scenes.

Two scenes converted with the real pipeline and the Panda: a Kinect scan (mOSD test45, converted
once per run and shared with test_scan_conversion) and a capture folder of two YCB objects on an
assumed table.
"""

from __future__ import annotations

import json
import os
import shutil
import warnings
from pathlib import Path

import mujoco
import numpy as np
import pytest

from conftest import YCB, converted_scan
from realsim import cli

YCB_OBJECTS = ("077_rubiks_cube", "061_foam_brick")


@pytest.fixture(scope="module")
def scenes(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    root = tmp_path_factory.mktemp("export-scenes")
    capture = root / "ycb_capture"
    for name in YCB_OBJECTS:
        (capture / "objects" / name).mkdir(parents=True)
        for file in ("textured.obj", "textured.mtl"):
            shutil.copyfile(YCB / name / file, capture / "objects" / name / file)
    (capture / "capture.yaml").write_text("support: {size: [1.0, 0.7], height: 0.75}\n")
    out = {"scan": converted_scan(tmp_path_factory, "test45"), "ycb": root / "ycb"}  # the scan: read only
    assert cli.main(["convert", str(capture), "-o", str(out["ycb"]), "-q"]) == 0
    return out


def _trajectory(xml: Path, seconds: float = 2.0) -> tuple[np.ndarray, np.ndarray]:
    """Keyframe 'initial' qpos and the qpos after ``seconds`` of simulation (compiled from /)."""
    cwd = os.getcwd()
    os.chdir("/")
    try:
        model = mujoco.MjModel.from_xml_path(str(xml))
    finally:
        os.chdir(cwd)
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
    start = data.qpos.copy()
    for _ in range(int(round(seconds / model.opt.timestep))):
        mujoco.mj_step(model, data)
    return start, data.qpos.copy()


@pytest.mark.parametrize("kind", ["scan", "ycb"])
def test_mjcf_export_is_relocatable_and_simulates_identically(scenes, kind, tmp_path):
    src = scenes[kind]
    assert cli.main(["export", str(src), "--format", "mjcf", "-o", str(tmp_path / "export")]) == 0
    moved = tmp_path / "elsewhere" / "copy"
    shutil.move(str(tmp_path / "export"), moved)
    xml = (moved / "scene.xml").read_text()
    assert str(src) not in xml and "/tmp" not in xml  # nothing points back at the source
    assert any(f.name.startswith("panda_") for f in (moved / "assets").iterdir())  # the robot came along
    start_a, end_a = _trajectory(src / "scene.xml")
    start_b, end_b = _trajectory(moved / "scene.xml")
    np.testing.assert_array_equal(start_a, start_b)
    np.testing.assert_allclose(end_a, end_b, rtol=0, atol=1e-9)


def test_objects_only_export_attaches_into_another_scene(scenes, tmp_path):
    src = scenes["ycb"]
    assert cli.main(["export", str(src), "--objects-only", "-o", str(tmp_path / "objs")]) == 0
    moved = tmp_path / "moved"
    shutil.move(str(tmp_path / "objs"), moved)
    index = json.loads((moved / "objects.json").read_text())
    original = mujoco.MjModel.from_xml_path(str(src / "scene.xml"))
    scene_objects = [o["body"] for o in json.loads((src / "scene.json").read_text())["objects"]]
    assert sorted(o["body"] for o in index["objects"]) == sorted(scene_objects)
    host = mujoco.MjSpec()
    host.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[1, 1, 0.1])
    for k, entry in enumerate(index["objects"]):
        body = entry["body"]
        files = [f.name for f in (moved / body / "assets").iterdir()]
        assert files and all(f.startswith(body) for f in files)  # only this object's meshes
        child_xml = moved / entry["xml"]
        child_model = mujoco.MjModel.from_xml_path(str(child_xml))
        assert child_model.nbody == 2 and child_model.njnt == 1 and child_model.nu == 0
        for prefix in ("a_", "b_"):  # two copies of every object: names stay unique
            frame = host.worldbody.add_frame(pos=[0.3 * k, 0.2 if prefix == "a_" else -0.2, 0.05])
            with warnings.catch_warnings():
                warnings.simplefilter("error")  # no option/size conflicts with the host
                host.attach(mujoco.MjSpec.from_file(str(child_xml)), prefix=prefix, frame=frame)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        model = host.compile()
    for entry in index["objects"]:
        ref = original.body(entry["body"])
        got = model.body("a_" + entry["body"])
        assert got.mass[0] == pytest.approx(ref.mass[0], rel=1e-9)
        np.testing.assert_allclose(got.inertia, ref.inertia, rtol=1e-6)
        ngeom_collision = sum(1 for g in range(original.ngeom) if original.geom_bodyid[g] == ref.id and original.geom_group[g] == 3)
        assert sum(1 for g in range(model.ngeom) if model.geom_bodyid[g] == got.id and model.geom_group[g] == 3) == ngeom_collision
        assert sum(1 for g in range(model.ngeom) if model.geom_bodyid[g] == got.id and model.geom_group[g] == 2) == 1
    data = mujoco.MjData(model)
    for _ in range(200):
        mujoco.mj_step(model, data)
    assert np.all(np.isfinite(data.qpos))


@pytest.mark.parametrize("kind", ["scan", "ycb"])
def test_usd_stage_has_physics_on_every_object(scenes, kind, tmp_path, capsys):
    from pxr import Usd, UsdGeom, UsdPhysics, UsdShade

    src = scenes[kind]
    out = tmp_path / "stage" / "scene.usda"
    assert cli.main(["export", str(src), "--format", "usd", "-o", str(out)]) == 0
    assert "robot is not exported" in capsys.readouterr().err
    umask = os.umask(0)
    os.umask(umask)
    assert out.stat().st_mode & 0o777 == 0o666 & ~umask  # the user's normal mode, not a temp file's 0600
    stage = Usd.Stage.Open(str(out))
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert UsdPhysics.GetStageKilogramsPerUnit(stage) == 1.0
    assert "realsim:robot" in stage.GetRootLayer().customLayerData
    scenes_ = [p for p in stage.Traverse() if p.IsA(UsdPhysics.Scene)]
    assert len(scenes_) == 1
    physics = UsdPhysics.Scene(scenes_[0])
    assert tuple(physics.GetGravityDirectionAttr().Get()) == (0, 0, -1)
    assert physics.GetGravityMagnitudeAttr().Get() == pytest.approx(9.81)

    model = mujoco.MjModel.from_xml_path(str(src / "scene.xml"))
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
    mujoco.mj_kinematics(model, data)
    objects = [o["body"] for o in json.loads((src / "scene.json").read_text())["objects"]]
    assert objects
    for body in objects:
        prim = stage.GetPrimAtPath(f"/World/Objects/{body}")
        assert prim.IsValid(), body
        assert prim.HasAPI(UsdPhysics.RigidBodyAPI) and prim.HasAPI(UsdPhysics.MassAPI)
        b = model.body(body).id
        mass = UsdPhysics.MassAPI(prim)
        assert mass.GetMassAttr().Get() == pytest.approx(model.body_mass[b], rel=1e-6)
        np.testing.assert_allclose(mass.GetCenterOfMassAttr().Get(), model.body_ipos[b], atol=1e-6)
        np.testing.assert_allclose(mass.GetDiagonalInertiaAttr().Get(), model.body_inertia[b], rtol=1e-5)
        assert mass.GetPrincipalAxesAttr().Get() is not None
        world = UsdGeom.Xformable(prim).ComputeLocalToWorldTransform(Usd.TimeCode.Default())
        np.testing.assert_allclose(np.array(world.ExtractTranslation()), data.xpos[b], atol=1e-6)
        colliders = [p for p in Usd.PrimRange(prim) if p.HasAPI(UsdPhysics.CollisionAPI)]
        hulls = sum(1 for g in range(model.ngeom) if model.geom_bodyid[g] == b and model.geom_group[g] == 3)
        assert len(colliders) == hulls
        geoms = [g for g in range(model.ngeom) if model.geom_bodyid[g] == b and model.geom_group[g] == 3]
        for c, g in zip(sorted(colliders, key=lambda p: p.GetName()), sorted(geoms, key=lambda g: model.geom(g).name)):
            kind = model.geom_type[g]
            if kind == mujoco.mjtGeom.mjGEOM_MESH:  # a hull: convex mesh collider with its points
                assert c.IsA(UsdGeom.Mesh) and c.HasAPI(UsdPhysics.MeshCollisionAPI)
                assert UsdPhysics.MeshCollisionAPI(c).GetApproximationAttr().Get() == UsdPhysics.Tokens.convexHull
                assert len(UsdGeom.Mesh(c).GetPointsAttr().Get()) >= 4
            elif kind == mujoco.mjtGeom.mjGEOM_BOX:  # a primitive: USD's cube of side 2 scaled to the half sizes
                assert c.IsA(UsdGeom.Cube) and UsdGeom.Cube(c).GetSizeAttr().Get() == 2.0
                scale = [op.Get() for op in UsdGeom.Xformable(c).GetOrderedXformOps() if op.GetOpType() == UsdGeom.XformOp.TypeScale]
                np.testing.assert_allclose(scale[0], model.geom_size[g], rtol=1e-5)
            else:
                assert c.IsA(UsdGeom.Sphere) or c.IsA(UsdGeom.Cylinder) or c.IsA(UsdGeom.Capsule)
                assert c.GetAttribute("radius").Get() == pytest.approx(model.geom_size[g][0], rel=1e-5)
        visuals = [p for p in Usd.PrimRange(prim) if p.IsA(UsdGeom.Mesh) and not p.HasAPI(UsdPhysics.CollisionAPI)]
        assert len(visuals) == 1
        material, _ = UsdShade.MaterialBindingAPI(visuals[0]).ComputeBoundMaterial()
        assert material and material.GetSurfaceOutput().HasConnectedSource()
    statics = [p for p in stage.Traverse() if p.HasAPI(UsdPhysics.CollisionAPI)
               and not any(a.HasAPI(UsdPhysics.RigidBodyAPI) for a in _ancestors(p))]
    assert any(p.IsA(UsdGeom.Cube) for p in statics) and any(p.IsA(UsdGeom.Plane) for p in statics)  # support and floor
    assert not any("panda" in str(p.GetPath()) for p in stage.Traverse())


def _ancestors(prim):
    while prim.IsValid() and str(prim.GetPath()) != "/":
        yield prim
        prim = prim.GetParent()


def test_export_errors_are_one_line(tmp_path, capsys):
    assert cli.main(["export", str(tmp_path / "missing"), "-o", str(tmp_path / "x")]) == 2
    assert cli.main(["export", str(tmp_path), "--format", "usd", "-o", str(tmp_path / "x.txt")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and all(line.startswith("realsim: error:") for line in err)
