"""How much detection depends on the measured point spacing: the same clouds, the spacing scaled.

Every working length of detection (voxels, supervoxels, cut gates) follows the spacing that
``point_spacing`` measures on the capture. A robust detector gives nearly the same objects when
that measure is off by 10-25 %, as it is between poses of one capture (its grid is laid on the
input's axes). Each layout is written as sampled clouds (realsim.synth), converted with the measured
spacing times each factor (load, planes, segment) and scored as in bench_captures.py:

    .venv/bin/python bench/bench_spacing.py [--factors 0.8,0.9,1,1.1,1.25]
        [--layouts table,counter,floor,table:62,counter:64,floor:66] [--densities 50000,200000]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_captures import bench_scene, evaluate  # noqa: E402

import realsim.perception.capture as capture_module  # noqa: E402
from realsim.synth import write_point_cloud  # noqa: E402

MEASURED = capture_module.point_spacing


def scaled_spacing(factor: float):  # noqa: ANN201 - a point_spacing stand-in
    """``point_spacing`` times ``factor``."""
    return lambda points, seed=0: MEASURED(points, seed) * factor


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--factors", default="0.8,0.9,1,1.1,1.25")
    parser.add_argument("--layouts", default="table,counter,floor,table:62,counter:64,floor:66")
    parser.add_argument("--densities", default="50000,200000")
    args = parser.parse_args()
    factors = [float(f) for f in args.factors.split(",")]
    densities = [int(d) for d in args.densities.split(",")]
    results: dict[tuple[float, int], list[tuple[float, float, int, int]]] = {}
    with tempfile.TemporaryDirectory() as tmp:
        clouds = []
        for key in args.layouts.split(","):
            gt = bench_scene(key)
            for count in densities:
                path = Path(tmp) / f"{key.replace(':', '_')}_{count}.ply"
                entry, ids = write_point_cloud(gt, path, count)
                clouds.append((key, count, gt, path, entry["capture_to_world"], ids))
        for factor in factors:
            capture_module.point_spacing = scaled_spacing(factor)
            for key, count, gt, path, to_world, ids in clouds:
                row = evaluate(gt, path, to_world, f"cloud {count // 1000}k", gt_ids=ids)
                results.setdefault((factor, count), []).append((row.f1, row.iou, row.n_true, row.n_found))
                print(f"x{factor:<5g} {key:12s} {count // 1000:5d}k  true {row.n_true}  found {row.n_found}  "
                      f"F1 {row.f1:.3f}  IoU {row.iou:.3f}", flush=True)
    capture_module.point_spacing = MEASURED
    print(f"\n{'factor':>6s} " + " ".join(f"{f'{c // 1000}k F1':>8s} {f'{c // 1000}k IoU':>8s}" for c in densities))
    for factor in factors:
        cells = []
        for count in densities:
            rows = results[(factor, count)]
            cells.append(f"{np.mean([r[0] for r in rows]):8.3f} {np.mean([r[1] for r in rows]):8.3f}")
        print(f"{factor:6g} " + " ".join(cells))


if __name__ == "__main__":
    main()
