"""`realsim run` end to end on a small YCB scene made with the real pipeline (mug + bowl).

The scene is converted once per session (CoACD on the two meshes, cached in the session's
REALSIM_CACHE); every run starts from keyframe "initial".
"""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import numpy as np
import pytest
from anthropic_server import MessagesServer

from conftest import YCB
from realsim import cli
from realsim.errors import InputError
from realsim.planner.sandbox import SandboxViolation
from realsim.runtime import Sim, probe, run_command, run_program


@pytest.fixture(scope="session")
def scene(tmp_path_factory: pytest.TempPathFactory) -> Path:
    from realsim.pipeline import convert

    root = tmp_path_factory.mktemp("run_scene")
    prebuilt = os.environ.get("REALSIM_RUN_TEST_SCENE")  # a converted copy of this scene, to iterate fast
    if prebuilt:
        shutil.copytree(prebuilt, root / "mugbowl", ignore=shutil.ignore_patterns("runs"))
        return root / "mugbowl"
    cap = root / "capture"
    for folder in ("025_mug", "024_bowl"):
        dest = cap / "objects" / folder.split("_", 1)[1]
        dest.mkdir(parents=True)
        for f in (YCB / folder).glob("textured.*"):
            shutil.copy(f, dest / f.name)
    (cap / "capture.yaml").write_text("support: {size: [0.55, 0.8], height: 0.75}\n")
    out = root / "mugbowl"
    convert(cap, out, seed=0)
    return out


def _run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = cli.main(["run", *argv])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_pick_and_place_sentence_reaches_goal(scene: Path, tmp_path: Path, capsys) -> None:
    log = tmp_path / "log.json"
    code, out, err = _run(capsys, str(scene), "pick up the mug and put it in the bowl", "--planner", "rules", "--log", str(log))
    assert code == 0, out + err
    assert "grasp('obj2_mug')" in out and "place_in('obj2_mug', 'obj1_bowl')" in out  # the program is printed
    assert "-> ok" in out and "goal [met] obj2_mug inside obj1_bowl" in out
    rec = json.loads(log.read_text())
    assert rec["verdict"] == "met" and rec["exit_code"] == 0 and rec["planner"] == "rules"
    assert rec["goals"][0]["ok"] and "of its base over the container" in rec["goals"][0]["measured"]
    assert [c["call"] for c in rec["calls"]] == ["grasp('obj2_mug')", "place_in('obj2_mug', 'obj1_bowl')"]
    assert rec["sim_time"] > 1.0 and rec["wall_time"]["total"] > 0 and rec["usage"]["calls"] == 0
    assert not (scene / "runs").exists()  # --log given: nothing else written into the scene
    # the scene itself is untouched: a fresh load starts where the conversion left the objects
    sim = Sim.load(scene)
    assert sim.state() == {k: v for k, v in rec["objects_before"].items()}


def test_a_lift_put_back_is_checked_when_the_lift_ends(scene: Path, tmp_path: Path, capsys) -> None:
    """"lift the mug, then put it back": the end state alone cannot tell it was lifted; the lift is
    checked in the simulation when its call returns."""
    log = tmp_path / "log.json"
    code, out, err = _run(capsys, str(scene), "lift the mug, then put it back where it was", "--planner", "rules", "--log", str(log))
    assert code == 0, out + err
    goals = json.loads(log.read_text())["goals"]
    assert [g["goal"] for g in goals][0] == "obj2_mug lifted (after call 1)" and all(g["ok"] for g in goals)
    assert float(goals[0]["measured"].split()[1]) >= 0.03  # "raised +0.1xx m (>= 0.030)"


def test_default_log_goes_to_numbered_runs(scene: Path, capsys) -> None:
    code, out, err = _run(capsys, str(scene), "go home", "--planner", "rules")
    assert code == 0, out + err
    first = scene / "runs" / "run_0001.json"
    assert first.is_file() and json.loads(first.read_text())["verdict"] == "met"
    code, _, _ = _run(capsys, str(scene), "go home", "--planner", "rules")
    assert (scene / "runs" / "run_0002.json").is_file()
    shutil.rmtree(scene / "runs")


def test_unknown_object_lists_objects(scene: Path, capsys) -> None:
    code, out, err = _run(capsys, str(scene), "put the banana in the bowl", "--planner", "rules")
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "banana" in lines[0] and "obj2_mug" in lines[0] and "obj1_bowl" in lines[0]
    assert "Traceback" not in err


@pytest.mark.parametrize("argv, needle", [
    (["/no/such/scene", "go home"], "no such scene folder"),
    ([], "either a command"),
])
def test_bad_input_exit_2(scene: Path, capsys, argv, needle) -> None:
    code, _, err = _run(capsys, *(argv or [str(scene)]))
    assert code == 2 and needle in err


def test_scene_without_robot_is_input_error(tmp_path: Path) -> None:
    import mujoco

    spec = mujoco.MjSpec()
    body = spec.worldbody.add_body(name="box")
    body.add_freejoint()
    body.add_geom(size=[0.02, 0.02, 0.02], type=mujoco.mjtGeom.mjGEOM_BOX)
    spec.compile()
    (tmp_path / "scene.xml").write_text(spec.to_xml())
    with pytest.raises(InputError, match="no robot"):
        Sim.load(tmp_path)


