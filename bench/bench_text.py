"""Ten varied scene descriptions -> settled scenes: objects, counts, sizes, rest, timings.

With ``--robot`` the Panda is placed, the scene is written, and the robot tries to grasp and lift
every free object from keyframe "initial" (one `grasp` per object, up to 4 attempts each).

    MENAGERIE_ROOT=../shared/data python bench/bench_text.py [--robot]
"""

from __future__ import annotations

import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

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


def main() -> int:
    robot = "--robot" in sys.argv
    failures = 0
    picks: list[tuple[str, str, str]] = []
    for i, text in enumerate(DESCRIPTIONS):
        started = time.perf_counter()
        try:
            overrides = {"load": {"text": text}, **({} if robot else {"robot": {"enabled": False}})}
            if robot:
                with tempfile.TemporaryDirectory() as tmp:
                    scene = convert(None, Path(tmp) / "scene", seed=i, overrides=overrides)
                    scene_picks = pick_every_object(Path(tmp) / "scene")
                picks += scene_picks
                for name, outcome, detail in scene_picks:
                    print(f"   {outcome:13s} {name}: {detail}")
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
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
