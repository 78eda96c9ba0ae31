"""Gravity and support heights from single organized views (generated ground truth, realsim.synth).

Each seed builds a scene (layouts table, counter, floor in turn; drawn YCB objects) and captures
of it of each asked kind:

- ``view``: the generator's own tripod view (``kinect_view``, the one bench_completion converts);
- ``hand``: a hand-held view of the scene with a wall behind the support and, for tables and
  counters, no floor (``without_floor``), pitched 20-65 degrees down and rolled up to 20 degrees;
- ``roll``: the same scene held at a strong roll (90, 135 or 180 degrees by seed, +-10), so the
  picture is sideways or upside down and the wall faces the picture's up as much as the support;
- ``overhead``: the same scene seen from 75-88 degrees down (looking nearly straight down);
- ``cloud``: an unorganized 200k-point cloud (no camera) of the scene with a wall and, for tables
  and counters, no floor, turned by each of ``--tilts`` degrees about a seeded random axis;
- ``cloudfloor`` / ``cloudbare``: the same clouds with the floor kept / without the wall.

Only the load and planes stages run. Per view: the angle between the converter's up and the true
up (degrees), and for each support whose top fills at least 3 % of the picture the height error of
the matching observed plane, read in the true world through the true camera pose (so a floorless
view's assumed floor does not count). A view is right when gravity is within 0.5 degrees and every
such support is found within 5 mm. Run:

    .venv/bin/python bench/bench_gravity.py [--seeds 0-29] [--kinds view hand roll overhead cloud]
        [--tilts 0,20,40,60,90] [--layouts table,counter,floor]
"""

from __future__ import annotations

import argparse
import math
import resource
import tempfile
from pathlib import Path
from typing import Any, Callable

import numpy as np
from scipy.spatial.transform import Rotation

from realsim.perception.capture import load_capture
from realsim.perception.pcd_io import write_pcd
from realsim.perception.planes import detect_planes
from realsim.synth import SceneSpec, SynthScene, kinect_view, make_scene
from realsim.synth.camera import Camera, view_cloud
from realsim.synth.exports import without_floor, write_cloud
from realsim.synth.forms import sample_cloud
from realsim.synth.scene import PART_FLOOR, PART_SUPPORT_TOP

MIN_SHARE = 0.03  # a support whose top fills this share of the picture must be found
GRAVITY_DEG = 0.5
HEIGHT_MM = 5.0
VIEW_KINDS = ("view", "hand", "roll", "overhead")
CLOUD_KINDS = ("cloud", "cloudfloor", "cloudbare")
ROLLS = (90.0, 135.0, 180.0)
LAYOUTS = ["table", "counter", "floor"]  # by seed in turn; --layouts replaces them (e.g. rooms)


def walled_scene(seed: int, floor: bool = False, wall: bool = True) -> SynthScene:
    """The seed's scene (layout by seed), with a wall behind the support; a table's or counter's
    floor dropped unless ``floor``."""
    layout = LAYOUTS[seed % len(LAYOUTS)]
    scene = make_scene(SceneSpec(layout=layout, seed=seed, wall=wall))
    return scene if floor or layout == "floor" else without_floor(scene)


def view_scene(seed: int, kind: str) -> tuple[SynthScene, Camera]:
    """The seed's scene and camera of ``kind`` (``view``, ``hand``, ``roll`` or ``overhead``)."""
    if kind == "view":
        scene = make_scene(SceneSpec(layout=LAYOUTS[seed % len(LAYOUTS)], seed=seed))
        return scene, kinect_view(scene, np.random.default_rng([seed, 11]))
    rng = np.random.default_rng([seed, 13])
    scene = walled_scene(seed)
    if kind == "roll":
        roll = ROLLS[seed % len(ROLLS)] * (1.0 if seed % 2 else -1.0) + float(rng.uniform(-10.0, 10.0))
        return scene, kinect_view(scene, rng, pitch_deg=(20.0, 65.0), roll_deg=roll)
    roll = float(rng.uniform(-20.0, 20.0))
    pitch = (75.0, 88.0) if kind == "overhead" else (20.0, 65.0)
    return scene, kinect_view(scene, rng, pitch_deg=pitch, roll_deg=roll)


def tilted_cloud(scene: SynthScene, seed: int, tilt_deg: float, path: Path) -> np.ndarray:
    """Write the scene as a 200k-point PLY whose up is turned ``tilt_deg`` off its +z (about a
    seeded horizontal axis); return the file-to-world rotation (3x3)."""
    points, colours, _ = sample_cloud(scene, 200_000, seed)
    heading = np.random.default_rng([seed, 19]).uniform(0.0, 2.0 * math.pi)
    rotvec = math.radians(tilt_deg) * np.array([math.cos(heading), math.sin(heading), 0.0])
    rot = Rotation.from_rotvec(rotvec).as_matrix()
    write_cloud(path, points @ rot.T, colours, "ply")
    return np.asarray(rot.T)


