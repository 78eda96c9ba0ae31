"""Captures as people export them: one generated scene written in many file forms, frames and
units, each converted (load + planes + segment, ``bench_captures.evaluate``) and scored in the
ground-truth frame.

A row passes when every support is found within 3 mm and 0.3 deg, no extra support is found,
and object F1 >= 0.75 (at most one of four objects wrong). Forms: clouds (PLY binary/ascii/
double, PCD ascii/binary/binary_compressed, XYZ, PTS), meshes (OBJ+MTL, PLY, STL, GLB, glTF,
USDA, USDZ), a 3DGS splat, RGB-D sequences (PNG, JPG, small depth, rgb.mp4, confidence, .npy);
frames: six up axes with a turn about up, cm/mm, a 4 deg tilt, origins 2 km and 500 km away;
a tabletop scan without floor (folder with capture.yaml ``support_height``).

    .venv/bin/python bench/bench_capture_files.py [--all] [--only SUBSTRING] [--points 100000]

By default each variant runs on one layout (table, counter, floor in turn, seeds 100-102);
``--all`` runs every variant on every layout and on seeds 110-112 too (heavy).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_captures import Row, evaluate, print_rows  # noqa: E402

from realsim.errors import InputError  # noqa: E402
from realsim.synth import SceneSpec, SynthScene, make_scene, sample_cloud, write_rgbd_sequence, write_splat  # noqa: E402
from realsim.synth.exports import capture_transform, without_floor, write_cloud, write_mesh_file  # noqa: E402
from realsim.synth.forms import apply  # noqa: E402
from realsim.synth.sequence_forms import restyle_sequence  # noqa: E402

LAYOUTS = ("table", "counter", "floor")
Writer = Callable[[SynthScene, Path, int], tuple[Path, np.ndarray]]  # -> (capture path, capture_to_world)


def cloud(kind: str, units: str = "m", up: str = "+z", yaw: float = 0.0, tilt: float = 0.0,
          offset: tuple[float, float, float] = (0.0, 0.0, 0.0), suffix: str | None = None) -> Writer:
    def write(gt: SynthScene, d: Path, points: int) -> tuple[Path, np.ndarray]:
        t = capture_transform(units, up, yaw, tilt, offset)
        pts, cols, _ = sample_cloud(gt, points, seed=1)
        path = write_cloud(d / f"cloud.{suffix or kind.split('_')[0]}", apply(t, pts), cols, kind)
        return path, np.linalg.inv(t)
    return write


def mesh(ext: str, units: str = "m", up: str = "+z", yaw: float = 0.0, tilt: float = 0.0,
         offset: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> Writer:
    def write(gt: SynthScene, d: Path, points: int) -> tuple[Path, np.ndarray]:
        t = capture_transform(units, up, yaw, tilt, offset)
        return write_mesh_file(d / f"scene.{ext}", gt, t, usd_up=up), np.linalg.inv(t)
    return write


def splat(units: str, up: str) -> Writer:
    def write(gt: SynthScene, d: Path, points: int) -> tuple[Path, np.ndarray]:
        entry, _ = write_splat(gt, d / "splat.ply", points, seed=1, units=units, up=up)
        return d / "splat.ply", entry["capture_to_world"]
    return write


def sequence(frames: int, **style) -> Writer:  # noqa: ANN003 - restyle_sequence's keywords
    def write(gt: SynthScene, d: Path, points: int) -> tuple[Path, np.ndarray]:
        entry = write_rgbd_sequence(gt, d / "seq", frames, seed=1)
        back = restyle_sequence(d / "seq", **style)
        return d / "seq", entry["capture_to_world"] @ back
    return write


def floorless(inner: Writer) -> Writer:
    """A tabletop scan without floor, in a folder with capture.yaml giving the table's height."""
    def write(gt: SynthScene, d: Path, points: int) -> tuple[Path, np.ndarray]:
        top = without_floor(gt)
        (d / "cap").mkdir()
        path, ctw = inner(top, d / "cap", points)
        path.rename(d / "cap" / f"scene{path.suffix}")
        low = min(s.height for s in top.supports)
        (d / "cap" / "capture.yaml").write_text(f"support_height: {low:.4f}\n")
        return d / "cap", ctw
    return write


