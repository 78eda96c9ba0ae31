"""`realsim convert --text`: a description becomes a settled scene with the stated objects."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import mujoco
import numpy as np
import pytest

from realsim.cli import main
from realsim.composition.settle import rest_check
from realsim.pipeline import pipeline_for, run_pipeline
from realsim.procedural import size_range
from realsim.runtime import Sim, run_command

NO_ROBOT = {"robot": {"enabled": False}}


def _check(scene, expected: dict[str, int]) -> mujoco.MjModel:
    counts = Counter(o.label for o in scene.objects)
    for label, n in expected.items():
        assert counts[label] == n, counts
    for o in scene.objects:
        if o.label in expected:
            lo, _, hi = size_range(o.label)
            assert lo <= max(o.size) <= hi, (o.label, o.size)
    model = scene.spec.compile()
    rest = rest_check(model, 2.0)
    assert rest["max_displacement"] < 0.005, rest
    return model


def test_cli_issue_example(tmp_path: Path) -> None:
    out = tmp_path / "out"
    text = "a kitchen table with a mug, a bowl, two soda cans and a cereal box"
    assert main(["convert", "--text", text, "-o", str(out), "--no-robot", "-q"]) == 0
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    names = [model.body(i).name for i in range(model.nbody)]
    assert sum("soda_can" in n for n in names) == 2 and any("mug" in n for n in names) and any("cereal_box" in n for n in names)
    assert rest_check(model, 2.0)["max_displacement"] < 0.005


def test_counter_colours_and_drawer_slides() -> None:
    scene = run_pipeline(None, seed=1, overrides={"load": {"text": "a drawer cabinet and two red cups on the counter"}, **NO_ROBOT})
    assert scene.plane(1).height == pytest.approx(0.9)
    model = _check(scene, {"cup": 2, "cabinet": 1, "drawer": 1})
    cups = [o for o in scene.objects if o.label == "cup"]
    assert all(np.allclose(c.color, [0.8, 0.1, 0.1], atol=0.01) for c in cups)
    drawer = next(o for o in scene.objects if o.label == "drawer")
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
    mujoco.mj_forward(model, data)
    joint = model.joint(f"{drawer.name}_joint")
    body = model.body(drawer.name).id
    axis = data.xmat[body].reshape(3, 3) @ model.jnt_axis[joint.id]
    q0 = float(data.qpos[joint.qposadr[0]])
    for _ in range(500):
        data.xfrc_applied[body, :3] = 30.0 * axis
        mujoco.mj_step(model, data)
    assert data.qpos[joint.qposadr[0]] > q0 + 0.05


def test_text_in_capture_yaml(tmp_path: Path) -> None:
    (tmp_path / "capture.yaml").write_text('text: "a book and a can on the floor"\n')
    assert pipeline_for(tmp_path) == "text"
    scene = run_pipeline(tmp_path, overrides=NO_ROBOT)
    assert [p.kind for p in scene.planes] == ["floor"]
    _check(scene, {"book": 1, "can": 1})


def test_cli_errors(tmp_path: Path) -> None:
    assert main(["convert", "-o", str(tmp_path / "a")]) == 2
    assert main(["convert", "--text", "a table", "-o", str(tmp_path / "b"), "--no-robot", "-q"]) == 2


@pytest.fixture(scope="module")
def kitchen(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The issue's example converted with the Panda placed (seed 0)."""
    out = tmp_path_factory.mktemp("text_robot") / "kitchen"
    text = "a kitchen table with a mug, a bowl, two soda cans and a cereal box"
    assert main(["convert", "--text", text, "-o", str(out), "-q"]) == 0
    return out


@pytest.mark.parametrize("label", ["mug", "soda can", "cereal box"])
def test_franka_picks_procedural_objects(kitchen: Path, label: str) -> None:
    sim = Sim.load(kitchen)
    name = next(n for n in sim.robot.object_names() if n.split("_", 1)[1] == label.replace(" ", "_"))
    z0 = sim.robot.object_pose(name)[0][2]
    res = sim.robot.grasp(name)
    assert res.success, res.reason
    assert sim.robot.holding(name)
    assert sim.robot.object_pose(name)[0][2] > z0 + 0.1


def test_mug_goes_into_the_bowl(kitchen: Path) -> None:
    sim = Sim.load(kitchen)
    record = run_command(sim, "put the mug in the bowl", planner="rules")
    assert record.success, record.summary()


def test_franka_opens_and_closes_the_drawer(tmp_path: Path) -> None:
    """The cabinet's drawer has a handle site; the robot is placed to reach it and pulls it open."""
    out = tmp_path / "drawer"
    assert main(["convert", "--text", "a drawer cabinet, a mug and a can on the table", "--seed", "1", "-o", str(out), "-q"]) == 0
    sim = Sim.load(out)
    drawer = next(n for n in sim.object_names() if n.endswith("_drawer"))
    assert sim.model.site(f"{drawer}_handle") is not None
    record = run_command(sim, "open the drawer", planner="rules")
    assert record.success, record.summary()
    assert sim.joint_position(drawer) > 0.1
    record = run_command(sim, "open the drawer, then close the drawer", planner="rules")
    assert record.success, record.summary()
    assert sim.joint_position(drawer) < 0.01
