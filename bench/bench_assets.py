"""Benchmark of the object-asset stage on the 15 YCB scans.

    python bench/bench_assets.py                 # fidelity, mass, drop, cavity tables + cold/warm timing
    python bench/bench_assets.py --baseline      # + sequential CoACD at obj2mjcf defaults (subset)
    python bench/bench_assets.py --baseline all  # ... on all 15 objects (slow: minutes)
    python bench/bench_assets.py --only 024_bowl 025_mug   # a subset of the scans (folder names)
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from realsim.assets import AssetParams, load_object_mesh, prepare_objects  # noqa: E402
from realsim.assets.fidelity import surface_distances, volume_iou  # noqa: E402
from realsim.assets.geometry import clean_geometry, make_solid  # noqa: E402
from realsim.cache import DiskCache  # noqa: E402
from realsim.physics import estimate_manifest  # noqa: E402
from realsim.physics.sim_checks import ball_in_container_test, drop_test  # noqa: E402

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "ycb_google16k"
# Official YCB masses quoted in ycb_google16k/PROVENANCE.txt (kg)
OFFICIAL_MASS = {"banana": 0.066, "cracker_box": 0.411, "foam_brick": 0.028, "mustard_bottle": 0.603, "potted_meat_can": 0.370,
                 "power_drill": 0.895, "scissors": 0.082, "strawberry": 0.018, "tomato_soup_can": 0.349}
CONTAINERS = ("bowl", "mug", "pitcher_base")
BASELINE_SUBSET = ("061_foam_brick", "011_banana", "037_scissors", "006_mustard_bottle")


def baseline_coacd(path: Path) -> tuple[float, int]:
    """CoACD on the cleaned solid with obj2mjcf's defaults, as obj2mjcf would run it."""
    import coacd

    coacd.set_log_level("error")
    mesh, _ = load_object_mesh(path)
    solid, _, _ = make_solid(clean_geometry(mesh))
    t = time.perf_counter()
    parts = coacd.run_coacd(coacd.Mesh(solid.vertices, solid.faces), threshold=0.05, preprocess_resolution=50, resolution=2000,
                            mcts_iterations=100, mcts_nodes=20, mcts_max_depth=3, seed=0)
    return time.perf_counter() - t, len(parts)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--baseline", nargs="?", const="subset", default=None, help="'subset' (default) or 'all'")
    ap.add_argument("--data", type=Path, default=DATA)
    ap.add_argument("--only", nargs="+", default=None, help="scan folder names to measure (default: all)")
    args = ap.parse_args()
    paths = sorted(p for p in args.data.glob("*/textured.obj") if args.only is None or p.parent.name in args.only)
    params = AssetParams()
    with tempfile.TemporaryDirectory() as tmp:
        cache = DiskCache(Path(tmp))
        t = time.perf_counter()
        objs = prepare_objects(paths, None, params, cache, progress=True)
        cold = time.perf_counter() - t
        t = time.perf_counter()
        prepare_objects(paths, None, params, cache, progress=False)
        warm = time.perf_counter() - t
    print(f"\n## Conversion timing ({len(paths)} objects, {__import__('os').cpu_count()} cores)")
    print(f"cold (empty cache, parallel): {cold:7.1f} s   warm (cache hit): {warm:5.2f} s")
    print(f"\n{'object':18s} {'hulls':>5s} {'method':>12s} {'dec s':>6s} {'p95 h->s':>9s} {'p95 s->h':>9s} {'IoU':>6s}  {'drop: sink mm':>13s} {'drift mm':>8s} {'tilt':>5s}")
    errs = []
    rows_mass = []
    for p in objs:
        a, b = surface_distances(p.hulls, p.solid, n=20000, dense=200000, seed=0)
        iou = volume_iou(p.hulls, p.solid)
        man = estimate_manifest(p)
        d = drop_test(p, man, height=0.02)
        kind = "cavity" if p.open_container else "solid"
        print(f"{p.label:18s} {len(p.hulls):5d} {p.decomposition.get('method', ''):>12s} {p.timings.get('decompose', 0):6.1f} "
              f"{np.percentile(a, 95) * 1e3:7.2f}mm {np.percentile(b, 95) * 1e3:7.2f}mm {iou:6.3f}{'*' if kind == 'cavity' else ' '} "
              f"{d['sinking'] * 1e3:13.2f} {d['drift'] * 1e3:8.2f} {d['tilt_deg']:5.1f}{'' if d['finite'] else ' EXPLODED'}")
        ref = OFFICIAL_MASS.get(p.label)
        if ref:
            errs.append(abs(man.mass_kg - ref) / ref)
        rows_mass.append((p.label, man.mass_kg, man.sources["mass_kg"], ref, man.category, man.material_class, p.inertia_model))
    print("(* open container in the size table: its volume is walls, IoU of thin walls is not a fidelity measure)")
    print(f"\n## Offline mass estimates\n{'object':18s} {'est kg':>8s} {'source':>9s} {'official':>9s} {'rel err':>8s}  category / material / inertia")
    for label, m, src, ref, cat, mat, im in rows_mass:
        err = f"{abs(m - ref) / ref * 100:7.0f}%" if ref else "     n/a"
        print(f"{label:18s} {m:8.3f} {src:>9s} {ref if ref else '':>9} {err}  {cat} / {mat} / {im}")
    print(f"median relative error over {len(errs)} objects with official masses: {np.median(errs) * 100:.0f}%")
    print("\n## Containers: 3 cm ball dropped into the cavity")
    for p in objs:
        if p.label in CONTAINERS:
            r = ball_in_container_test(p)
            state = "stays inside" if r["inside"] else ("no open cavity in the scan" if not r["cavity_found"] else "FELL OUT")
            print(f"{p.label:18s} {state}  ball at {np.round(r['ball_pos'], 3).tolist()}")
    if args.baseline:
        names = [p.parent.name for p in paths] if args.baseline == "all" else list(BASELINE_SUBSET)
        print(f"\n## Baseline: sequential CoACD at obj2mjcf defaults ({len(names)} objects)")
        total_b = total_ours = 0.0
        for name in names:
            tb, nb = baseline_coacd(args.data / name / "textured.obj")
            ours = next(o for o in objs if o.source.parent.name == name)
            to = sum(v for k, v in ours.timings.items())
            total_b += tb
            total_ours += to
            print(f"{name:22s} baseline {tb:7.1f} s ({nb} hulls)   ours {to:5.1f} s ({len(ours.hulls)} hulls)")
        print(f"subset total: baseline {total_b:.1f} s sequential vs ours {total_ours:.1f} s sequential-equivalent ({total_b / max(total_ours, 1e-9):.1f}x)")
        if args.baseline == "all":
            print(f"all 15: baseline {total_b:.1f} s vs ours cold parallel {cold:.1f} s ({total_b / cold:.1f}x)")


if __name__ == "__main__":
    main()