def test_hostile_program_rejected_before_anything_moves(scene: Path, tmp_path: Path, capsys) -> None:
    prog = tmp_path / "evil.py"
    prog.write_text("p, q = object_pose('obj2_mug')\ngrasp('obj2_mug')\nimport os\nos.system('echo pwned')\n")
    code, out, err = _run(capsys, str(scene), "--program", str(prog))
    assert code == 2 and "line 3" in err and "import" in err
    assert "running:" not in out and not (scene / "runs").exists()
    sim = Sim.load(scene)
    before = sim.state()
    with pytest.raises(SandboxViolation, match="line 3"):
        run_program(sim, prog.read_text())
    assert sim.data.time == 0.0 and sim.state() == before


def test_runaway_program_stopped_naming_the_line(scene: Path, tmp_path: Path, capsys) -> None:
    prog = tmp_path / "loop.py"
    prog.write_text("n = 0\nwhile True:\n    n = n + 1\n")
    log = tmp_path / "loop.json"
    code, out, err = _run(capsys, str(scene), "--program", str(prog), "--log", str(log))
    assert code == 2 and "line 2: while loop" in out
    assert json.loads(log.read_text())["program_error"] is True


def test_user_program_runs_in_the_sim(scene: Path, tmp_path: Path) -> None:
    sim = Sim.load(scene)
    rec = run_program(sim, "push('obj1_bowl', [0, 1], 0.05)\np, q = object_pose('obj1_bowl')\nprint(round(p[1], 2))\n")
    assert rec.success and rec.exit_code == 0 and rec.verdict == "goal unknown"
    assert rec.objects_after["obj1_bowl"][1] > rec.objects_before["obj1_bowl"][1] + 0.03
    assert rec.output and rec.calls[0]["success"]


def test_a_place_that_already_holds_moves_nothing(scene: Path) -> None:
    sim = Sim.load(scene)
    rec = run_program(sim, "place_in('obj2_mug', 'obj1_bowl')\nplace_in('obj2_mug', 'obj1_bowl')\n")
    first, again = rec.calls
    assert first["success"] and first["sim_time"] > 0.5 and "already" not in first["reason"]
    assert again["success"] and again["sim_time"] == 0 and "already rests there" in again["reason"]
    assert rec.success


def test_impossible_request_goal_not_met(scene: Path, tmp_path: Path, capsys) -> None:
    log = tmp_path / "fail.json"
    code, out, err = _run(capsys, str(scene), "push the mug 1 m forward", "--planner", "rules", "--log", str(log))
    assert code == 1, out + err
    rec = json.loads(log.read_text())
    assert rec["verdict"] == "not met" and not rec["goals"][0]["ok"] and "moved" in rec["goals"][0]["measured"]


def test_video_is_a_playable_mp4(scene: Path, tmp_path: Path, capsys) -> None:
    video = tmp_path / "run.mp4"
    code, out, err = _run(capsys, str(scene), "nudge the bowl right 5 cm", "--planner", "rules", "--video", str(video),
                          "--video-fps", "6", "--log", str(tmp_path / "v.json"))
    assert code == 0, out + err
    rec = json.loads((tmp_path / "v.json").read_text())
    frames, seconds = probe(video)  # ffmpeg decodes every frame
    assert frames == rec["video"]["frames"] > 15
    assert seconds == pytest.approx(rec["sim_time"], abs=0.5)  # frames were taken in simulated time


def test_claude_planner_through_local_messages_api(scene: Path, tmp_path: Path, capsys, monkeypatch) -> None:
    reply = "Here is the program:\n```python\nplace_in(\"obj2_mug\", \"obj1_bowl\")\ngo_home()\n```\n"
    with MessagesServer() as server:
        server.push_text(reply, input_tokens=900, output_tokens=40)
        monkeypatch.setenv("ANTHROPIC_API_KEY", "test-key")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", server.base_url)
        log = tmp_path / "claude.json"
        code, out, err = _run(capsys, str(scene), "put the mug in the bowl and go home", "--log", str(log))  # auto -> claude
        assert server.calls == 1
        sent = server.requests[0]
    assert code == 0, out + err
    assert "obj2_mug" in json.dumps(sent["messages"])  # the live scene went to Claude
    rec = json.loads(log.read_text())
    assert rec["planner"] == "claude" and rec["usage"]["calls"] == 1 and rec["usage"]["input_tokens"] == 900
    assert rec["verdict"] == "met" and {g["goal"] for g in rec["goals"]} == {"obj2_mug inside obj1_bowl", "robot at home"}


def test_same_seed_same_outcome(scene: Path) -> None:
    sim = Sim.load(scene)
    a = run_command(sim, "push the bowl 5 cm to the left", planner="rules")
    b = run_command(sim, "push the bowl 5 cm to the left", planner="rules")
    assert a.objects_after == b.objects_after and a.sim_time == b.sim_time
    assert np.isclose(a.objects_after["obj1_bowl"][1] - a.objects_before["obj1_bowl"][1], 0.05, atol=0.02)


def test_reset_undoes_what_a_run_left_in_the_model(scene: Path) -> None:
    """A run that ends holding an object leaves the noslip solver on; the next sentence in the same
    Sim must start from the scene's own options, as a fresh load does (a bench runs many in one)."""
    sim = Sim.load(scene)
    own = int(sim.model.opt.noslip_iterations)
    rec = run_program(sim, "grasp('obj2_mug')")
    assert rec.error is None and sim.robot.held == "obj2_mug"
    assert int(sim.model.opt.noslip_iterations) != own  # held at the end: the solver is still on
    sim.reset()
    assert int(sim.model.opt.noslip_iterations) == own
