"""Every capture form against generated ground truth (realsim.synth): supports, objects, units, time, memory.

Three layouts (table, counter, floor) of real YCB scans, each with a stacked and a touching pair,
written as an organized Kinect view, a fused 30-frame RGB-D sweep, sampled clouds at several
densities and a merged glTF mesh (Y-up, millimetres); each is converted in process (load, planes,
segment) and compared in the ground-truth frame:

- supports: height error and tilt of the detected plane matching each ground-truth support top;
  "extra" counts detected non-floor supports that match no support top (an underside, a slab,
  an object top);
- objects: Hungarian-matched point IoU (ground truth = the object owning the nearest true face),
  found/true counts, F1 of matches with IoU >= 0.5;
- units: the 200k cloud written in m, cm and mm (no flags) must give the same world within 1 mm;
  the cloud scaled by 1e6 must fail with exit-2 InputError naming --units, in seconds;
- time: load+planes+segment per form; the full conversion (with objects, robot, settle) of the
  1 M cloud and the mesh with --full; peak memory of the 10 M-point conversion (a subprocess).

    .venv/bin/python bench/bench_captures.py [--quick] [--full] [--layouts table,counter,floor]
        [--forms view,cloud,mesh,sequence] [--densities 50000,200000] [--no-big]

A layout written ``name:seed`` (``table:7``) is a held-out scene: four objects drawn from the
generator's default set with that seed, a stacked and a touching pair (seed 0: the fixed sets).
"""

from __future__ import annotations

import argparse
import resource
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from realsim.errors import InputError
from realsim.metrics import matched_iou
from realsim.pipeline import convert, run_pipeline
from realsim.synth import SceneSpec, SynthScene, make_scene, write_mesh, write_organized_view, write_point_cloud, write_rgbd_sequence

SCENES = {
    "table": ("003_cracker_box", "077_rubiks_cube", "005_tomato_soup_can", "025_mug"),
    "counter": ("010_potted_meat_can", "012_strawberry", "021_bleach_cleanser", "024_bowl"),
    "floor": ("003_cracker_box", "006_mustard_bottle", "019_pitcher_base", "035_power_drill"),
    "rooms": ("003_cracker_box", "005_tomato_soup_can", "006_mustard_bottle", "024_bowl", "025_mug", "077_rubiks_cube"),
}
DETECT = Path(__file__).resolve().parent / "_detect_only.yaml"


@dataclass
class Row:
    layout: str
    form: str
    seconds: float
    sup_err_mm: float
    sup_tilt_deg: float
    sup_missing: int
    sup_extra: int
    n_true: int
    n_found: int
    f1: float
    iou: float
    note: str = ""
    cpu: float = 0.0  # CPU seconds of load+planes+segment (wall overstates on a loaded machine)


def bench_scene(key: str) -> SynthScene:
    """The scene of a ``--layouts`` entry: ``table`` (the fixed objects) or ``table:7`` (seeded draw)."""
    layout, _, seed = key.partition(":")
    if layout not in SCENES or (seed and not seed.isdigit()):
        raise SystemExit(f"unknown layout {key!r}: use table, counter, floor or rooms, optionally :seed")
    if not seed or int(seed) == 0:
        return make_scene(SceneSpec(layout=layout, objects=SCENES[layout], seed=0))
    return make_scene(SceneSpec(layout=layout, seed=int(seed)))


def _pipeline_file() -> Path:
    """The detection stages only (load, planes, segment): what the quality figures measure."""
    return DETECT


def evaluate(gt: SynthScene, source: Path, capture_to_world: np.ndarray, form: str, gt_ids: np.ndarray | None = None,
             overrides: dict | None = None) -> Row:
    """Convert ``source`` (load, planes, segment) and score it against ``gt``."""
    started, cpu = time.perf_counter(), time.process_time()
    scene = run_pipeline(source, pipeline=_pipeline_file(), overrides=overrides or {})
    seconds, cpu = time.perf_counter() - started, time.process_time() - cpu
    m = scene.capture.input_to_world
    to_gt = np.asarray(capture_to_world) @ np.linalg.inv(m)  # converter world -> ground-truth world
    rot = to_gt[:3, :3] / np.cbrt(np.linalg.det(to_gt[:3, :3]))
    errs, tilts, missing, matched = [], [], 0, set()
    tops = [s for s in gt.supports]
    for s in tops:
        best = None
        for p in scene.planes:
            if not p.observed:
                continue
            c = to_gt @ np.r_[p.rect_center, p.height, 1.0]
            if abs(c[2] - s.height) < 0.05 and (best is None or abs(c[2] - s.height) < abs(best[0])):
                best = (c[2] - s.height, p)
        if best is None:
            if s.kind != "floor" or gt.spec.layout == "floor":
                missing += 1
            continue
        matched.add(best[1].id)
        n = rot @ best[1].normal
        errs.append(abs(best[0]))
        tilts.append(float(np.degrees(np.arccos(np.clip(abs(n[2]) / np.linalg.norm(n), -1, 1)))))
    extra = sum(1 for p in scene.planes if p.observed and p.kind != "floor" and p.id not in matched)
    pts = scene.points
    finite = np.isfinite(pts).all(axis=1)
    if gt_ids is None:
        gt_ids = np.zeros(len(pts), dtype=np.int32)
        world = pts[finite] @ to_gt[:3, :3].T + to_gt[:3, 3]
        gt_ids[finite] = gt.label_points(world)
    pred = scene.labels if scene.labels is not None else np.zeros(len(pts), np.int32)
    ious, _ = matched_iou(pred, gt_ids)
    n_true = len(gt.objects)
    n_found = len(scene.objects)
    tp = int((ious >= 0.5).sum())
    f1 = 2 * tp / max(n_true + n_found, 1)
    return Row(gt.spec.layout, form, seconds, max(errs, default=np.nan) * 1000, max(tilts, default=np.nan), missing, extra,
               n_true, n_found, f1, float(np.mean(ious)) if len(ious) else 0.0, "; ".join(scene.warnings)[:60], cpu)


