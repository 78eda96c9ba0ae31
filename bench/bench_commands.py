"""Benchmark the command planners: the language side, and whole commands in the simulation.

    python bench/bench_commands.py            # rule planner only (offline), recording primitives
    python bench/bench_commands.py --claude   # also Claude (needs ANTHROPIC_API_KEY; costs tokens)
    MENAGERIE_ROOT=../shared/data python bench/bench_commands.py --sim [--scenes DIR] [--planner rules]

Without ``--sim``, programs run in the sandbox against recording primitives (no robot): this
measures parsing only. With ``--sim``, three YCB scenes are made with the real pipeline (copied
meshes + ``capture.yaml``, ``realsim convert``; cached under ``--scenes``) and every sentence of
:data:`SIM_SUITE` runs from keyframe "initial": the program, each primitive's outcome and the
goal check are printed, then the success rate (goal met in the simulation).
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
sys.path.insert(0, str(REPO / "tests"))
os.environ.setdefault("MENAGERIE_ROOT", str(REPO.parent / "shared" / "data"))
os.environ.setdefault("MUJOCO_GL", "egl")

from realsim.errors import RealsimError  # noqa: E402
from realsim.planner import ClaudePlanner, RulePlanner, run  # noqa: E402

YCB = REPO.parent / "shared" / "data" / "ycb_google16k"

EXTRA = [
    "put the mug next to the bowl",
    "put every red object in the bowl",
    "tidy the table",
    "stack the can on the box then push the block 4 cm forward",
]

# A table 0.55 m deep (x) and 0.8 m wide (y); the Panda at its -x edge facing +x, so "left" is +y.
SUPPORT = "support: {size: [0.55, 0.8], height: 0.75}\n"
SCENES: dict[str, tuple[str, ...]] = {
    "kitchen": ("003_cracker_box", "005_tomato_soup_can", "025_mug", "024_bowl", "011_banana"),
    "pantry": ("006_mustard_bottle", "010_potted_meat_can", "061_foam_brick", "077_rubiks_cube", "040_large_marker"),
    "mugbowl": ("025_mug", "024_bowl"),
}
SIM_SUITE: list[tuple[str, str]] = [
    ("kitchen", "pick up the mug and put it in the bowl"),
    ("kitchen", "put the banana in the bowl"),
    ("kitchen", "grab the soup can"),
    ("kitchen", "lift the banana"),
    ("kitchen", "push the cracker box 10 cm to the left, then go home"),
    ("kitchen", "push the bowl back by 10 cm"),
    ("kitchen", "put the cup into the bowl"),
    ("kitchen", "put the soup can next to the bowl"),
    ("kitchen", "slide the mug forward 5 cm"),
    ("kitchen", "go home"),
    ("kitchen", "pick up the banana, then put it next to the mug"),
    ("kitchen", "push the soup can 5 cm forward and then go home"),
    ("kitchen", "take the tomato soup can and place it in the bowl"),
    ("pantry", "put the rubiks cube on the potted meat can"),
    ("pantry", "stack the foam brick on the rubiks cube"),
    ("pantry", "pick up the marker"),
    ("pantry", "grab the mustard bottle"),
    ("pantry", "push the foam brick 10 cm to the right"),
    ("pantry", "push the rubiks cube left by 8 cm"),
    ("pantry", "put the foam brick next to the potted meat can"),
    ("pantry", "lift the can"),
    ("pantry", "push the potted meat can back 10 cm, then go home"),
    ("pantry", "move the rubik's cube forward 5 cm"),
    ("pantry", "take the foam block and put it beside the mustard"),
    ("pantry", "grab the brick, then put it on the can"),
    ("mugbowl", "put the mug in the bowl"),
    ("mugbowl", "pick up the cup"),
    ("mugbowl", "push the bowl 10 cm to the left"),
    ("mugbowl", "push the mug forward 8 cm, then go home"),
    ("mugbowl", "put the mug next to the bowl"),
    ("mugbowl", "nudge the bowl right 5 cm"),
    ("mugbowl", "lift up the coffee mug"),
]


def make_scene(name: str, root: Path) -> Path:
    """The YCB scene ``name`` under ``root`` (made with the real pipeline once, then reused)."""
    out = root / name
    if (out / "scene.xml").is_file():
        return out
    from realsim.pipeline import convert

    cap = root / f"capture_{name}"
    if cap.exists():
        shutil.rmtree(cap)
    for folder in SCENES[name]:
        dest = cap / "objects" / folder.split("_", 1)[1]
        dest.mkdir(parents=True)
        for f in (YCB / folder).glob("textured.*"):
            shutil.copy(f, dest / f.name)
        for f in (YCB / folder).glob("*.png"):
            shutil.copy(f, dest / f.name)
    (cap / "capture.yaml").write_text(SUPPORT)
    convert(cap, out, seed=0)  # the robot placed by realsim's own reach search
    return out


def bench_sim(args: argparse.Namespace) -> int:
    from realsim.runtime import Sim, run_command

    root = Path(args.scenes)
    root.mkdir(parents=True, exist_ok=True)
    suite = [(s, c) for s, c in SIM_SUITE if not args.only or args.only in c]
    sims: dict[str, Sim] = {}
    rows = []
    t_start = time.perf_counter()
    for i, (scene, command) in enumerate(suite, 1):
        if scene not in sims:
            sims[scene] = Sim.load(make_scene(scene, root), seed=args.seed)
        sim = sims[scene]
        print(f"[{i}/{len(suite)}] {scene}: {command!r}")
        try:
            rec = run_command(sim, command, planner=args.planner, seed=args.seed)
        except RealsimError as exc:
            print(f"    rejected: {exc}")
            rows.append((scene, command, False, f"rejected: {exc}", 0.0, 0.0))
            continue
        for line in rec.program.rstrip().splitlines():
            print(f"    | {line}")
        for c in rec.calls:
            if "reason" in c:
                print(f"    {c['call']} -> {'ok' if c['success'] else 'FAILED: ' + c['reason']}")
        for g in rec.goals:
            print(f"    goal [{'met' if g['ok'] else 'NOT met'}] {g['goal']}: {g['measured']}")
        why = "" if rec.success else (rec.error or "; ".join(g["goal"] for g in rec.goals if not g["ok"]))
        print(f"    => {'SUCCESS' if rec.success else 'FAIL'} ({rec.verdict}; {rec.sim_time:.1f} s sim, {rec.wall_time['total']:.1f} s wall)")
        rows.append((scene, command, rec.success, why, rec.sim_time, rec.wall_time["total"]))
    n_ok = sum(r[2] for r in rows)
    print("\nscene     ok    sim s  wall s  command")
    for scene, command, ok, why, sim_s, wall_s in rows:
        print(f"{scene:9} {'yes' if ok else 'NO ':3} {sim_s:7.1f} {wall_s:7.1f}  {command}" + ("" if ok else f"   <- {why}"))
    print(f"\n{args.planner} planner in the simulation: {n_ok}/{len(rows)} commands reached their goal "
          f"({100.0 * n_ok / max(len(rows), 1):.0f}%), {time.perf_counter() - t_start:.0f} s wall in total")
    return 0


def bench_language(args: argparse.Namespace) -> int:
    from test_planner_rules import CASES, OBJECTS
    from test_sandbox import Recorder

    commands = [c[0] for c in CASES] + EXTRA
    planners = [RulePlanner()] + ([ClaudePlanner()] if args.claude else [])
    for planner in planners:
        ok = failed = 0
        t_plan = t_run = 0.0
        for command in commands:
            t0 = time.perf_counter()
            try:
                plan = planner.plan(command, OBJECTS)
            except RealsimError as exc:
                failed += 1
                print(f"  [{planner.name}] {command!r}: {exc}")
                continue
            t1 = time.perf_counter()
            report = run(plan.program, Recorder())
            t_run += time.perf_counter() - t1
            t_plan += t1 - t0
            ok += report.ok
        n = ok + failed
        print(
            f"{planner.name}: {ok}/{n} commands planned and ran; "
            f"plan {1e3 * t_plan / max(ok, 1):.2f} ms/command, sandbox {1e3 * t_run / max(ok, 1):.2f} ms/command"
        )
    return 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--claude", action="store_true", help="also plan with Claude (language benchmark)")
    ap.add_argument("--sim", action="store_true", help="run the sentence suite in the simulation on YCB scenes")
    ap.add_argument("--scenes", default=str(Path(os.environ.get("TMPDIR", "/tmp")) / "realsim_bench_commands"),
                    help="where the YCB scenes are made and cached")
    ap.add_argument("--planner", default="rules", choices=["rules", "claude", "auto"], help="planner for --sim")
    ap.add_argument("--only", help="--sim: only sentences containing this text")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    return bench_sim(args) if args.sim else bench_language(args)


if __name__ == "__main__":
    raise SystemExit(main())
