"""Full conversion time per stage, cold: the four mOSD scans, two 640 x 480 PCL scans, a 1 M-point cloud, a 30-frame RGB-D sweep.

Each input is converted (``realsim.convert``, every stage, written) in its own fresh Python
process with an empty cache except the Panda's meshes (input-independent, converted once at
the start), after the libraries are imported (an in-process measure: a long-lived process pays
imports once). Two tables show wall and CPU seconds per stage, the total wall and CPU seconds of the
converting process, ``main`` its main thread's CPU (the critical path: helpers, pool workers and
MuJoCo's compile threads run beside it), ``cpu+`` its CPU with that of its forked helpers and pool workers (all cores'
work: on an idle 2-core machine wall is about the larger of ``cpu`` and ``cpu+`` / 2), the warm
rerun (the same conversion again into a new folder: restored from the cache), peak memory, the
output size, the first hex digits of scene.xml's SHA-256 and of every output file's
(``files``: scene.json without its timings; byte-identity before/after a change).

    .venv/bin/python bench/bench_convert_time.py [--only test0,cloud1m] [--workers N] [--mesh] [--repeat N]

``--repeat N`` converts each input N times (each cold) and keeps the run of least ``cpu+``;
``--outputs DIR`` keeps each output folder as ``DIR/<input>`` (for ``diff -r``).

Generated inputs (realsim.synth, seed 0) are written under a temporary folder; ``--keep DIR``
writes them there once and reuses them.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

DATA = Path(__file__).resolve().parents[2] / "shared" / "data"
PCL_SCANS = {"region": "region_growing_rgb_tutorial", "milk": "milk_cartoon_all_small_clorox"}  # name -> pcl_scenes/<stem>.pcd
STAGE_ORDER = ("load", "planes", "segment", "complete", "objects", "compose", "robot", "settle", "write")

CHILD = r"""
import hashlib, json, os, resource, sys, time
from pathlib import Path
import mujoco, numpy, open3d, scipy, trimesh  # noqa: F401  (imports are not the conversion)
from dataclasses import replace
from realsim.pipeline import convert
from realsim.stages import STAGES
cpu_s = {}
def timed(name, run):
    def wrapped(scene, params):
        started = time.process_time()
        try:
            return run(scene, params)
        finally:
            cpu_s[name] = time.process_time() - started
    return wrapped
for name, stage in list(STAGES.items()):
    STAGES[name] = replace(stage, run=timed(name, stage.run))
def children_cpu():
    used = resource.getrusage(resource.RUSAGE_CHILDREN)  # forked helpers and pool workers, once waited for
    return used.ru_utime + used.ru_stime
def files_digest(folder):
    h = hashlib.sha256()
    for f in sorted(p for p in Path(folder).rglob('*') if p.is_file()):
        data = f.read_bytes()
        if f.name == 'scene.json':
            record = json.loads(data)
            record.pop('timings_s', None)
            data = json.dumps(record, sort_keys=True).encode()
        h.update(f"{f.relative_to(folder)}\0".encode() + hashlib.sha256(data).digest())
    return h.hexdigest()
src, out, warm_out = sys.argv[1:4]
started, cpu, main, helpers = time.perf_counter(), time.process_time(), time.thread_time(), children_cpu()
scene = convert(src, out)
wall, cpu, main = time.perf_counter() - started, time.process_time() - cpu, time.thread_time() - main
import multiprocessing.forkserver as forkserver
forkserver._forkserver._stop()  # a pool's workers are the forkserver's children: counted once it exits
cpu_all = cpu + children_cpu() - helpers
started = time.perf_counter()
convert(src, warm_out)
warm = time.perf_counter() - started
hwm = next(int(l.split()[1]) for l in open('/proc/self/status') if l.startswith('VmHWM'))
size = sum(p.stat().st_size for p in Path(out).rglob('*') if p.is_file())
print(json.dumps({"timings": scene.timings, "cpu_s": cpu_s, "wall": wall, "cpu": cpu, "main": main, "cpu_all": cpu_all, "warm": warm,
                  "peak_mb": hwm // 1024, "out_mb": size / 1e6, "objects": len(scene.objects),
                  "sha": hashlib.sha256((Path(out) / 'scene.xml').read_bytes()).hexdigest(), "files": files_digest(out)}))
"""


def generated_inputs(folder: Path, mesh: bool, data: Path) -> dict[str, Path]:
    """The counter scene as a 1 M-point cloud, the table scene as a 30-frame sweep (and mesh)."""
    os.environ.setdefault("REALSIM_YCB_ROOT", str(data / "ycb_google16k"))
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from bench_captures import SCENES

    from realsim.synth import SceneSpec, make_scene, write_mesh, write_point_cloud, write_rgbd_sequence

    out = {"cloud1m": folder / "counter_1m.ply", "rgbd30": folder / "table_seq"}
    if mesh:
        out["mesh"] = folder / "table_mesh.glb"
    if not out["cloud1m"].exists():
        write_point_cloud(make_scene(SceneSpec(layout="counter", objects=SCENES["counter"], seed=0)), out["cloud1m"], 1_000_000)
    table = make_scene(SceneSpec(layout="table", objects=SCENES["table"], seed=0))
    if not (out["rgbd30"] / "odometry.csv").exists():
        write_rgbd_sequence(table, out["rgbd30"], 30)
    if mesh and not out["mesh"].exists():
        write_mesh(table, out["mesh"])
    return out


def robot_cache(folder: Path) -> Path:
    """A cache holding only the Panda's converted meshes (what every conversion shares)."""
    root = folder / "robot_cache"
    if not root.exists():
        code = "from realsim.robot.model import panda_spec; panda_spec()"
        subprocess.run([sys.executable, "-c", code], check=True, env={**os.environ, "REALSIM_CACHE": str(root)})
    return root