def print_rows(rows: list[Row]) -> None:
    print(f"{'layout':10s} {'form':16s} {'s':>6s} {'cpu s':>6s} {'sup mm':>6s} {'deg':>5s} {'miss':>4s} {'extra':>5s} {'true':>4s} {'found':>5s} {'F1':>5s} {'IoU':>5s}  warnings")
    for r in rows:
        print(f"{r.layout:10s} {r.form:16s} {r.seconds:6.2f} {r.cpu:6.2f} {r.sup_err_mm:6.2f} {r.sup_tilt_deg:5.2f} {r.sup_missing:4d} {r.sup_extra:5d} "
              f"{r.n_true:4d} {r.n_found:5d} {r.f1:5.2f} {r.iou:5.3f}  {r.note}")


def units_check(gt: SynthScene, tmp: Path) -> list[str]:
    """The same 200k cloud in m, cm and mm: worlds must agree within 1 mm; 1e6 must fail fast."""
    lines, worlds = [], {}
    for units in ("m", "cm", "mm"):
        path = tmp / f"units_{units}.ply"
        write_point_cloud(gt, path, 200_000, units=units, up="+z")
        scene = run_pipeline(path, pipeline=_pipeline_file())
        worlds[units] = (scene.capture.units, scene.capture.input_to_world, scene.planes)
        lines.append(f"  {units:2s}: detected {scene.capture.units} ({scene.capture.units_reason or ''})")
    ref = worlds["m"][1]
    probe = np.array([[0.3, 0.2, 0.8], [-0.5, 0.1, 0.0], [0.0, 0.0, 0.75]])
    for units, scale in (("cm", 100.0), ("mm", 1000.0)):
        a = probe @ ref[:3, :3].T + ref[:3, 3]
        t = worlds[units][1]
        b = (probe * scale) @ t[:3, :3].T + t[:3, 3]
        lines.append(f"  {units} vs m: world differs by {np.abs(a - b).max() * 1000:.3f} mm")
    path = tmp / "units_1e6.ply"
    write_point_cloud(gt, path, 200_000, units="m", up="+z")
    import open3d as o3d

    pcd = o3d.io.read_point_cloud(str(path))
    pcd.points = o3d.utility.Vector3dVector(np.asarray(pcd.points) * 1e6)
    o3d.io.write_point_cloud(str(path), pcd)
    started = time.perf_counter()
    try:
        run_pipeline(path, pipeline=_pipeline_file())
        lines.append("  1e6-scaled: converted (FAIL: should be refused)")
    except InputError as exc:
        lines.append(f"  1e6-scaled: InputError (exit {exc.exit_code}) in {time.perf_counter() - started:.2f} s, "
                     f"names --units: {'--units' in str(exc)}: {str(exc)[:110]}")
    return lines


