"""Gravity and support heights from single organized views (generated ground truth, realsim.synth).

Each seed builds a scene (layouts table, counter, floor in turn; drawn YCB objects) and two views:

- ``view``: the generator's own tripod view (``kinect_view``, the one bench_completion converts);
- ``hand``: a hand-held view of the scene with a wall behind the support and, for tables and
  counters, no floor (``without_floor``), pitched 20-65 degrees down and rolled up to 20 degrees.

Only the load and planes stages run. Per view: the angle between the converter's up and the true
up (degrees), and for each support whose top fills at least 3 % of the picture the height error of
the matching observed plane, read in the true world through the true camera pose (so a floorless
view's assumed floor does not count). A view is right when gravity is within 0.5 degrees and every
such support is found within 5 mm. Run:

    .venv/bin/python bench/bench_gravity.py [--seeds 0-29] [--kinds view hand]
"""

from __future__ import annotations

import argparse
import math
import resource
import tempfile
from pathlib import Path

import numpy as np

from realsim.perception.capture import load_capture
from realsim.perception.pcd_io import write_pcd
from realsim.perception.planes import detect_planes
from realsim.synth import LAYOUTS, SceneSpec, SynthScene, kinect_view, make_scene
from realsim.synth.camera import Camera, view_cloud
from realsim.synth.exports import without_floor
from realsim.synth.scene import PART_FLOOR, PART_SUPPORT_TOP

MIN_SHARE = 0.03  # a support whose top fills this share of the picture must be found
GRAVITY_DEG = 0.5
HEIGHT_MM = 5.0


def view_scene(seed: int, kind: str) -> tuple[SynthScene, Camera]:
    """The seed's scene and camera of ``kind`` (``view`` or ``hand``)."""
    layout = LAYOUTS[seed % len(LAYOUTS)]
    if kind == "view":
        scene = make_scene(SceneSpec(layout=layout, seed=seed))
        return scene, kinect_view(scene, np.random.default_rng([seed, 11]))
    rng = np.random.default_rng([seed, 13])
    scene = make_scene(SceneSpec(layout=layout, seed=seed, wall=True))
    if layout != "floor":
        scene = without_floor(scene)
    roll = float(rng.uniform(-20.0, 20.0))
    return scene, kinect_view(scene, rng, pitch_deg=(20.0, 65.0), roll_deg=roll)


def measure(scene: SynthScene, cam: Camera, seed: int, folder: Path) -> dict:
    """Render, convert (load + planes) and score one view."""
    points, frame = view_cloud(scene, cam, np.random.default_rng([seed, 17]))
    path = folder / f"view{seed}.pcd"
    write_pcd(path, points, colors=frame.color.reshape(-1, 3), grid_shape=frame.depth.shape)
    converted = detect_planes(load_capture(path, seed=seed))
    m = converted.capture.input_to_world
    up = m[2, :3] / np.linalg.norm(m[2, :3])  # the converter's up in the optical frame
    gravity = math.degrees(math.acos(float(np.clip(up @ cam.pose[2, :3], -1.0, 1.0))))
    to_true = cam.pose @ np.linalg.inv(m)
    errors, missing = [], 0
    for sup in scene.supports:
        part = PART_FLOOR if sup.kind == "floor" else PART_SUPPORT_TOP
        if sup.kind != "floor" and scene.spec.layout == "floor":
            continue
        if np.mean(frame.part == part) < MIN_SHARE or (sup.kind == "floor") != (part == PART_FLOOR):
            continue
        heights = [(to_true @ np.r_[p.rect_center, p.height, 1.0])[2] for p in converted.planes if p.observed]
        near = [abs(h - sup.height) for h in heights if abs(h - sup.height) < 0.05]
        if near:
            errors.append(min(near) * 1000)
        else:
            missing += 1
    right = gravity < GRAVITY_DEG and missing == 0 and max(errors, default=0.0) < HEIGHT_MM
    return {"gravity": gravity, "err_mm": max(errors, default=float("nan")), "missing": missing, "right": right,
            "floor_seen": any(p.kind == "floor" and p.observed for p in converted.planes), "warnings": converted.warnings}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="0-29", help="a range a-b or a comma list")
    ap.add_argument("--kinds", nargs="+", default=["view", "hand"], choices=["view", "hand"])
    args = ap.parse_args()
    lo, _, hi = args.seeds.partition("-")
    seeds = list(range(int(lo), int(hi) + 1)) if hi else [int(s) for s in args.seeds.split(",")]
    print(f"{'kind':5s} {'seed':>4s} {'layout':8s} {'grav deg':>8s} {'sup mm':>7s} {'miss':>4s} {'floor':>5s} right  warnings")
    tally: dict[str, list[bool]] = {k: [] for k in args.kinds}
    start = resource.getrusage(resource.RUSAGE_SELF)
    with tempfile.TemporaryDirectory() as tmp:
        for kind in args.kinds:
            for seed in seeds:
                scene, cam = view_scene(seed, kind)
                try:
                    r = measure(scene, cam, seed, Path(tmp))
                except Exception as exc:  # noqa: BLE001 - a failed conversion is a wrong view, reported
                    r = {"gravity": float("nan"), "err_mm": float("nan"), "missing": -1, "right": False, "floor_seen": False,
                         "warnings": [f"{type(exc).__name__}: {exc}"]}
                tally[kind].append(r["right"])
                print(f"{kind:5s} {seed:4d} {scene.spec.layout:8s} {r['gravity']:8.3f} {r['err_mm']:7.2f} {r['missing']:4d} "
                      f"{'yes' if r['floor_seen'] else 'no':>5s} {'yes' if r['right'] else 'NO':5s}  {'; '.join(r['warnings'])[:70]}")
    end = resource.getrusage(resource.RUSAGE_SELF)
    for kind, ok in tally.items():
        print(f"{kind}: {sum(ok)}/{len(ok)} views with gravity within {GRAVITY_DEG} deg and every support within {HEIGHT_MM:.0f} mm")
    print(f"CPU {end.ru_utime + end.ru_stime - start.ru_utime - start.ru_stime:.1f} s")


if __name__ == "__main__":
    main()