def convert_cold(name: str, source: Path, work: Path, cache_seed: Path, workers: int | None) -> dict[str, Any]:
    """Convert ``source`` in a fresh process with a cold cache; the child's JSON report."""
    run = work / name
    shutil.rmtree(run, ignore_errors=True)
    shutil.copytree(cache_seed, run / "cache")
    env = {**os.environ, "REALSIM_CACHE": str(run / "cache")}
    if workers:
        env["REALSIM_WORKERS"] = str(workers)
    out = subprocess.run([sys.executable, "-c", CHILD, str(source), str(run / "out"), str(run / "warm")],
                         capture_output=True, text=True, env=env)
    if out.returncode:
        raise RuntimeError(f"{name}: {out.stderr.strip().splitlines()[-1] if out.stderr.strip() else out.returncode}")
    report: dict[str, Any] = json.loads(out.stdout.strip().splitlines()[-1])
    return report


def print_table(rows: list[tuple[str, dict[str, Any]]], key: str) -> None:
    head = " ".join(f"{s[:8]:>8s}" for s in STAGE_ORDER)
    print(f"{'input':8s} {head} {'wall':>6s} {'main':>6s} {'cpu':>6s} {'cpu+':>6s} {'warm':>5s} {'peakMB':>6s} {'outMB':>5s} {'obj':>3s}"
          "  scene.xml sha256  files sha256")
    for name, r in rows:
        t = r[key]
        cells = " ".join(f"{t.get(s, float('nan')):8.2f}" for s in STAGE_ORDER)
        print(f"{name:8s} {cells} {r['wall']:6.2f} {r['main']:6.2f} {r['cpu']:6.2f} {r['cpu_all']:6.2f} {r['warm']:5.2f} {r['peak_mb']:6d} "
              f"{r['out_mb']:5.1f} {r['objects']:3d}  {r['sha'][:16]}  {r['files'][:16]}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default="", help="comma-separated input names (test0, test31, test45, test55, region, milk, cloud1m, rgbd30, mesh)")
    parser.add_argument("--workers", type=int, default=None, help="REALSIM_WORKERS for the conversions")
    parser.add_argument("--mesh", action="store_true", help="also the table scene as a merged glTF mesh")
    parser.add_argument("--data", type=Path, default=DATA, help="the shared data folder (mOSD scans)")
    parser.add_argument("--keep", type=Path, default=None, help="write the generated inputs here once and reuse them")
    parser.add_argument("--repeat", type=int, default=1, help="cold conversions per input; the one of least cpu+ is shown")
    parser.add_argument("--outputs", type=Path, default=None, help="keep each output folder as DIR/<input>")
    args = parser.parse_args()
    only = set(filter(None, args.only.split(",")))
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = Path(tmp_name)
        inputs_dir = args.keep or tmp / "inputs"
        inputs_dir.mkdir(parents=True, exist_ok=True)
        inputs = {f"test{i}": args.data / "pcl_scenes" / "mOSD" / f"test{i}.pcd" for i in (0, 31, 45, 55)}
        inputs.update({name: args.data / "pcl_scenes" / f"{stem}.pcd" for name, stem in PCL_SCANS.items()})
        wanted_generated = not only or bool(only & {"cloud1m", "rgbd30", "mesh"})
        if wanted_generated:
            inputs.update(generated_inputs(inputs_dir, args.mesh or "mesh" in only, args.data))
        cache_seed = robot_cache(inputs_dir if args.keep else tmp)
        rows = []
        for name, source in inputs.items():
            if only and name not in only:
                continue
            runs = [convert_cold(name, source, tmp, cache_seed, args.workers) for _ in range(args.repeat)]
            if len({r["files"] for r in runs}) > 1:
                print(f"[{name}: output files differ between runs]", flush=True)
            rows.append((name, min(runs, key=lambda r: r["cpu_all"])))
            if args.outputs:
                shutil.rmtree(args.outputs / name, ignore_errors=True)
                shutil.copytree(tmp / name / "out", args.outputs / name)
            cpus = ", ".join(f"{r['cpu_all']:.2f}" for r in runs)
            print(f"[{name} done: cpu+ {cpus}]", flush=True)
        print("stage wall seconds (the machine's other load counts here)")
        print_table(rows, "timings")
        print("\nstage CPU seconds of the converting process")
        print_table(rows, "cpu_s")
        digest = hashlib.sha256("".join(r["sha"] for _, r in rows).encode()).hexdigest()[:16]
        print(f"\nall scene.xml digests: {digest}")


if __name__ == "__main__":
    main()