def variants(frames: int) -> dict[str, Writer]:
    km2, km500 = (1200.0, -1600.0, 35.0), (350000.0, 357000.0, 120.0)
    v: dict[str, Writer] = {f"cloud {k}": cloud(k) for k in ("ply", "ply_ascii", "pcd_ascii", "pcd_binary",
                                                              "pcd_binary_compressed", "xyz", "pts")}
    v |= {f"cloud up {u} yaw 37": cloud("ply", up=u, yaw=37.0) for u in ("+x", "-x", "+y", "-y", "+z", "-z")}
    v |= {f"cloud {u} -y": cloud("ply", units=u, up="-y") for u in ("cm", "mm")}
    v |= {"cloud tilt 4": cloud("ply", tilt=4.0, yaw=20.0), "cloud pcd 2km": cloud("pcd_binary", offset=km2),
          "cloud ply64 2km": cloud("ply_double", offset=km2), "cloud ply64 500km": cloud("ply_double", offset=km500),
          "cloud xyz mm 500km": cloud("xyz", units="mm", offset=km500)}
    v |= {"mesh obj m +z": mesh("obj"), "mesh obj cm +y": mesh("obj", "cm", "+y", yaw=90.0), "mesh ply m +z": mesh("ply"),
          "mesh ply m -x": mesh("ply", up="-x", yaw=15.0), "mesh stl mm +z": mesh("stl", "mm"),
          "mesh glb m +y": mesh("glb", up="+y"), "mesh gltf cm +y": mesh("gltf", "cm", "+y"),
          "mesh usda cm +y": mesh("usda", "cm", "+y"), "mesh usdz m +z": mesh("usdz"), "mesh usda mm +z": mesh("usda", "mm"),
          "mesh obj tilt 3": mesh("obj", tilt=3.0), "mesh ply 2km": mesh("ply", offset=km2),
          "mesh glb 500km": mesh("glb", up="+y", offset=km500)}
    v |= {"splat m +z": splat("m", "+z"), "splat cm +y": splat("cm", "+y")}
    v |= {"seq png": sequence(frames), "seq jpg": sequence(frames, jpg=True),
          "seq depth 256x192": sequence(frames, depth_size=(256, 192)), "seq mp4": sequence(frames, mp4=True),
          "seq confidence": sequence(frames, confidence=True), "seq npy": sequence(frames, npy=True),
          "seq 500km": sequence(frames, offset_m=km500)}
    v |= {"nofloor cloud ply": floorless(cloud("ply")), "nofloor mesh obj": floorless(mesh("obj")),
          "cloud xyz mm": cloud("xyz", units="mm")}
    return v


def passes(r: Row) -> bool:
    ok_sup = not (r.sup_err_mm > 3.0) and not (r.sup_tilt_deg > 0.3) and r.sup_missing == 0 and r.sup_extra == 0
    return bool(ok_sup and np.isfinite(r.sup_err_mm) and r.f1 >= 0.75)


def run(names: list[str], writers: dict[str, Writer], scenes: list[tuple[str, int]], every: bool, points: int) -> list[Row]:
    """Each variant on its scene (the i-th variant of the full list on scene i mod 3), or on all."""
    rows: list[Row] = []
    cache: dict[tuple[str, int], SynthScene] = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            i = list(writers).index(name)
            todo = scenes if every else [scenes[i % len(scenes)]]
            for layout, seed in todo:
                if name.startswith("nofloor") and layout == "floor":
                    layout = "table"
                gt = cache.get((layout, seed)) or cache.setdefault((layout, seed), make_scene(SceneSpec(layout=layout, objects=None, seed=seed)))
                d = Path(tmp) / f"{i}_{layout}_{seed}"
                d.mkdir()
                cpu = time.process_time()
                try:
                    path, ctw = writers[name](gt, d, points)
                    scored = without_floor(gt) if name.startswith("nofloor") else gt
                    row = evaluate(scored, path, ctw, name)
                except InputError as exc:
                    row = Row(layout, name, 0, np.nan, np.nan, 0, 0, len(gt.objects), 0, 0.0, 0.0, f"InputError: {exc}"[:80])
                except Exception as exc:  # a crash is a finding: record it, keep sweeping
                    row = Row(layout, name, 0, np.nan, np.nan, 0, 0, len(gt.objects), 0, 0.0, 0.0,
                              f"CRASH {type(exc).__name__}: {exc}"[:80])
                row.layout, row.cpu = f"{layout}:{seed}", time.process_time() - cpu
                row.note = ("ok   " if passes(row) else "FAIL ") + row.note
                rows.append(row)
                print(f"  {row.layout:11s} {name:24s} {row.note[:70]}  (F1 {row.f1:.2f}, {row.cpu:.1f} s CPU)", flush=True)
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--all", action="store_true", help="every variant on every layout, seeds 100-102 and 110-112")
    parser.add_argument("--only", default="", help="run the variants whose name holds this text")
    parser.add_argument("--points", type=int, default=100_000, help="points of clouds and splats")
    parser.add_argument("--frames", type=int, default=10, help="frames of RGB-D sequences")
    args = parser.parse_args()
    writers = variants(args.frames)
    names = [n for n in writers if args.only in n]
    scenes = [(layout, 100 + i) for i, layout in enumerate(LAYOUTS)]
    if args.all:
        scenes += [(layout, 110 + i) for i, layout in enumerate(LAYOUTS)]
    cpu = time.process_time()
    rows = run(names, writers, scenes, args.all, args.points)
    print()
    print_rows(rows)
    failed = [r for r in rows if not passes(r)]
    print(f"\n{len(rows) - len(failed)}/{len(rows)} rows pass; failing: {', '.join(f'{r.layout} {r.form}' for r in failed) or 'none'}")
    print(f"total {time.process_time() - cpu:.1f} s CPU")


if __name__ == "__main__":
    main()
