"""Is every object of a single camera view found once? (perception only, real YCB meshes)

Builds the scenes of ``bench_completion.py --all`` (every shared YCB object once per seed: three
scenes of five, layouts table, counter, table), writes each as one organized Kinect-like view and
runs only load, planes and segment (``_detect_only.yaml``). Per true object: its pixels, how many
segments hold more than 10 % of them ("found"), which segment holds most and its point IoU with the
object, who takes the rest (support, noise, another true object), and, for an object not found once
or found with IoU < 0.5, why (:func:`failure_cause`). Run:

    .venv/bin/python bench/bench_view_objects.py [--seeds 0 1 2] [--all-rows]
"""

from __future__ import annotations

import argparse
import resource
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_completion import all_objects  # noqa: E402

from realsim.errors import InputError  # noqa: E402
from realsim.perception.pcd_io import read_pcd  # noqa: E402
from realsim.pipeline import run_pipeline  # noqa: E402
from realsim.synth import SceneSpec, make_scene, write_organized_view  # noqa: E402

DETECT = Path(__file__).resolve().parent / "_detect_only.yaml"
SHARE = 0.1  # a segment holding more than this share of an object's pixels is a piece of it (as bench_completion)
JUMP = 0.008  # m: image neighbours farther apart lie across a depth jump (SegmentParams.jump_distance)
HEIGHT, WIDTH = 480, 640  # the organized view's image


def failure_cause(gt_ids: np.ndarray, pred: np.ndarray, points: np.ndarray, obj: int, shape: tuple[int, int] = (HEIGHT, WIDTH),
                  jump: float = JUMP) -> str:
    """Why true object ``obj`` (``gt_ids`` per pixel) is not one segment of ``pred`` (0 support, -1 noise,
    k > 0 segments) alone, or "" when it is: "hidden" (no pixel in view); "split at a fold" (its two
    largest pieces are image neighbours within ``jump``, m, on at least half their border: the surface goes
    on across it), "split at a depth jump" (mostly farther apart), "parted by a nearer object" (no
    image neighbours at all); "part taken by a neighbour" (a piece of it lies in a segment that is mostly
    another true object's); "merged with a neighbour" (its best segment holds another true object's
    pixels, at least ``SHARE`` of its own); "absorbed by the support" or "dropped as too small" (no
    segment holds ``SHARE`` of it: most of the rest is support, or noise)."""
    mine = gt_ids == obj
    total = int(mine.sum())
    if total == 0:
        return "hidden"
    ids, counts = np.unique(pred[mine & (pred > 0)], return_counts=True)
    pieces = ids[counts > SHARE * total][np.argsort(-counts[counts > SHARE * total], kind="stable")]
    if len(pieces) == 0:
        return "absorbed by the support" if np.count_nonzero(pred[mine] == 0) >= np.count_nonzero(pred[mine] < 0) else "dropped as too small"
    if len(pieces) >= 2:  # a piece that holds more of other true objects than of this one is theirs
        own = [k for k in pieces if np.count_nonzero((pred == k) & mine) >= np.count_nonzero((pred == k) & ~mine & (gt_ids > 0))]
        if len(own) < len(pieces) and len(own) <= 1:
            return "part taken by a neighbour"
        pieces = np.asarray(own)
        image = np.where(mine, pred, 0).reshape(shape)
        xyz = points.reshape(*shape, 3)
        linked = pairs = 0
        for axis in (0, 1):
            here, there = (image[:-1], image[1:]) if axis == 0 else (image[:, :-1], image[:, 1:])
            p, q = (xyz[:-1], xyz[1:]) if axis == 0 else (xyz[:, :-1], xyz[:, 1:])
            border = ((here == pieces[0]) & (there == pieces[1])) | ((here == pieces[1]) & (there == pieces[0]))
            with np.errstate(invalid="ignore"):
                near = np.linalg.norm(p - q, axis=-1) <= jump
            linked += int(np.count_nonzero(border & near))
            pairs += int(np.count_nonzero(border))
        return "parted by a nearer object" if not pairs else "split at a fold" if 2 * linked >= pairs else "split at a depth jump"
    best = pred == pieces[0]
    others = np.count_nonzero(best & ~mine & (gt_ids > 0))
    return "merged with a neighbour" if others >= SHARE * total else ""


