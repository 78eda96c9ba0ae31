"""Physics speed of a converted scene, before and after the collision and sleep changes, in one run.

The scene: 10 YCB scans on a 1.2 x 0.8 m table with the Panda (objects capture, seed 3). It is
converted four times from the same capture: "before" with the former settings (CoACD hulls
capped at 48 at the former 3.5 mm self-check, no primitives, no hull budget, no container rings,
no sleeping), "no rings" with the defaults before open containers got floor-and-wall rings,
"1 mm/s" with today's defaults but MuJoCo's default sleep tolerance (the former defaults), and
"after" with the defaults. For each, two workloads are timed on one core (process CPU time of
``mj_step`` only):

- rest: 5 s from keyframe ``initial``, the robot holding its home posture;
- robot: a pick and place commanded through the runtime ("put the soup can next to the bowl"),
  its controls recorded and replayed open loop, so only physics is timed.

x real time = simulated seconds / CPU seconds. Also printed: hulls and primitives, peak
contacts and constraint rows, the goal verdict, and a table of solver options on the "after"
scene (so the defaults are chosen by measurement), and where the time of the "after" robot
workload goes (MuJoCo's per-stage timers, contacts per step by the kind of geom pair).

    MENAGERIE_ROOT=../shared/data .venv/bin/python bench/bench_sim.py [--rest 5] [--no-options]
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

import mujoco
import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
os.environ.setdefault("MENAGERIE_ROOT", str(REPO.parent / "shared" / "data"))
os.environ["REALSIM_REUSE"] = "0"  # convert for real (stage caches still apply)

from realsim.pipeline import convert  # noqa: E402
from realsim.runtime import Sim, run_command  # noqa: E402

YCB = REPO.parent / "shared" / "data" / "ycb_google16k"
OBJECTS = ("003_cracker_box", "005_tomato_soup_can", "006_mustard_bottle", "010_potted_meat_can", "011_banana",
           "024_bowl", "025_mug", "035_power_drill", "037_scissors", "061_foam_brick")
COMMAND = "put the soup can next to the bowl"
BEFORE = {"objects": {"assets": {"primitives": False, "hull_budget": False, "container_ring": False, "target_p95": 0.0035}},
          "compose": {"sleep": False}}
NO_RINGS = {"objects": {"assets": {"container_ring": False, "target_p95": 0.0035}},  # the defaults before container rings
            "compose": {"sleep_tolerance": 0.001}}  # and before the 5 mm/s sleep tolerance
SLEEP_1MM = {"compose": {"sleep_tolerance": 0.001}}  # today's defaults at MuJoCo's default sleep tolerance


def make_capture(root: Path) -> Path:
    cap = root / "ycb10"
    for folder in OBJECTS:
        dest = cap / "objects" / folder.split("_", 1)[1]
        dest.mkdir(parents=True)
        for f in (YCB / folder).glob("textured.*"):
            shutil.copyfile(f, dest / f.name)
    (cap / "capture.yaml").write_text("support: {size: [1.2, 0.8], height: 0.75}\n")
    return cap


def collision_summary(model: mujoco.MjModel) -> str:
    kinds = {"mesh": 0, "primitive": 0}
    for g in range(model.ngeom):
        name = model.geom(g).name
        if name.startswith("obj") and "_collision_" in name:
            kinds["mesh" if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH else "primitive"] += 1
    return f"{kinds['mesh']} hulls + {kinds['primitive']} primitives"


def time_steps(model: mujoco.MjModel, ctrls: np.ndarray | None, seconds: float) -> tuple[float, int, int]:
    """(x real time, peak ncon, peak nefc) stepping from keyframe initial: replaying ``ctrls``
    (one row per step) or holding the keyframe's controls for ``seconds``."""
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
    steps = len(ctrls) if ctrls is not None else int(round(seconds / model.opt.timestep))
    ncon = nefc = 0
    busy = 0.0
    for i in range(steps):
        if ctrls is not None:
            data.ctrl[:] = ctrls[i]
        t0 = time.process_time()
        mujoco.mj_step(model, data)
        busy += time.process_time() - t0
        ncon, nefc = max(ncon, data.ncon), max(nefc, data.nefc)
    return steps * model.opt.timestep / max(busy, 1e-9), ncon, nefc


def record_command(folder: Path) -> tuple[np.ndarray, str]:
    """The controls of every physics step of COMMAND run by the rule planner, and the verdict."""
    sim = Sim.load(folder)
    ctrls: list[np.ndarray] = []
    original = sim.reset

    def reset() -> None:
        original()
        sim.robot.step_hook = lambda m, d: ctrls.append(d.ctrl.copy())
        sim.robot.hook_every = 1

    sim.reset = reset  # type: ignore[method-assign]
    record = run_command(sim, COMMAND, planner="rules")
    return np.array(ctrls), record.verdict


TIMERS = (("collision: broad phase", "mjTIMER_COL_BROAD"), ("collision: mid + narrow phase", "mjTIMER_COL_NARROW"),
          ("constraint make", "mjTIMER_POS_MAKE"), ("constraint solver", "mjTIMER_CONSTRAINT"),
          ("kinematics + inertia", ("mjTIMER_POS_KINEMATICS", "mjTIMER_POS_INERTIA")), ("velocity + actuation", ("mjTIMER_VELOCITY", "mjTIMER_ACTUATION")))


def _pair_kind(model: mujoco.MjModel, geom: int) -> str:
    body = model.body(model.geom_bodyid[geom]).name
    if model.geom_bodyid[geom] == 0:
        return "static"
    if body.startswith("panda/"):
        return "finger" if "finger" in body else "arm"
    return "object"