def score(scene: SynthScene, path: Path, to_world: np.ndarray, seen: Callable[[bool], bool], seed: int) -> dict[str, Any]:
    """Convert ``path`` (load + planes) and score it: ``to_world`` takes the file's frame to the
    true world; ``seen(is_floor)`` says whether a support must be found."""
    converted = detect_planes(load_capture(path, seed=seed))
    m = converted.capture.input_to_world
    up = m[2, :3] / np.linalg.norm(m[2, :3])  # the converter's up in the file's frame
    true_up = to_world[2, :3] / np.linalg.norm(to_world[2, :3])
    gravity = math.degrees(math.acos(float(np.clip(up @ true_up, -1.0, 1.0))))
    to_true = to_world @ np.linalg.inv(m)
    errors, missing = [], 0
    for sup in scene.supports:
        if sup.kind != "floor" and scene.spec.layout == "floor":
            continue
        if not seen(sup.kind == "floor"):
            continue
        heights = [(to_true @ np.r_[p.rect_center, p.height, 1.0])[2] / np.cbrt(np.linalg.det(to_true[:3, :3]))
                   for p in converted.planes if p.observed]
        near = [abs(h - sup.height) for h in heights if abs(h - sup.height) < 0.05]
        if near:
            errors.append(min(near) * 1000)
        else:
            missing += 1
    right = gravity < GRAVITY_DEG and missing == 0 and max(errors, default=0.0) < HEIGHT_MM
    return {"gravity": gravity, "err_mm": max(errors, default=float("nan")), "missing": missing, "right": right,
            "floor_seen": any(p.kind == "floor" and p.observed for p in converted.planes), "warnings": converted.warnings}


def measure(scene: SynthScene, cam: Camera, seed: int, folder: Path) -> dict[str, Any]:
    """Render, convert (load + planes) and score one view."""
    points, frame = view_cloud(scene, cam, np.random.default_rng([seed, 17]))
    path = folder / f"view{seed}.pcd"
    write_pcd(path, points, colors=frame.color.reshape(-1, 3), grid_shape=frame.depth.shape)
    shares = {floor: float(np.mean(frame.part == (PART_FLOOR if floor else PART_SUPPORT_TOP))) for floor in (False, True)}
    return score(scene, path, cam.pose, lambda floor: shares[floor] >= MIN_SHARE, seed)


def measure_cloud(kind: str, seed: int, tilt_deg: float, folder: Path) -> dict[str, Any]:
    """Write, turn, convert (load + planes) and score one unorganized cloud of ``kind``."""
    scene = walled_scene(seed, floor=kind == "cloudfloor", wall=kind != "cloudbare")
    path = folder / f"cloud{seed}.ply"
    to_world = np.eye(4)
    to_world[:3, :3] = tilted_cloud(scene, seed, tilt_deg, path)
    return score(scene, path, to_world, lambda floor: True, seed)


def seed_range(text: str) -> range:
    """The seeds of one ``--seeds`` item: ``7`` or ``a-b`` (inclusive)."""
    lo, _, hi = text.partition("-")
    return range(int(lo), int(hi or lo) + 1)


def failed(exc: Exception) -> dict[str, Any]:
    """The row of a conversion that raised: a wrong capture, reported."""
    return {"gravity": float("nan"), "err_mm": float("nan"), "missing": -1, "right": False, "floor_seen": False,
            "warnings": [f"{type(exc).__name__}: {exc}"]}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="0-29", help="a comma list of seeds and ranges a-b")
    ap.add_argument("--kinds", nargs="+", default=["view", "hand"], choices=VIEW_KINDS + CLOUD_KINDS)
    ap.add_argument("--tilts", default="0,20,40,60,90", help="degrees the clouds are turned (comma list)")
    ap.add_argument("--layouts", default=",".join(LAYOUTS), help="generator layouts taken by seed in turn (comma list)")
    args = ap.parse_args()
    LAYOUTS[:] = args.layouts.split(",")
    seeds = [seed for part in args.seeds.split(",") for seed in seed_range(part)]
    tilts = [float(t) for t in args.tilts.split(",")]
    print(f"{'kind':10s} {'seed':>4s} {'layout':8s} {'tilt':>4s} {'grav deg':>8s} {'sup mm':>7s} {'miss':>4s} {'floor':>5s} right  warnings")
    tally: dict[str, list[bool]] = {}
    start = resource.getrusage(resource.RUSAGE_SELF)
    with tempfile.TemporaryDirectory() as tmp:
        for kind in args.kinds:
            for seed in seeds:
                for tilt in tilts if kind in CLOUD_KINDS else [0.0]:
                    try:
                        if kind in CLOUD_KINDS:
                            r = measure_cloud(kind, seed, tilt, Path(tmp))
                        else:
                            scene, cam = view_scene(seed, kind)
                            r = measure(scene, cam, seed, Path(tmp))
                    except Exception as exc:  # noqa: BLE001 - a failed conversion is a wrong capture, reported
                        r = failed(exc)
                    label = f"{kind} {tilt:.0f}" if kind in CLOUD_KINDS else kind
                    tally.setdefault(label, []).append(r["right"])
                    print(f"{kind:10s} {seed:4d} {LAYOUTS[seed % len(LAYOUTS)]:8s} {tilt:4.0f} {r['gravity']:8.3f} {r['err_mm']:7.2f} {r['missing']:4d} "
                          f"{'yes' if r['floor_seen'] else 'no':>5s} {'yes' if r['right'] else 'NO':5s}  {'; '.join(r['warnings'])[:70]}",
                          flush=True)
    end = resource.getrusage(resource.RUSAGE_SELF)
    for label, ok in tally.items():
        print(f"{label}: {sum(ok)}/{len(ok)} with gravity within {GRAVITY_DEG} deg and every support within {HEIGHT_MM:.0f} mm")
    print(f"CPU {end.ru_utime + end.ru_stime - start.ru_utime - start.ru_stime:.1f} s")


if __name__ == "__main__":
    main()
