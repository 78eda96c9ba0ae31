"""Scan-to-simulation benchmark on the labelled Kinect scenes (mOSD) and the other PCL scans.

Prints, per scene: conversion time (in process, imports excluded, output written; wall and this
process's CPU time, the fastest of ``--repeat``, and the CPU of the forked helpers
(``+fork``, realsim.forkmap) in that run; every conversion is run, none restored from the
warm-rerun store: ``REALSIM_REUSE=0``), table-plane
error against the plane fitted to the ground-truth table points, object count, mean
Hungarian-matched point IoU, and the 2 s rest check; then the same quality figures and time
for the plain Open3D baseline (RANSAC plane + DBSCAN). Run:

    .venv/bin/python bench/bench_scan.py [--repeat 3]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_segmentation import open3d_baseline  # noqa: E402

from realsim.metrics import matched_iou, mosd_object_ids, plane_error  # noqa: E402
from realsim.perception.pcd_io import read_pcd  # noqa: E402
from realsim.pipeline import convert  # noqa: E402

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "pcl_scenes"
MOSD = ["test0", "test31", "test45", "test55"]
OTHERS = ["table_scene_mug_stereo_textured", "milk_cartoon_all_small_clorox", "region_growing_rgb_tutorial"]


def children_cpu() -> float:
    """CPU seconds of this process's finished children (forkmap's helpers share the conversion)."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run(repeat: int, scenes: list[str]) -> None:
    rows, all_ious, base_ious = [], [], []
    right = base_right = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name in scenes:
            path = DATA / ("mOSD" if name in MOSD else "") / f"{name}.pcd"
            times, cpu, helper_cpu = [], [], []
            for r in range(repeat):
                started, cpu_started, helpers_started = time.perf_counter(), time.process_time(), children_cpu()
                convert(path, Path(tmp) / f"{name}_{r}")
                times.append(time.perf_counter() - started)
                cpu.append(time.process_time() - cpu_started)
                helper_cpu.append(children_cpu() - helpers_started)
            out = Path(tmp) / f"{name}_0"
            record = json.loads((out / "scene.json").read_text())
            row = {"scene": name, "time": min(times), "cpu": min(cpu), "helper_cpu": helper_cpu[int(np.argmin(cpu))], "objects": len(record["objects"]), "rest_mm": record["settle"]["max_displacement"] * 1000}
            if name in MOSD:
                data = read_pcd(path)
                t = np.asarray(record["capture"]["input_to_world"])
                world = data.points @ t[:3, :3].T + t[:3, 3]
                table = max((p for p in record["planes"] if p["kind"] != "floor"), key=lambda p: p["inlier_count"])
                dist, angle = plane_error(world[(data.labels >= 1) & (data.labels <= 9)], np.asarray(table["normal"]), table["height"])
                gt = mosd_object_ids(data.labels)
                ious, _ = matched_iou(np.load(out / "labels.npy"), gt)
                n_gt = len(np.unique(gt[gt > 0]))
                all_ious.extend(ious)
                right += row["objects"] == n_gt
                started = time.perf_counter()
                base_labels = open3d_baseline(data.points, seed=0)
                base_time = time.perf_counter() - started
                b_ious, _ = matched_iou(base_labels, gt)
                base_ious.extend(b_ious)
                n_base = len(np.unique(base_labels[base_labels > 0]))
                base_right += n_base == n_gt
                row.update(gt=n_gt, plane_mm=dist * 1000, plane_deg=angle, iou=float(np.mean(ious)), base_objects=n_base,
                           base_iou=float(np.mean(b_ious)), base_time=base_time)
            rows.append(row)
    print(f"{'scene':34s} {'wall s':>7s} {'cpu s':>6s} {'+fork':>6s} {'plane mm':>8s} {'deg':>5s} {'gt':>3s} {'found':>5s} {'IoU':>5s} {'rest mm':>7s} | {'O3D found':>9s} {'O3D IoU':>7s} {'O3D s':>6s}")
    for r in rows:
        if "gt" in r:
            print(f"{r['scene']:34s} {r['time']:7.2f} {r['cpu']:6.2f} {r['helper_cpu']:6.2f} {r['plane_mm']:8.2f} {r['plane_deg']:5.2f} {r['gt']:3d} {r['objects']:5d} {r['iou']:5.3f} {r['rest_mm']:7.2f} | {r['base_objects']:9d} {r['base_iou']:7.3f} {r['base_time']:6.2f}")
        else:
            print(f"{r['scene']:34s} {r['time']:7.2f} {r['cpu']:6.2f} {r['helper_cpu']:6.2f} {'':8s} {'':5s} {'':3s} {r['objects']:5d} {'':5s} {r['rest_mm']:7.2f} |")
    n_mosd = sum(name in MOSD for name in scenes)
    print(f"\nmOSD: mean IoU over {len(all_ious)} objects {np.mean(all_ious):.3f} (Open3D baseline {np.mean(base_ious):.3f}); "
          f"right count in {right}/{n_mosd} scenes (baseline {base_right}/{n_mosd}); slowest conversion {max(r['time'] for r in rows):.2f} s wall, "
          f"{max(r['cpu'] for r in rows):.2f} s CPU")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="conversions per scene; the fastest is reported")
    parser.add_argument("--scenes", nargs="+", choices=MOSD + OTHERS, help="a subset of the scans (default: all)")
    os.environ["REALSIM_REUSE"] = "0"  # a rerun restored from the store would time the copy, not the conversion
    args = parser.parse_args()
    run(args.repeat, args.scenes or MOSD + OTHERS)
