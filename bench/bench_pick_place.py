"""Pick-and-place benchmark on the 15 YCB objects.

For each object, ``--trials`` seeded random placements on a 1.0 x 0.7 m table at 0.75 m; the
Panda (placed by ``choose_robot_pose``) grasps the object and places it into a marked 20 x 20 cm
zone on the same table (with ``--anywhere``: a zone at a seeded random spot on the table). Prints one row per object: grasp success, place success, attempts,
simulated and wall time; then the totals and the objects declared not graspable.

    MENAGERIE_ROOT=../shared/data python bench/bench_pick_place.py [--trials 5] [--jobs 2] [--objects mug,bowl]
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from multiprocessing import get_context
from pathlib import Path

import mujoco
import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
os.environ.setdefault("MENAGERIE_ROOT", str(REPO.parent / "shared" / "data"))

from realsim.assets import prepare_object  # noqa: E402
from realsim.composition.compose import compose_scene  # noqa: E402
from realsim.composition.robot_placement import add_robot  # noqa: E402
from realsim.composition.settle import settle_scene  # noqa: E402
from realsim.robot import Robot  # noqa: E402
from realsim.scene import CaptureInfo, Scene, SceneObject, SupportPlane  # noqa: E402

YCB = REPO.parent / "shared" / "data" / "ycb_google16k"
TABLE_Z = 0.75
TABLE_SIZE = (1.0, 0.7)
ZONE_CENTRE = (0.25, -0.12)
ZONE_HALF = 0.10
# YCB official masses (kg); PROVENANCE.txt lists most of them
MASSES = {
    "cracker_box": 0.411, "tomato_soup_can": 0.349, "mustard_bottle": 0.603, "potted_meat_can": 0.370, "banana": 0.066,
    "strawberry": 0.018, "pitcher_base": 0.178, "bleach_cleanser": 1.131, "bowl": 0.147, "mug": 0.118, "power_drill": 0.895,
    "scissors": 0.082, "large_marker": 0.0158, "foam_brick": 0.028, "rubiks_cube": 0.252,
}


def _rect(c, size) -> np.ndarray:
    hx, hy = size[0] / 2, size[1] / 2
    return np.array([[c[0] - hx, c[1] - hy], [c[0] + hx, c[1] - hy], [c[0] + hx, c[1] + hy], [c[0] - hx, c[1] + hy]])


def build_scene(folder: Path, trial: int, seed: int, anywhere: bool = False) -> tuple[Scene, str, np.ndarray]:
    """The object at a seeded random pose and the zone (fixed, or with ``anywhere`` at a seeded
    random spot on the table): (scene, object name, zone centre)."""
    prep = prepare_object(folder / "textured.obj")
    rng = np.random.default_rng([seed, trial, sum(map(ord, folder.name))])
    zone = np.array(ZONE_CENTRE)
    if anywhere:  # anywhere on the table the zone fits, 2 cm inside its edges
        zone = rng.uniform([-TABLE_SIZE[0] / 2 + ZONE_HALF + 0.02, -TABLE_SIZE[1] / 2 + ZONE_HALF + 0.02],
                           [TABLE_SIZE[0] / 2 - ZONE_HALF - 0.02, TABLE_SIZE[1] / 2 - ZONE_HALF - 0.02])
    while True:
        xy = rng.uniform([-0.3, -0.2], [0.3, 0.2])
        if np.linalg.norm(xy - zone) > ZONE_HALF + 0.5 * float(np.max(prep.size[:2])) + 0.05:
            break
    yaw = float(rng.uniform(-np.pi, np.pi))
    label = prep.label
    mass = MASSES.get(label, 400.0 * prep.volume)
    name = label.replace(" ", "_")
    obj = SceneObject(
        id=1, name=name, label=label, position=np.array([xy[0], xy[1], TABLE_Z]), quat=np.array([np.cos(yaw / 2), 0, 0, np.sin(yaw / 2)]),
        size=prep.size, support_id=1, color=np.asarray(prep.rgba[:3]), visual=prep.visual, collision=list(prep.hulls), mass=mass,
        com=np.asarray(prep.com), inertia=np.asarray(prep.inertia_unit_mass) * mass, texture_png=prep.texture_png, source_file=prep.source,
    )
    cap = CaptureInfo(source=folder, kind="objects", environment_file=None, units="m", up="+z", units_detected=False, up_detected=False, input_to_world=np.eye(4))
    floor = SupportPlane(0, "floor", np.array([0, 0, 1.0]), 0.0, _rect((0, 0), (3, 3)), np.zeros(2), np.array([3.0, 3.0]), 0.0, 0, observed=False)
    table = SupportPlane(1, "table", np.array([0, 0, 1.0]), TABLE_Z, _rect((0, 0), TABLE_SIZE), np.zeros(2), np.array(TABLE_SIZE), 0.0, 1000)
    scene = compose_scene(Scene(capture=cap, seed=seed, planes=[floor, table], objects=[obj]))
    scene.spec.worldbody.add_geom(name="target_zone", type=mujoco.mjtGeom.mjGEOM_BOX, pos=[zone[0], zone[1], TABLE_Z + 0.0005],
                                  size=[ZONE_HALF, ZONE_HALF, 0.0005], group=2, contype=0, conaffinity=0, rgba=[0.1, 0.8, 0.2, 0.5])
    add_robot(scene, extra_targets=[np.array([zone[0], zone[1], TABLE_Z + 0.2])])
    settle_scene(scene)
    return scene, name, zone


def run_trial(job: tuple[str, int, int, bool]) -> dict:
    folder_name, trial, seed, anywhere = job
    t0 = time.perf_counter()
    scene, name, zone = build_scene(YCB / folder_name, trial, seed, anywhere)
    t_build = time.perf_counter() - t0
    model = scene.spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
    mujoco.mj_forward(model, data)
    robot = Robot(model, data, seed=seed * 1000 + trial)
    t1 = time.perf_counter()
    grasp = robot.grasp(name)
    place = robot.place_in(name, "target_zone") if grasp.success else None
    wall = time.perf_counter() - t1
    graspable = grasp.values.get("graspable", True)
    return {
        "object": folder_name, "trial": trial, "graspable": graspable, "grasp": grasp.success, "place": bool(place and place.success),
        "attempts": grasp.attempts, "sim_time": data.time, "wall": wall, "build": t_build,
        "reason": grasp.reason if not grasp.success else ("" if place and place.success else (place.reason if place else "")),
        "kind": grasp.values.get("kind"), "zone": zone.tolist(),
    }


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--trials", type=int, default=5)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1))
    ap.add_argument("--objects", default="", help="comma-separated substrings of object folder names")
    ap.add_argument("--anywhere", action="store_true", help="each trial's zone at a seeded random spot on the table (the robot placed to reach it)")
    ap.add_argument("--verbose", action="store_true")
    args = ap.parse_args()
    folders = sorted(p.name for p in YCB.iterdir() if (p / "textured.obj").is_file())
    if args.objects:
        keys = args.objects.split(",")
        folders = [f for f in folders if any(k in f for k in keys)]
    for f in folders:  # warm the asset cache once, serially
        prepare_object(YCB / f / "textured.obj")
    jobs = [(f, t, args.seed, args.anywhere) for f in folders for t in range(args.trials)]
    t0 = time.perf_counter()
    if args.jobs > 1:
        with get_context("spawn").Pool(args.jobs) as pool:
            rows = pool.map(run_trial, jobs, chunksize=1)
    else:
        rows = [run_trial(j) for j in jobs]
    total_wall = time.perf_counter() - t0
    if args.verbose:
        for r in rows:
            print(f"  {r['object']:<22} t{r['trial']} grasp={r['grasp']!s:<5} place={r['place']!s:<5} att={r['attempts']} kind={r['kind']} zone=({r['zone'][0]:+.2f},{r['zone'][1]:+.2f}) sim={r['sim_time']:.1f}s {r['reason']}")
    print(f"{'object':<22} {'grasp':>7} {'place':>7} {'attempts':>9} {'sim s':>7} {'wall s':>7}  notes")
    not_graspable: dict[str, str] = {}
    holdable_rows = []
    for f in folders:
        rs = [r for r in rows if r["object"] == f]
        n = len(rs)
        g = sum(r["grasp"] for r in rs)
        p = sum(r["place"] for r in rs)
        att = np.mean([r["attempts"] for r in rs])
        sim = np.mean([r["sim_time"] for r in rs])
        wall = np.mean([r["wall"] for r in rs])
        declared = [r for r in rs if not r["graspable"]]
        if len(declared) == n:
            not_graspable[f] = declared[0]["reason"]
        else:
            holdable_rows.append((f, p / n))
        fails = sorted({r["reason"][:70] for r in rs if not r["place"] and r["graspable"]})
        note = "NOT GRASPABLE" if len(declared) == n else "; ".join(fails)[:110]
        print(f"{f:<22} {g:>3}/{n:<3} {p:>3}/{n:<3} {att:>9.2f} {sim:>7.1f} {wall:>7.1f}  {note}")
    n_all = len(rows)
    p_all = sum(r["place"] for r in rows)
    holdable = [r for r in rows if r["object"] not in not_graspable]
    p_hold = sum(r["place"] for r in holdable)
    print(f"\nplace success: {p_all}/{n_all} = {p_all / max(n_all, 1):.0%} over all trials; "
          f"{p_hold}/{len(holdable)} = {p_hold / max(len(holdable), 1):.0%} over holdable objects")
    worst = min((s for _, s in holdable_rows), default=1.0)
    print(f"worst holdable object: {worst:.0%} (target >= 80%); total wall {total_wall:.0f} s with {args.jobs} job(s)")
    if not_graspable:
        print("declared not graspable:")
        for f, why in not_graspable.items():
            print(f"  {f}: {why}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
