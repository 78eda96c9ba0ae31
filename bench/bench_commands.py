"""Benchmark the command planners: parse rate and time per command, sandbox run time.

    python bench/bench_commands.py            # rule planner only (offline)
    python bench/bench_commands.py --claude   # also Claude (needs ANTHROPIC_API_KEY; costs tokens)

Programs run in the sandbox against recording primitives (no robot), so this measures the
language side only.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from realsim.errors import RealsimError  # noqa: E402
from realsim.planner import ClaudePlanner, RulePlanner, run  # noqa: E402
from test_planner_rules import CASES, OBJECTS  # noqa: E402
from test_sandbox import Recorder  # noqa: E402

EXTRA = [
    "put the mug next to the bowl",
    "put every red object in the bowl",
    "tidy the table",
    "stack the can on the box then push the block 4 cm forward",
]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--claude", action="store_true", help="also plan with Claude")
    args = ap.parse_args()
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


if __name__ == "__main__":
    raise SystemExit(main())
