"""Per-stage wall, main-thread CPU and main-thread run-queue wait of in-process conversions (a loaded machine's A/B).

On a machine other work keeps busy, wall time mostly measures the others; the kernel counts the time
the converting thread was ready to run but waited for a core (``/proc/thread-self/schedstat``).
Printed per run: wall, main-thread CPU (``main``), that wait (``rq``) and ``est`` = wall - rq (the main
thread's own path, its waits for helpers included), then per stage ``(wall - rq) / main-thread CPU``.
Each run converts cold (a fresh cache holding only the Panda's meshes), after the imports. Compare two
trees interleaved, e.g.::

    for t in /work/main /work/wt_x; do (cd $t && PYTHONPATH=$t python bench/bench_stage_cpu.py test55.pcd --repeat 2); done
"""

from __future__ import annotations

import argparse
import importlib
import os
import shutil
import sys
import tempfile
import time
from dataclasses import replace
from typing import Any


def _sched() -> tuple[float, float]:
    """(CPU seconds, run-queue wait seconds) of this thread so far."""
    run, wait, _ = open("/proc/thread-self/schedstat").read().split()
    return int(run) / 1e9, int(wait) / 1e9


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source", help="a capture to convert")
    parser.add_argument("--repeat", type=int, default=2, help="cold conversions, one line each")
    args = parser.parse_args()
    for library in ("mujoco", "numpy", "open3d", "scipy", "trimesh"):  # imports are not the conversion
        importlib.import_module(library)

    base = tempfile.mkdtemp()
    os.environ["REALSIM_CACHE"], os.environ["REALSIM_REUSE"] = base + "/seed", "0"
    from realsim.pipeline import convert
    from realsim.robot.model import panda_spec
    from realsim.stages import STAGES

    panda_spec()
    stages: dict[str, tuple[float, float, float]] = {}

    def timed(name: str, run: Any) -> Any:
        def wrapped(scene: Any, params: Any) -> Any:
            wall, (cpu, wait) = time.perf_counter(), _sched()
            try:
                return run(scene, params)
            finally:
                cpu1, wait1 = _sched()
                stages[name] = (time.perf_counter() - wall, cpu1 - cpu, wait1 - wait)
        return wrapped

    for name, stage in list(STAGES.items()):
        STAGES[name] = replace(stage, run=timed(name, stage.run))
    try:
        for r in range(args.repeat):
            run_dir = f"{base}/run{r}"
            shutil.copytree(base + "/seed", run_dir + "/cache")
            os.environ["REALSIM_CACHE"] = run_dir + "/cache"
            wall, (cpu, wait) = time.perf_counter(), _sched()
            convert(args.source, run_dir + "/out")
            wall, (cpu1, wait1) = time.perf_counter() - wall, _sched()
            cells = " ".join(f"{k} {w - q:.2f}/{c:.2f}" for k, (w, c, q) in stages.items())
            print(f"wall {wall:.2f} main {cpu1 - cpu:.2f} rq {wait1 - wait:.2f} est {wall - (wait1 - wait):.2f} | {cells}", flush=True)
    finally:
        shutil.rmtree(base, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
