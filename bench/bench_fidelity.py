"""Does the simulated scene look and measure like the captured one? (the four mOSD scans)

Each scan is converted, the written scene is rendered at keyframe ``initial`` from camera
``capture`` with the intrinsics fitted from the organized cloud, and compared with the capture's
own RGB-D on every pixel with captured depth, robot pixels masked: depth median error, share
within 1 cm, colour PSNR and SSIM (:mod:`realsim.fidelity`). Also printed: conversion time (in
process), output folder size, settling drift (the rest check after the keyframe), how far an object
moved while settling (completed pose to keyframe ``initial``, the largest), object collision pieces (mesh files). Run:

    .venv/bin/python bench/bench_fidelity.py [--scans test0 test55] [--keep out/fidelity] [--overrides '{"complete": {...}}']
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

import mujoco
import numpy as np
from PIL import Image

from realsim.fidelity import capture_rgbd, compare, render_rgbd
from realsim.perception.intrinsics import fit_intrinsics
from realsim.perception.pcd_io import read_pcd
from realsim.pipeline import convert

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "pcl_scenes" / "mOSD"
SCANS = ["test0", "test31", "test45", "test55"]


def folder_mb(folder: Path) -> float:
    return sum(p.stat().st_size for p in folder.rglob("*") if p.is_file()) / 1e6


def measure(name: str, out: Path, overrides: dict | None = None) -> dict:
    path = DATA / f"{name}.pcd"
    started = time.perf_counter()
    convert(path, out, overrides=overrides)
    seconds = time.perf_counter() - started
    record = json.loads((out / "scene.json").read_text())
    data = read_pcd(path)
    intr = fit_intrinsics(data.points, data.grid_shape)
    transform = np.asarray(record["capture"]["input_to_world"])
    scale = float(np.cbrt(abs(np.linalg.det(transform[:3, :3]))))
    capture = capture_rgbd(data.points, data.colors, data.grid_shape, scale)
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    render, robot = render_rgbd(model, intr)
    fid = compare(render, capture, exclude=robot)
    Image.fromarray((np.hstack([render.rgb, capture.rgb]) * 255).astype(np.uint8)).save(out.parent / f"{name}_fidelity.png")
    return {"scan": name, "fid": fid, "seconds": seconds, "mb": folder_mb(out), "drift_mm": record["settle"]["max_displacement"] * 1000,
            "settled_mm": 1000 * max(record["settle"].get("moved_during_settling", {}).values(), default=0.0),
            "robot_px": int(robot.sum()), "fx": intr.fx, "pieces": len(list((out / "assets").glob("*_collision_*.stl")))}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scans", nargs="*", default=SCANS)
    parser.add_argument("--keep", type=Path, default=None, help="write the outputs (and <scan>_fidelity.png: render and capture side by side) here")
    parser.add_argument("--overrides", type=json.loads, default=None, help="stage parameters as JSON, as realsim.convert takes them (an A/B in one tree)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        root = args.keep or Path(tmp)
        rows = [measure(name, root / name, args.overrides) for name in args.scans]
    print(f"{'scan':8s} {'pixels':>7s} {'depth med mm':>12s} {'<=1cm %':>8s} {'PSNR dB':>8s} {'SSIM':>6s} | {'convert s':>9s} {'MB':>6s} {'drift mm':>8s} {'settle mm':>9s} {'robot px':>8s} {'pieces':>6s}")
    for r in rows:
        f = r["fid"]
        print(f"{r['scan']:8s} {f.pixels:7d} {f.depth_median_mm:12.2f} {100 * f.within_1cm:8.1f} {f.psnr_db:8.2f} {f.ssim:6.3f} | "
              f"{r['seconds']:9.2f} {r['mb']:6.1f} {r['drift_mm']:8.2f} {r['settled_mm']:9.2f} {r['robot_px']:8d} {r['pieces']:6d}")
    fids = [r["fid"] for r in rows]
    print(f"\nmean: depth median {np.mean([f.depth_median_mm for f in fids]):.2f} mm, within 1 cm {100 * np.mean([f.within_1cm for f in fids]):.1f} %, "
          f"PSNR {np.mean([f.psnr_db for f in fids]):.2f} dB, SSIM {np.mean([f.ssim for f in fids]):.3f}; "
          f"slowest conversion {max(r['seconds'] for r in rows):.2f} s, largest output {max(r['mb'] for r in rows):.1f} MB")


if __name__ == "__main__":
    main()
