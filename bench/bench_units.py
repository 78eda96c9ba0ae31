"""The same scene in m, cm and mm, shifted by a fraction of a millimetre or with its points in another
order, must give the same world: the same supports (heights within 0.1 mm) and the same objects.

Each layout's 200k-point cloud (float32 PLY) and merged mesh (OBJ) are written in every variant,
converted without flags (load, planes, segment) and compared with the metre version in the
converter's world frame: supports (observed ones, by height), their rectangle extents, and the
objects (Hungarian-matched by the centroids of their points).

    .venv/bin/python bench/bench_units.py [--layouts table:41,counter:42,floor:43,table:44]
        [--forms cloud,mesh] [--points 200000]

A layout is written ``name:seed`` as in bench_captures.py (a seeded draw of four objects).
"""

from __future__ import annotations

import argparse
import resource
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.optimize import linear_sum_assignment

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_captures import DETECT, bench_scene  # noqa: E402

from realsim.pipeline import run_pipeline  # noqa: E402
from realsim.scene import Scene  # noqa: E402
from realsim.synth import SynthScene, sample_cloud  # noqa: E402
from realsim.synth.exports import capture_transform, write_cloud, write_mesh_file  # noqa: E402
from realsim.synth.forms import apply  # noqa: E402

SHIFT_M = (0.00031, -0.00047, 0.00023)  # a sub-millimetre origin offset, below any capture's noise
VARIANTS = ("m", "cm", "mm", "shift", "perm")


@dataclass
class World:
    """What detection decided, in its world frame."""

    units: str
    heights: np.ndarray  # observed supports' heights, ascending (m)
    extents: np.ndarray  # (S, 2) their rectangle sizes, sorted per support (m)
    objects: np.ndarray  # (K, 3) centroids of the objects' points (m)
    cpu: float


def _cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def world_of(scene: Scene, cpu: float) -> World:
    """The supports and objects of a converted scene."""
    planes = sorted((p for p in scene.planes if p.observed), key=lambda p: p.height)
    heights = np.array([p.height for p in planes])
    extents = np.array([np.sort(p.rect_size) for p in planes]).reshape(-1, 2)
    labels = np.zeros(0, dtype=np.int64) if scene.labels is None else np.asarray(scene.labels)
    points = np.zeros((0, 3)) if scene.points is None else scene.points
    objects = np.array([points[labels == o.id].mean(axis=0) for o in scene.objects]).reshape(-1, 3)
    return World(scene.capture.units, heights, extents, objects, cpu)


def cloud_of(gt: SynthScene, points: int) -> tuple[np.ndarray, np.ndarray]:
    """The layout's sampled cloud (world points, colours), the same for every variant."""
    pts, cols, _ = sample_cloud(gt, points, seed=1)
    return pts, cols


def write_variant(gt: SynthScene, form: str, variant: str, dest: Path, cloud: tuple[np.ndarray, np.ndarray]) -> Path:
    """The scene as ``form`` (the mesh, or ``cloud`` from :func:`cloud_of`) in ``variant`` (units,
    a sub-mm shift or a permutation)."""
    units = variant if variant in ("m", "cm", "mm") else "m"
    offset = SHIFT_M if variant == "shift" else (0.0, 0.0, 0.0)
    to_capture = capture_transform(units, "+z", 0.0, 0.0, offset)
    if form == "mesh":
        return write_mesh_file(dest / f"mesh_{variant}.obj", gt, to_capture, usd_up="+z")
    pts, cols = cloud
    if variant == "perm":
        order = np.random.default_rng(7).permutation(len(pts))
        pts, cols = pts[order], cols[order]
    return write_cloud(dest / f"cloud_{variant}.ply", apply(to_capture, pts), cols, "ply")


def convert_world(source: Path) -> World:
    """Load, planes and segment ``source`` with no flags; its world and the CPU seconds taken."""
    start = _cpu()
    scene = run_pipeline(source, pipeline=DETECT)
    return world_of(scene, _cpu() - start)


def compare(ref: World, other: World) -> tuple[float, float, float]:
    """Max support height difference, max extent difference and max matched object distance (m);
    NaN where the counts differ."""
    nan = float("nan")
    if len(ref.heights) != len(other.heights):
        dh = de = nan
    else:
        dh = float(np.abs(ref.heights - other.heights).max(initial=0.0))
        de = float(np.abs(ref.extents - other.extents).max(initial=0.0))
    if len(ref.objects) != len(other.objects):
        return dh, de, nan
    if len(ref.objects) == 0:
        return dh, de, 0.0
    dist = np.linalg.norm(ref.objects[:, None] - other.objects[None], axis=2)
    rows, cols = linear_sum_assignment(dist)
    return dh, de, float(dist[rows, cols].max())


def run(layouts: list[str], forms: list[str], points: int) -> int:
    """Print the table; return the number of variants that differ from metres."""
    print(f"{'layout':11s} {'form':5s} {'variant':7s} {'read':4s} {'supports (mm)':24s} {'obj':>3s} "
          f"{'dh mm':>7s} {'dext mm':>7s} {'dpos mm':>7s} {'cpu s':>6s}")
    differ = 0
    with tempfile.TemporaryDirectory() as tmp:
        for key in layouts:
            gt = bench_scene(key)
            cloud = cloud_of(gt, points) if "cloud" in forms else (np.zeros((0, 3)), np.zeros((0, 3), dtype=np.uint8))
            for form in forms:
                ref: World | None = None
                for variant in VARIANTS if form == "cloud" else VARIANTS[:4]:
                    world = convert_world(write_variant(gt, form, variant, Path(tmp), cloud))
                    ref = ref or world
                    dh, de, dp = compare(ref, world)
                    bad = not (dh <= 1e-4 and de <= 0.02 and dp <= 1e-3)
                    differ += bad
                    heights = ",".join(f"{h * 1000:.1f}" for h in world.heights)
                    print(f"{key:11s} {form:5s} {variant:7s} {world.units:4s} {heights:24s} {len(world.objects):3d} "
                          f"{dh * 1000:7.3f} {de * 1000:7.1f} {dp * 1000:7.3f} {world.cpu:6.1f}{'  DIFFERS' if bad else ''}",
                          flush=True)
    print(f"\n{differ} variant(s) differ from metres (support height > 0.1 mm, extent > 20 mm, "
          "object count or position > 1 mm)")
    return differ


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--layouts", default="table:41,counter:42,floor:43,table:44")
    parser.add_argument("--forms", default="cloud,mesh")
    parser.add_argument("--points", type=int, default=200_000)
    args = parser.parse_args()
    run(args.layouts.split(","), args.forms.split(","), args.points)


if __name__ == "__main__":
    main()
