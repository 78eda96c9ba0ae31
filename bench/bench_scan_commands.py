"""Pick and place every object of converted real scans: per object, graspable or why not, held,
placed, collateral.

Each scan (the mOSD test scenes and the PCL mug scene) is converted with ``realsim convert``
(cached under ``--scenes``); then, for every object, from keyframe "initial": the robot decides
whether the hand can hold it (declared not graspable with a reason before any attempt), grasps
and lifts it, and puts it down on the table at the nearest free spot (``place_down``). A place
counts when the object rests on the table, out of the hand; collateral is any other object
moving more than 2 cm.

    MENAGERIE_ROOT=../shared/data python bench/bench_scan_commands.py [--scans test0,test45] [--scenes DIR]
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
os.environ.setdefault("MENAGERIE_ROOT", str(REPO.parent / "shared" / "data"))
os.environ.setdefault("MUJOCO_GL", "egl")

DATA = REPO.parent / "shared" / "data" / "pcl_scenes"
SCANS = {
    "test0": DATA / "mOSD" / "test0.pcd",
    "test31": DATA / "mOSD" / "test31.pcd",
    "test45": DATA / "mOSD" / "test45.pcd",
    "test55": DATA / "mOSD" / "test55.pcd",
    "mug_stereo": DATA / "table_scene_mug_stereo_textured.pcd",
}
COLLATERAL = 0.02  # m


def make_scene(name: str, root: Path) -> Path:
    out = root / name
    if not (out / "scene.xml").is_file():
        from realsim.pipeline import convert

        convert(SCANS[name], out, seed=0)
    return out


def pick_and_place(sim, name: str) -> dict:
    """One object, from the keyframe: graspability, grasp, put down, collateral."""
    sim.reset()
    robot = sim.robot
    before = sim.state()
    ok, why = robot.graspability(name)
    row = {"object": name, "graspable": ok, "grasp": False, "place": False, "reason": why, "kind": "", "collateral": []}
    if not ok:
        return row
    grasp = robot.grasp(name)
    row["grasp"], row["kind"] = grasp.success, grasp.values.get("kind") or ""
    if not grasp.success:
        row["reason"] = f"grasp: {grasp.reason}"
        return row
    place = robot.place_down(name)
    row["place"] = place.success
    row["reason"] = "" if place.success else f"place: {place.reason}"
    after = sim.state()
    row["collateral"] = [f"{n} {math.dist(p, after[n]) * 100:.1f} cm" for n, p in before.items()
                         if n != name and math.dist(p, after[n]) > COLLATERAL]
    return row


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scans", default=",".join(SCANS), help="comma-separated scan names")
    ap.add_argument("--scenes", default=str(Path(os.environ.get("TMPDIR", "/tmp")) / "realsim_bench_scan_commands"))
    args = ap.parse_args()
    from realsim.runtime import Sim

    root = Path(args.scenes)
    root.mkdir(parents=True, exist_ok=True)
    rows = []
    t0 = time.perf_counter()
    for scan in args.scans.split(","):
        sim = Sim.load(make_scene(scan, root))
        for name in sim.robot.object_names():
            t1 = time.perf_counter()
            r = pick_and_place(sim, name)
            r["scan"], r["wall"] = scan, time.perf_counter() - t1
            rows.append(r)
            print(f"{scan:10} {name:24} {'graspable' if r['graspable'] else 'NOT graspable':13} grasp={'yes' if r['grasp'] else 'no ':3} "
                  f"place={'yes' if r['place'] else 'no ':3} {r['kind']:5} {r['wall']:5.1f}s {r['reason'][:150]}"
                  + (f" collateral: {r['collateral']}" if r["collateral"] else ""), flush=True)
    graspable = [r for r in rows if r["graspable"]]
    placed = sum(r["place"] for r in graspable)
    collateral = sum(len(r["collateral"]) for r in rows)
    print(f"\n{len(rows)} objects in {len(args.scans.split(','))} scans: {len(graspable)} declared graspable, "
          f"{sum(r['grasp'] for r in graspable)} grasped, {placed} picked and placed "
          f"({100.0 * placed / max(len(graspable), 1):.0f}% of the graspable); collateral moves > 2 cm: {collateral}; "
          f"{time.perf_counter() - t0:.0f} s wall")
    print("declared not graspable:")
    for r in rows:
        if not r["graspable"]:
            print(f"  {r['scan']}/{r['object']}: {r['reason']}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
