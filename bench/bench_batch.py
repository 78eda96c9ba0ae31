"""`realsim batch` on a local Ray: 1 worker against 2, a corrupt capture among them, then a rerun.

20 captures: the 7 PCL scans, 8 YCB object captures (1-3 objects each), 4 text descriptions
and one corrupt point cloud. The object meshes are decomposed once beforehand into a cache that
each timed run starts from a copy of (so both runs do the same work: everything but CoACD). The
runs: 1 worker into a new folder, 2 workers into another, and the 2-worker batch again (every
scene unchanged: skipped; the corrupt capture is retried and reported again).

    MENAGERIE_ROOT=../shared/data .venv/bin/python bench/bench_batch.py [--captures 20]
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
os.environ.setdefault("MENAGERIE_ROOT", str(REPO.parent / "shared" / "data"))
os.environ["REALSIM_REUSE"] = "0"  # time real conversions

from realsim.assets import AssetParams, prepare_objects  # noqa: E402
from realsim.batch import print_summary, run_batch  # noqa: E402
from realsim.cache import DiskCache  # noqa: E402

DATA = REPO.parent / "shared" / "data"
SCANS = ["mOSD/test0.pcd", "mOSD/test31.pcd", "mOSD/test45.pcd", "mOSD/test55.pcd", "table_scene_mug_stereo_textured.pcd",
         "milk_cartoon_all_small_clorox.pcd", "region_growing_rgb_tutorial.pcd"]
OBJECT_SETS = [("077_rubiks_cube",), ("012_strawberry", "011_banana"), ("003_cracker_box",), ("006_mustard_bottle", "077_rubiks_cube"),
               ("021_bleach_cleanser",), ("040_large_marker", "012_strawberry"), ("011_banana", "003_cracker_box", "077_rubiks_cube"),
               ("006_mustard_bottle",)]
TEXTS = ["a table with a mug and a bowl", "a kitchen table with two soda cans and a cereal box",
         "a desk with a book and a bottle", "a counter with a plate and a cup"]


def make_captures(root: Path, count: int) -> list[Path]:
    out: list[Path] = []
    for scan in SCANS:
        dest = root / Path(scan).name
        shutil.copyfile(DATA / "pcl_scenes" / scan, dest)
        out.append(dest)
    for i, names in enumerate(OBJECT_SETS):
        cap = root / f"objects_{i}"
        for name in names:
            dest = cap / "objects" / name.split("_", 1)[1]
            dest.mkdir(parents=True, exist_ok=True)
            for f in (DATA / "ycb_google16k" / name).glob("textured.*"):
                shutil.copyfile(f, dest / f.name)
        (cap / "capture.yaml").write_text("support: {size: [1.0, 0.7], height: 0.75}\n")
        out.append(cap)
    for i, text in enumerate(TEXTS):
        cap = root / f"text_{i}"
        cap.mkdir()
        (cap / "capture.yaml").write_text(f"text: {text!r}\n")
        out.append(cap)
    corrupt = root / "corrupt.pcd"
    corrupt.write_bytes(b"# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 5000\nHEIGHT 1\n"
                        b"POINTS 5000\nDATA binary\n" + os.urandom(64))
    out.append(corrupt)
    keep = out[: count - 1] + [corrupt] if count < len(out) else out
    for path in out:
        if path not in keep:
            shutil.rmtree(path) if path.is_dir() else path.unlink()
    return keep


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--captures", type=int, default=20, help="how many captures (the corrupt one included)")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        captures_dir = tmp / "captures"
        captures_dir.mkdir()
        captures = make_captures(captures_dir, args.captures)
        warm = tmp / "cache-warm"
        files = sorted({f for c in captures if c.is_dir() for f in c.glob("objects/*/textured.obj")})
        started = time.perf_counter()
        prepare_objects(files, [None] * len(files), AssetParams(), DiskCache(warm))
        print(f"assets decomposed once beforehand: {len(files)} meshes in {time.perf_counter() - started:.1f} s")
        rows = []
        for label, workers, out, cache in (("1 worker", 1, tmp / "out1", tmp / "cache1"), ("2 workers", 2, tmp / "out2", tmp / "cache2"),
                                           ("2 workers, rerun", 2, tmp / "out2", tmp / "cache2")):
            if not cache.exists():
                shutil.copytree(warm, cache)
            os.environ["REALSIM_CACHE"] = str(cache)
            started = time.perf_counter()
            jobs, summary = run_batch([str(captures_dir)], out, workers=workers, progress=False)
            wall = time.perf_counter() - started
            rows.append((label, wall, summary))
            print_summary(jobs, summary, out)
        print("\n## realsim batch, local Ray")
        print(f"{'run':18s} {'wall s':>8s} {'ok':>4s} {'skipped':>8s} {'failed':>7s}")
        for label, wall, s in rows:
            print(f"{label:18s} {wall:8.1f} {s['ok']:4d} {s['skipped']:8d} {s['failed']:7d}")
        print(f"speed-up 2 workers vs 1: {rows[0][1] / rows[1][1]:.2f}x; rerun: {rows[2][1]:.1f} s")


if __name__ == "__main__":
    main()
