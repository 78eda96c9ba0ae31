"""Ten varied scene descriptions -> settled scenes: objects, counts, sizes, rest, timings.

With ``--robot`` the Panda is placed, the scene is written, and the robot tries to grasp and lift
every free object from keyframe "initial" (one `grasp` per object, up to 4 attempts each), and to
open and close every drawer; then the same for a drawer cabinet scene over 8 seeds, and every
object of the first description picked over 10 seeds.

    MENAGERIE_ROOT=../shared/data python bench/bench_text.py [--robot]
"""

from __future__ import annotations

import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

import mujoco

from realsim.pipeline import convert, run_pipeline
from realsim.runtime import Sim
from realsim.procedural import size_range
from realsim.settle import rest_check
from realsim.text.parser import parse_description

DESCRIPTIONS = [
    "a kitchen table with a mug, a bowl, two soda cans and a cereal box",
    "3 red mugs on the counter",
    "a large bowl and a small blue cup on the floor",
    "a desk with a book, a bottle and a jar",
    "two plates, a tray and a green cup",
    "a drawer cabinet and a yellow mug on the table",
    "a hinged box, a can and a book",
    "a trash bin and a box on the floor",
    "a kitchen counter with a bottle of water, two glasses and a plate",
    "a table with a toy dinosaur, an apple and a white bowl",
]
DRAWER_TEXT = "a drawer cabinet, a mug and a can on the table"
DRAWER_SEEDS = 8
EXAMPLE_SEEDS = 10  # the example sentence, every object picked, over this many seeds


def pick_every_object(folder: Path) -> list[tuple[str, str, str]]:
    """(object, outcome, detail) for one seeded grasp of each free object, each from the keyframe.

    outcome: "lifted", "not graspable" (declared before trying: wider than the hand) or "failed".
    """
    sim = Sim.load(folder)
    out = []
    for name in sim.robot.object_names():
        sim.reset()
        res = sim.robot.grasp(name)
        if res.success:
            out.append((name, "lifted", res.values.get("kind") or ""))
        else:
            out.append((name, "failed" if res.values.get("graspable", True) else "not graspable", res.reason))
    return out


def open_and_close_drawers(folder: Path) -> list[tuple[str, bool, str]]:
    """(drawer, opened and closed again, detail) for every slide-jointed part, from the keyframe."""
    sim = Sim.load(folder)
    out = []
    for name in sim.object_names():
        joint = sim.model.body_jntadr[sim.model.body(name).id]
        if joint < 0 or int(sim.model.jnt_type[joint]) != mujoco.mjtJoint.mjJNT_SLIDE:
            continue
        sim.reset()
        opened = sim.robot.open_drawer(name)
        closed = sim.robot.close_drawer(name) if opened.success else None
        ok = bool(opened.success and closed and closed.success)
        detail = f"opened {opened.values.get('opened', 0.0) * 1000:.0f} mm" + (f", closed to {closed.values.get('position', 0.0) * 1000:.0f} mm" if closed else "")
        out.append((name, ok, detail if opened.success else opened.reason))
    return out


def main() -> int:
    robot = "--robot" in sys.argv
    failures = 0
    picks: list[tuple[str, str, str]] = []
    drawers: list[tuple[str, bool, str]] = []
    for i, text in enumerate(DESCRIPTIONS):
        started = time.perf_counter()
        try:
            overrides = {"load": {"text": text}, **({} if robot else {"robot": {"enabled": False}})}
            if robot:
                with tempfile.TemporaryDirectory() as tmp:
                    scene = convert(None, Path(tmp) / "scene", seed=i, overrides=overrides)
                    scene_picks = pick_every_object(Path(tmp) / "scene")
                    scene_drawers = open_and_close_drawers(Path(tmp) / "scene")
                picks += scene_picks
                drawers += scene_drawers
                for name, outcome, detail in scene_picks:
                    print(f"   {outcome:13s} {name}: {detail}")
                for name, ok, detail in scene_drawers:
                    print(f"   {'opened+closed' if ok else 'drawer FAILED'} {name}: {detail}")
            else:
                scene = run_pipeline(None, seed=i, overrides=overrides)
            rest = rest_check(scene.spec.compile(), 2.0)
            want = Counter()
            for o in parse_description(text).objects:
                want[o.label] += o.count
            got = Counter(o.label for o in scene.objects)
            counts_ok = all(got[k] == v for k, v in want.items() if k not in ("drawer cabinet", "hinged box"))
            sizes_ok = all(size_range(o.label)[0] <= max(o.size) <= size_range(o.label)[2] for o in scene.objects if o.label in want)
            ok = counts_ok and sizes_ok and rest["max_displacement"] < 0.005
        except Exception as exc:  # report and continue
            print(f"{i:2d} FAIL {text!r}: {type(exc).__name__}: {exc}")
            failures += 1
            continue
        failures += not ok
        print(f"{i:2d} {'ok  ' if ok else 'FAIL'} {time.perf_counter() - started:5.1f}s moved {rest['max_displacement'] * 1000:.2f} mm "
              f"counts {'ok' if counts_ok else 'BAD'} sizes {'ok' if sizes_ok else 'BAD'} {dict(got)}")
    print(f"{len(DESCRIPTIONS) - failures}/{len(DESCRIPTIONS)} passed")
    if robot:
        outcomes = Counter(outcome for _, outcome, _ in picks)
        tried = outcomes["lifted"] + outcomes["failed"]
        print(f"grasped and lifted {outcomes['lifted']}/{len(picks)} objects; {outcomes['lifted']}/{tried} of those the hand fits "
              f"({outcomes['not graspable']} declared not graspable before trying)")
        print(f"drawers opened and closed again by the robot in the ten scenes: {sum(ok for _, ok, _ in drawers)}/{len(drawers)}")
        seeded = []
        for seed in range(DRAWER_SEEDS):
            with tempfile.TemporaryDirectory() as tmp:
                convert(None, Path(tmp) / "scene", seed=seed, overrides={"load": {"text": DRAWER_TEXT}})
                result = open_and_close_drawers(Path(tmp) / "scene")
            seeded += result
            for name, ok, detail in result:
                print(f"   seed {seed}: {'opened+closed' if ok else 'FAILED'} {name}: {detail}")
        print(f"{DRAWER_TEXT!r}, seeds 0-{DRAWER_SEEDS - 1}: drawer opened and closed {sum(ok for _, ok, _ in seeded)}/{len(seeded)}")
        example = []
        for seed in range(EXAMPLE_SEEDS):
            with tempfile.TemporaryDirectory() as tmp:
                convert(None, Path(tmp) / "scene", seed=seed, overrides={"load": {"text": DESCRIPTIONS[0]}})
                result = pick_every_object(Path(tmp) / "scene")
            example += result
            print(f"   seed {seed}: " + ", ".join(f"{name} {outcome}" for name, outcome, _ in result))
        print(f"{DESCRIPTIONS[0]!r}, seeds 0-{EXAMPLE_SEEDS - 1}: lifted {sum(o == 'lifted' for _, o, _ in example)}/{len(example)}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
