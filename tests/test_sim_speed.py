"""Fast physics and GPU-ready sizes: primitives, sleeping, recorded capacity, MuJoCo Warp, bench-sim.

The scene is converted with the real pipeline (a Rubik's cube and a strawberry on a table).
Primitive fitting is checked on generated ground truth (a box and a cylinder of known size).
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh

from conftest import YCB
from realsim import cli
from realsim.assets.primitives import PRIMITIVE_KEY, fit_primitive
from realsim.composition.compose import ComposeParams
from realsim.composition.settle import rest_check
from realsim.physics.throughput import bench_scene, warp_available


@pytest.fixture(scope="module")
def scene(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("speed")
    cap = root / "capture"
    for folder in ("077_rubiks_cube", "012_strawberry"):
        dest = cap / "objects" / folder.split("_", 1)[1]
        dest.mkdir(parents=True)
        for file in (YCB / folder).glob("textured.*"):
            shutil.copyfile(file, dest / file.name)
    (cap / "capture.yaml").write_text("support: {size: [0.6, 0.8], height: 0.75}\n")
    assert cli.main(["convert", str(cap), "-o", str(root / "out"), "-q"]) == 0
    return root / "out"


def test_primitives_fit_generated_shapes() -> None:
    box = trimesh.creation.box(extents=[0.06, 0.1, 0.2])
    box.apply_transform(trimesh.transformations.rotation_matrix(0.4, [0, 0, 1]))
    box.apply_translation([0, 0, 0.1])
    fitted, tried = fit_primitive(box, 0.003, 0.85)
    assert fitted is not None and fitted.metadata[PRIMITIVE_KEY]["type"] == "box"
    np.testing.assert_allclose(sorted(fitted.metadata[PRIMITIVE_KEY]["size"]), [0.03, 0.05, 0.1], atol=1e-4)
    can = trimesh.creation.cylinder(radius=0.033, height=0.1, sections=64)
    can.apply_translation([0, 0, 0.05])
    fitted, _ = fit_primitive(can, 0.003, 0.85)
    assert fitted is not None and fitted.metadata[PRIMITIVE_KEY]["type"] == "cylinder"
    np.testing.assert_allclose(fitted.metadata[PRIMITIVE_KEY]["size"], [0.033, 0.05], atol=5e-4)
    torus = trimesh.creation.torus(major_radius=0.05, minor_radius=0.01)  # a ring: no primitive is faithful
    assert fit_primitive(torus, 0.003, 0.85)[0] is None


def test_cube_is_a_box_and_the_scene_sleeps(scene: Path) -> None:
    model = mujoco.MjModel.from_xml_path(str(scene / "scene.xml"))
    bodies = {model.body(b).name: b for b in range(model.nbody)}
    cube = next(b for n, b in bodies.items() if "rubiks" in n)
    types = {int(model.geom_type[g]) for g in range(model.ngeom) if model.geom_bodyid[g] == cube and model.geom_contype[g]}
    assert types == {int(mujoco.mjtGeom.mjGEOM_BOX)}
    for g in range(model.ngeom):
        if model.geom_contype[g] and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH and model.body(model.geom_bodyid[g]).name.startswith("obj"):
            assert model.mesh_vertnum[model.geom_dataid[g]] <= 64  # vertex cap per hull
    assert model.opt.enableflags & mujoco.mjtEnableBit.mjENBL_SLEEP
    assert model.opt.sleep_tolerance == ComposeParams().sleep_tolerance
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
    for _ in range(int(0.5 / model.opt.timestep)):  # objects at rest fall asleep within half a second
        mujoco.mj_step(model, data)
    assert all(data.body_awake[b] == 0 for n, b in bodies.items() if n.startswith("obj"))
    # a rest check still measures motion although the scene may sleep: lift the cube 5 cm
    mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
    qadr = model.jnt_qposadr[model.body_jntadr[cube]]
    data.qpos[qadr + 2] += 0.05
    report = rest_check(model, 0.5, state=(data.qpos.copy(), data.ctrl.copy()))
    assert report["max_displacement"] > 0.04
    assert model.opt.enableflags & mujoco.mjtEnableBit.mjENBL_SLEEP  # restored


def test_recorded_capacity_holds_settling(scene: Path) -> None:
    model = mujoco.MjModel.from_xml_path(str(scene / "scene.xml"))
    capacity = json.loads((scene / "scene.json").read_text())["settle"]["capacity"]
    assert (model.nconmax, model.njmax) == (capacity["nconmax"], capacity["njmax"])
    assert capacity["nconmax"] >= capacity["measured"]["ncon"] > 0 and capacity["njmax"] >= capacity["measured"]["nefc"] > 0
    model.opt.enableflags &= ~int(mujoco.mjtEnableBit.mjENBL_SLEEP)  # every contact counted
    for key, seconds in (("home", 0.6), ("initial", 1.0)):
        data = mujoco.MjData(model)
        mujoco.mj_resetDataKeyframe(model, data, model.key(key).id)
        for _ in range(int(seconds / model.opt.timestep)):
            mujoco.mj_step(model, data)
            assert data.ncon <= model.nconmax and data.nefc <= model.njmax


def test_bench_sim_command_on_the_c_engine(scene: Path, capsys) -> None:
    assert cli.main(["bench-sim", str(scene), "--worlds", "3", "--steps", "50", "--engine", "c"]) == 0
    out = capsys.readouterr().out
    assert "mujoco (C, one core): 3 world(s) x 50 steps" in out and "steps/s" in out
    result = bench_scene(scene, worlds=2, steps=20, engine="c")
    assert result.steps_per_second > 0 and result.peak_ncon <= result.nconmax


@pytest.mark.skipif(not warp_available(), reason="mujoco-warp is not installed (pip install 'realsim[gpu]')")
def test_mujoco_warp_accepts_the_scene_with_its_sizes(scene: Path) -> None:
    import mujoco_warp as mjw

    model = mujoco.MjModel.from_xml_path(str(scene / "scene.xml"))
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
    mujoco.mj_forward(model, data)
    mjw.put_model(model)
    warp_data = mjw.put_data(model, data, nworld=2, nconmax=model.nconmax, njmax=model.njmax)
    assert warp_data.njmax == model.njmax and int(warp_data.naconmax) >= 2 * data.ncon