def peak_memory_10m(gt_layout: str, tmp: Path) -> str:
    """Convert a 10 M-point cloud in a subprocess and report its time and peak RSS."""
    gt = bench_scene(gt_layout)
    path = tmp / "cloud10m.ply"
    write_point_cloud(gt, path, 10_000_000)
    # ru_maxrss survives fork+exec (it would report the parent's peak): reset the high-water mark first
    code = (f"open('/proc/self/clear_refs','w').write('5');import time;from realsim.pipeline import run_pipeline;t=time.perf_counter();"
            f"s=run_pipeline('{path}', pipeline='{_pipeline_file()}');"
            f"hwm=[l for l in open('/proc/self/status') if l.startswith('VmHWM')][0].split()[1];"
            f"print(len(s.objects), round(time.perf_counter()-t,2), int(hwm)//1024)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    if out.returncode:
        return f"  10M: failed: {out.stderr.strip().splitlines()[-1] if out.stderr.strip() else out.returncode}"
    n, secs, mb = out.stdout.split()
    return f"  10M points ({gt_layout}): {n} objects (true {len(gt.objects)}), load+planes+segment {secs} s, peak memory {int(mb)} MB"


def run(layouts: list[str], densities: list[int], frames: int, full: bool, big: bool,
        forms: frozenset[str] = frozenset({"view", "cloud", "mesh", "sequence"}), units: bool = True) -> None:
    rows: list[Row] = []
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = Path(tmp_name)
        for layout in layouts:
            gt = bench_scene(layout)
            d = tmp / layout.replace(":", "_")
            d.mkdir()
            start = len(rows)
            if "view" in forms:
                entry = write_organized_view(gt, d / "view.pcd")
                rows.append(evaluate(gt, d / "view.pcd", entry["capture_to_world"], "view (Kinect)"))
            for count in densities if "cloud" in forms else []:
                path = d / f"cloud_{count}.ply"
                entry, ids = write_point_cloud(gt, path, count)
                rows.append(evaluate(gt, path, entry["capture_to_world"], f"cloud {count // 1000}k", gt_ids=ids))
            if "mesh" in forms:
                entry = write_mesh(gt, d / "mesh.glb")
                rows.append(evaluate(gt, d / "mesh.glb", entry["capture_to_world"], "mesh glb mm Y-up"))
            if frames and "sequence" in forms:
                entry = write_rgbd_sequence(gt, d / "sequence", frames)
                rows.append(evaluate(gt, d / "sequence", entry["capture_to_world"], f"RGB-D {frames} fr"))
            for r in rows[start:]:
                r.layout = layout
            print(f"[{layout} done]", flush=True)
        print_rows(rows)
        good = rows
        print(f"\nall forms: F1 mean {np.mean([r.f1 for r in good]):.3f} (min {min(r.f1 for r in good):.2f}), "
              f"IoU mean {np.mean([r.iou for r in good]):.3f}, worst support {np.nanmax([r.sup_err_mm for r in good]):.2f} mm / "
              f"{np.nanmax([r.sup_tilt_deg for r in good]):.2f} deg, missing {sum(r.sup_missing for r in good)}, extra {sum(r.sup_extra for r in good)}")
        for form in dict.fromkeys(r.form for r in good):
            of = [r for r in good if r.form == form]
            print(f"  {form:16s} F1 mean {np.mean([r.f1 for r in of]):.3f} (min {min(r.f1 for r in of):.2f}), IoU mean {np.mean([r.iou for r in of]):.3f}")
        if units:
            print("\nunits (table scene, 200k cloud, no flags):")
            print("\n".join(units_check(bench_scene(layouts[0]), tmp)))
        if full:
            print("\nfull conversions (all stages, robot, settle, written), table scene:")
            first = tmp / layouts[0].replace(":", "_")
            for path in (first / "cloud_1000000.ply", first / "mesh.glb"):
                if path.exists():
                    started, cpu = time.perf_counter(), time.process_time()
                    scene = convert(path, tmp / f"out_{path.stem}")
                    print(f"  {path.name}: {time.perf_counter() - started:.2f} s wall, {time.process_time() - cpu:.2f} s CPU "
                          f"(wall on a loaded machine overstates), {len(scene.objects)} objects, warnings: {scene.warnings}")
        if big:
            print(peak_memory_10m(layouts[0], tmp))
    print(f"\nbench peak memory (this process): {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss // 1024} MB")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="200k clouds and 10-frame sequences only, no 10M")
    parser.add_argument("--full", action="store_true", help="also time full conversions")
    parser.add_argument("--layouts", default="table,counter,floor")
    parser.add_argument("--forms", default="view,cloud,mesh,sequence", help="capture forms to write and score")
    parser.add_argument("--densities", help="cloud point counts, comma-separated (default: 50k, 200k, 1 M; --quick 200k)")
    parser.add_argument("--no-big", action="store_true", help="skip the units check and the 10 M-point run")
    args = parser.parse_args()
    forms = frozenset(args.forms.split(","))
    if not forms <= {"view", "cloud", "mesh", "sequence"}:
        raise SystemExit(f"unknown form in {args.forms!r}: use view, cloud, mesh, sequence")
    chosen = [int(float(c)) for c in args.densities.split(",")] if args.densities else None
    if args.quick:
        run(args.layouts.split(","), chosen or [200_000], 10, False, False, forms, not args.no_big)
    else:
        run(args.layouts.split(","), chosen or [50_000, 200_000, 1_000_000], 30, args.full, not args.no_big, forms, not args.no_big)
