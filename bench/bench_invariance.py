"""Does detection depend on how a capture is posed or encoded? One sampled cloud of a generated
scene, written as is and turned about up, moved, and with its colours quantized or noised; each
converted (load, planes, segment) and compared with the plain one.

A variant is invariant when it finds as many objects as the plain cloud and its labels match the
plain labels with mean IoU >= ``--iou`` (Hungarian-matched, the plain objects as reference).
Also printed: F1 against the ground truth (IoU >= 0.5 matches), plain and per variant, and the
point spacing the loader measured (every working length of detection follows it). ``--fine`` adds
shifts of 1 and 3 mm, well under one working cell: a detector that changes with them depends on
where its grids fall, not on the spacing measure.

    .venv/bin/python bench/bench_invariance.py [--scenes table:72,counter:73,floor:74] [--points 100000]
        [--only yaw] [--iou 0.9] [--fine]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

from realsim.metrics import matched_iou
from realsim.pipeline import run_pipeline
from realsim.synth import SceneSpec, make_scene, sample_cloud
from realsim.synth.exports import capture_transform, write_cloud
from realsim.synth.forms import apply

DETECT = Path(__file__).resolve().parent / "_detect_only.yaml"
YAWS = (30.0, 90.0, 145.0, 260.0)
SHIFTS = ((1.0, 0.0, 0.0), (0.37, -0.81, 0.25), (-3.3, 7.1, 0.0))
FINE_SHIFTS = ((0.001, 0.0, 0.0), (0.003, 0.003, 0.003))


def variants(fine: bool = False) -> dict[str, tuple[np.ndarray, str | None]]:
    """Name -> (world -> capture transform, colour change); ``fine`` adds the sub-cell shifts."""
    v: dict[str, tuple[np.ndarray, str | None]] = {"plain": (np.eye(4), None)}
    if fine:
        v |= {f"shift {s}": (capture_transform(offset_m=s), None) for s in FINE_SHIFTS}
    v |= {f"yaw {y:g}": (capture_transform(yaw_deg=y), None) for y in YAWS}
    v |= {f"shift {s}": (capture_transform(offset_m=s), None) for s in SHIFTS}
    v |= {"colour noise 2": (np.eye(4), "noise"), "colour 6 bit": (np.eye(4), "quantize"),
          "colour 6 bit + yaw 30": (capture_transform(yaw_deg=30.0), "quantize")}
    return v


def recolour(cols: np.ndarray, how: str | None, seed: int) -> np.ndarray:
    """Colours as a video codec leaves them: +-2 levels of noise, or 6 bits a channel."""
    c = cols.astype(np.int64)
    if how == "noise":
        c = c + np.random.default_rng(seed).integers(-2, 3, c.shape)
    elif how == "quantize":
        c = (c // 4) * 4 + 2
    return np.clip(c, 0, 255).astype(np.uint8)


def convert(path: Path) -> tuple[np.ndarray, float]:
    """Per-point labels (0 where none) and the point spacing (m) the loader measured."""
    scene = run_pipeline(path, pipeline=DETECT, overrides={})
    if scene.labels is None:
        raise RuntimeError(f"{path}: the segment stage gave no labels")
    labels = scene.labels
    return labels, float(scene.capture.point_spacing or float("nan"))


def f1(pred: np.ndarray, truth: np.ndarray) -> float:
    ious, _ = matched_iou(pred, truth)
    found = len(np.unique(pred[pred > 0]))
    return 2 * int((ious >= 0.5).sum()) / max(len(ious) + found, 1)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", default="table:72,counter:73,floor:74", help="layout:seed, comma separated")
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--only", default="", help="the variants whose name holds this text (and the plain one)")
    parser.add_argument("--iou", type=float, default=0.9, help="mean IoU to the plain labels that counts as the same")
    parser.add_argument("--fine", action="store_true", help="also shift by 1 and 3 mm (under one working cell)")
    args = parser.parse_args()
    todo = {k: v for k, v in variants(args.fine).items() if k == "plain" or args.only in k}
    same = total = 0
    cpu = time.process_time()
    with tempfile.TemporaryDirectory() as tmp:
        for key in args.scenes.split(","):
            layout, _, seed = key.partition(":")
            gt = make_scene(SceneSpec(layout=layout, objects=None, seed=int(seed)))
            pts, cols, truth = sample_cloud(gt, args.points, seed=1)
            plain = None
            for name, (t, colour) in todo.items():
                path = write_cloud(Path(tmp) / f"{layout}_{seed}_{len(name)}_{abs(hash(name))}.ply", apply(t, pts),
                                   recolour(cols, colour, int(seed)), "ply_double")
                labels, spacing = convert(path)
                count = len(np.unique(labels[labels > 0]))
                if plain is None:
                    plain, plain_count = labels, count
                    print(f"{key:11s} {name:22s} {count} objects, F1 {f1(labels, truth):.2f}, spacing {spacing * 1000:.2f} mm",
                          flush=True)
                    continue
                ious, _ = matched_iou(labels, plain)
                iou = float(ious.mean()) if len(ious) else 1.0
                ok = count == plain_count and iou >= args.iou
                same, total = same + ok, total + 1
                print(f"{key:11s} {name:22s} {count} objects, IoU to plain {iou:.3f}, F1 {f1(labels, truth):.2f}, "
                      f"spacing {spacing * 1000:.2f} mm  {'same' if ok else 'DIFFERENT'}", flush=True)
    print(f"\ninvariant {same}/{total} variants; {time.process_time() - cpu:.1f} s CPU")


if __name__ == "__main__":
    main()