def profile_table(model: mujoco.MjModel, ctrls: np.ndarray) -> None:
    """Where the time of the robot workload goes: MuJoCo's stage timers (share of mj_step), the
    contacts per step by kind of geom pair, awake trees and solver iterations."""
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
    pairs: dict[str, int] = {}
    awake = iters = 0
    for row in ctrls:
        data.ctrl[:] = row
        mujoco.mj_step(model, data)
        for g1, g2 in zip(data.contact.geom1[: data.ncon], data.contact.geom2[: data.ncon]):
            key = " - ".join(sorted((_pair_kind(model, g1), _pair_kind(model, g2))))
            pairs[key] = pairs.get(key, 0) + 1
        awake += int(data.ntree_awake)
        iters += int(data.solver_niter[0])
    total = data.timer[int(mujoco.mjtTimer.mjTIMER_STEP)].duration
    print("\n## where the 'after' robot workload's time goes (MuJoCo timers, share of mj_step)")
    for label, names in TIMERS:
        share = sum(data.timer[int(getattr(mujoco.mjtTimer, n))].duration for n in ((names,) if isinstance(names, str) else names))
        print(f"{label:32s} {100 * share / max(total, 1e-12):5.1f} %")
    n = max(len(ctrls), 1)
    print("contacts per step: " + ", ".join(f"{k} {v / n:.1f}" for k, v in sorted(pairs.items(), key=lambda kv: -kv[1])))
    print(f"awake trees per step {awake / n:.1f} of {model.ntree}; solver iterations per step {iters / n:.2f}")


def options_table(model_path: Path, ctrls: np.ndarray, rest: float) -> None:
    variants = {
        "defaults (Newton, elliptic, sleep 5 mm/s)": lambda o: None,
        "sleep tolerance 1 mm/s (MuJoCo's)": lambda o: setattr(o, "sleep_tolerance", 0.001),
        "sleep tolerance 1 cm/s": lambda o: setattr(o, "sleep_tolerance", 0.01),
        "sleep off": lambda o: setattr(o, "enableflags", o.enableflags & ~int(mujoco.mjtEnableBit.mjENBL_SLEEP)),
        "CG solver": lambda o: setattr(o, "solver", mujoco.mjtSolver.mjSOL_CG),
        "pyramidal cone": lambda o: setattr(o, "cone", mujoco.mjtCone.mjCONE_PYRAMIDAL),
        "islands off": lambda o: setattr(o, "disableflags", o.disableflags | int(mujoco.mjtDisableBit.mjDSBL_ISLAND)),
    }
    print("\n## solver options on the 'after' scene (x real time, one core)")
    print(f"{'option':38s} {'rest':>8s} {'robot':>8s}")
    for name, change in variants.items():
        model = mujoco.MjModel.from_xml_path(str(model_path))
        change(model.opt)
        rest_x, _, _ = time_steps(model, None, rest)
        robot_x, _, _ = time_steps(model, ctrls, 0.0)
        print(f"{name:38s} {rest_x:8.1f} {robot_x:8.1f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rest", type=float, default=5.0, help="simulated seconds of the rest workload")
    ap.add_argument("--no-options", action="store_true", help="skip the solver-options table")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        cap = make_capture(Path(tmp))
        rows = []
        for label, overrides in (("before", BEFORE), ("no rings", NO_RINGS), ("1 mm/s", SLEEP_1MM), ("after", {})):
            out = Path(tmp) / label
            started = time.perf_counter()
            convert(cap, out, seed=3, overrides=overrides)
            took = time.perf_counter() - started
            model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
            ctrls, verdict = record_command(out)
            rest_x, rest_con, rest_efc = time_steps(model, None, args.rest)
            robot_x, robot_con, robot_efc = time_steps(model, ctrls, 0.0)
            rows.append((label, collision_summary(model), rest_x, robot_x, max(rest_con, robot_con), max(rest_efc, robot_efc),
                         verdict, len(ctrls) * model.opt.timestep, took))
            if label == "after":
                after_xml, after_ctrls = out / "scene.xml", ctrls
        print("## 10 YCB objects + Panda, one core (x real time = simulated s / CPU s of mj_step)")
        print(f"{'scene':8s} {'collision geoms':28s} {'rest x':>8s} {'robot x':>8s} {'ncon':>5s} {'nefc':>5s}  {'command':10s} {'sim s':>6s} {'convert s':>9s}")
        for label, geoms, rest_x, robot_x, ncon, nefc, verdict, sim_s, took in rows:
            print(f"{label:8s} {geoms:28s} {rest_x:8.1f} {robot_x:8.1f} {ncon:5d} {nefc:5d}  {verdict:10s} {sim_s:6.1f} {took:9.1f}")
        before, no_rings, sleep_1mm, after = rows
        print(f"speed-up after/before: rest {after[2] / before[2]:.1f}x, robot {after[3] / before[3]:.1f}x; "
              f"after/no rings: rest {after[2] / no_rings[2]:.2f}x, robot {after[3] / no_rings[3]:.2f}x; "
              f"after/1 mm/s: rest {after[2] / sleep_1mm[2]:.2f}x, robot {after[3] / sleep_1mm[3]:.2f}x")
        profile_table(mujoco.MjModel.from_xml_path(str(after_xml)), after_ctrls)
        if not args.no_options:
            options_table(after_xml, after_ctrls, args.rest)


if __name__ == "__main__":
    main()