def scene_rows(seed: int, layout: str, objects: tuple[str, ...], root: Path) -> list[dict]:
    """Per true object of one scene: pixels, pieces, best segment's IoU and where the rest went."""
    scene = make_scene(SceneSpec(layout=layout, objects=objects, n_objects=len(objects), stacked=True, touching=True, seed=seed))
    path = root / f"{layout}{seed}.pcd"
    form = write_organized_view(scene, path, seed=seed)
    gt = read_pcd(path).labels
    gt_ids = np.where(gt >= 10, gt // 10, 0)
    pred = run_pipeline(path, pipeline=DETECT).labels
    points = read_pcd(path).points
    names = {o.id: o.name for o in scene.objects}
    rows = []
    for obj in scene.objects:
        if obj.name in form["out_of_view"]:
            continue
        mine = gt_ids == obj.id
        got = pred[mine]
        ids, counts = np.unique(got[got > 0], return_counts=True)
        pieces = int(np.count_nonzero(counts > SHARE * mine.sum()))
        iou, best_share, rest = 0.0, 0.0, ""
        if len(ids):
            best = int(ids[np.argmax(counts)])
            seg = pred == best
            iou = float(np.count_nonzero(seg & mine) / np.count_nonzero(seg | mine))
            best_share = float(counts.max() / mine.sum())
            others = gt_ids[seg & ~mine]
            if len(others):
                o_ids, o_n = np.unique(others, return_counts=True)
                rest = ", ".join(f"{names.get(int(i), 'support')[:14]} {n}" for i, n in zip(o_ids, o_n) if n >= 50)
        lost = f"support {np.count_nonzero(got == 0)}, noise {np.count_nonzero(got < 0)}, segments {sorted(counts.tolist(), reverse=True)[:4]}"
        rows.append({"seed": seed, "layout": layout, "name": obj.name, "pixels": int(mine.sum()), "found": pieces, "iou": iou,
                     "share": best_share, "lost": lost, "takes": rest, "cause": failure_cause(gt_ids, pred, points, obj.id)})
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", nargs="*", type=int, default=[0, 1, 2])
    parser.add_argument("--all-rows", action="store_true", help="print every object, not only the failures")
    args = parser.parse_args()
    rows, skipped = [], []
    cpu = resource.getrusage(resource.RUSAGE_SELF)
    with tempfile.TemporaryDirectory() as tmp:
        for seed in args.seeds:
            for layout, objects in all_objects(seed):
                try:
                    rows += scene_rows(seed, layout, objects, Path(tmp))
                except InputError as error:
                    skipped.append(f"seed {seed} {layout} ({error})")
    used = resource.getrusage(resource.RUSAGE_SELF)
    print(f"{'seed':>4s} {'layout':8s} {'object':26s} {'pixels':>7s} {'found':>5s} {'IoU':>5s} {'share':>5s}  cause: lost / best segment also holds")
    for r in rows:
        if args.all_rows or r["found"] != 1 or r["iou"] < 0.5:
            print(f"{r['seed']:4d} {r['layout']:8s} {r['name']:26s} {r['pixels']:7d} {r['found']:5d} {r['iou']:5.2f} {r['share']:5.2f}  "
                  f"{r['cause'] or '-'}: {r['lost']} / {r['takes'] or '-'}")
    once = sum(r["found"] == 1 for r in rows)
    good = sum(r["found"] == 1 and r["iou"] >= 0.5 for r in rows)
    print(f"\n{len(rows)} objects: found once {once}/{len(rows)}, found once with IoU >= 0.5 {good}/{len(rows)}, "
          f"mean IoU {np.mean([r['iou'] for r in rows]):.3f}; cpu {used.ru_utime + used.ru_stime - cpu.ru_utime - cpu.ru_stime:.0f} s")
    causes: dict[str, int] = {}
    for r in rows:
        if r["found"] != 1 or r["iou"] < 0.5:
            causes[r["cause"] or "found once, IoU < 0.5"] = causes.get(r["cause"] or "found once, IoU < 0.5", 0) + 1
    if causes:
        print("causes: " + ", ".join(f"{k} {n}" for k, n in sorted(causes.items(), key=lambda kv: (-kv[1], kv[0]))))
    if skipped:
        print("skipped: " + "; ".join(skipped))


if __name__ == "__main__":
    main()
