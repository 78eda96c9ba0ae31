"""A plan that would carry something the hand cannot hold is refused before anything moves, with the
robot's own reason (its width at the narrowest, no rim or handle), on a converted text scene."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from realsim import cli
from realsim.errors import InputError
from realsim.planner import make_planner
from realsim.planner.vocab import with_colors
from realsim.runtime import Sim, run_command


@pytest.fixture(scope="module")
def plate_scene(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("holdable") / "plate"
    assert cli.main(["convert", "--text", "a table with a plate and a red cube", "-o", str(out), "-q"]) == 0
    return out


def _plan(sim: Sim, sentence: str):
    return make_planner("rules").plan(sentence, with_colors(sim.object_infos(), sim.meta), robot_yaw=sim.robot_yaw(), robot_base=sim.robot_base())


def test_lifting_a_plate_is_refused_before_anything_moves(plate_scene: Path) -> None:
    sim = Sim.load(plate_scene)
    plate = next(n for n in sim.object_names() if n.endswith("plate"))
    before = sim.data.qpos.copy()
    with pytest.raises(InputError, match=rf"{plate} is \d+ mm across at its narrowest.*cannot be lifted or carried; it can still be pushed"):
        run_command(sim, "pick up the plate and put it next to the cube", planner="rules")
    assert sim.data.time == 0.0 and np.array_equal(sim.data.qpos, before)


def test_what_the_hand_holds_is_planned_as_before(plate_scene: Path) -> None:
    sim = Sim.load(plate_scene)
    plan = _plan(sim, "put the red cube on the plate")
    assert plan.calls is not None and len(plan.calls.carried()) == 1 and plan.calls.carried()[0].endswith("cube")
    sim.check_holdable(plan.calls)  # the cube fits the hand: no refusal
    sim.check_holdable(_plan(sim, "push the plate 3 cm to the left").calls)  # a push holds nothing


def test_the_cli_says_why_in_one_line_and_exits_2(plate_scene: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = cli.main(["run", str(plate_scene), "lift the plate", "--planner", "rules"])
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1 and "cannot be lifted" in err
