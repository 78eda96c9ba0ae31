"""How well does completion recover what the camera could not see? (real YCB meshes, ground truth)

Scenes from :mod:`realsim.synth` (real YCB scans on a table, seeded layouts) are written as one
organized Kinect-like view, converted (no robot), and every ground-truth object is matched to the
converted object holding most of its pixels. Per object: volume IoU of the completed solid (at
its composed pose) with the true mesh (occupancy on a 2 mm grid), the oriented size error (sorted
extents of the oriented bounding boxes) and whether it was found once. Run:

    .venv/bin/python bench/bench_completion.py [--seeds 0 1 2] [--objects 5] [--baseline]
"""

from __future__ import annotations

import argparse
import json
import tempfile
from pathlib import Path

import numpy as np
import open3d as o3d
import trimesh
from scipy.spatial.transform import Rotation

from realsim.pcd_io import read_pcd
from realsim.pipeline import convert
from realsim.synth import SceneSpec, make_scene, write_organized_view

GRID = 0.002


def occupancy(mesh: trimesh.Trimesh, points: np.ndarray) -> np.ndarray:
    """Inside test for a closed (or nearly closed) surface: Open3D's ray-parity occupancy."""
    scene = o3d.t.geometry.RaycastingScene()
    scene.add_triangles(o3d.core.Tensor(np.asarray(mesh.vertices, np.float32)), o3d.core.Tensor(np.asarray(mesh.faces, np.uint32)))
    return scene.compute_occupancy(o3d.core.Tensor(points.astype(np.float32))).numpy() > 0.5


def volume_iou(parts: list[trimesh.Trimesh], b: trimesh.Trimesh) -> float:
    """IoU of the union of convex ``parts`` with the solid bounded by ``b``."""
    lo = np.minimum(np.min([p.bounds[0] for p in parts], axis=0), b.bounds[0])
    hi = np.maximum(np.max([p.bounds[1] for p in parts], axis=0), b.bounds[1])
    axes = [np.arange(x + GRID / 2, y, GRID) for x, y in zip(lo, hi)]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    ia = np.any([occupancy(p, grid) for p in parts], axis=0)
    ib = occupancy(b, grid)
    union = np.count_nonzero(ia | ib)
    return float(np.count_nonzero(ia & ib)) / union if union else 0.0


def obb_extents(mesh: trimesh.Trimesh) -> np.ndarray:
    return np.sort(np.asarray(mesh.bounding_box_oriented.primitive.extents, float))[::-1]


BASELINE = {"complete": {"carve": False, "containers": {"enabled": False}, "mirror_max_depth_share": 1e-6}}  # extrusion and cylinders only


def measure(seed: int, n_objects: int, root: Path, baseline: bool = False) -> list[dict]:
    scene = make_scene(SceneSpec(layout="table", n_objects=n_objects, stacked=True, touching=True, seed=seed))
    capture = root / f"seed{seed}"
    capture.mkdir(parents=True)
    form = write_organized_view(scene, capture / "view.pcd", seed=seed)
    out = root / f"out{seed}"
    convert(capture / "view.pcd", out, overrides={"robot": {"enabled": False}, **(BASELINE if baseline else {})})
    record = json.loads((out / "scene.json").read_text())
    synth_to_realsim = np.asarray(record["capture"]["input_to_world"]) @ np.linalg.inv(np.asarray(form["capture_to_world"]))
    labels = np.load(out / "labels.npy")
    gt_ids = read_pcd(capture / "view.pcd").labels
    gt_ids = np.where(gt_ids >= 10, gt_ids // 10, 0)
    rows = []
    for obj in scene.objects:
        mine = labels[gt_ids == obj.id]
        found = np.unique(mine[mine > 0])
        counts = {int(k): int(np.count_nonzero(mine == k)) for k in found}
        row = {"seed": seed, "name": obj.name, "pixels": int(np.count_nonzero(gt_ids == obj.id)), "clusters": len([k for k, c in counts.items() if c > 0.1 * len(mine)])}
        if not counts:
            rows.append({**row, "iou": 0.0, "size_err_mm": float("nan")})
            continue
        best = max(counts, key=counts.get)
        rec = next(o for o in record["objects"] if o["id"] == best)
        hulls = [trimesh.load(out / "assets" / f"{rec['name']}_collision_{i}.stl") for i in range(64)
                 if (out / "assets" / f"{rec['name']}_collision_{i}.stl").is_file()]
        pose = np.eye(4)
        pose[:3, :3] = Rotation.from_quat(np.roll(rec["quat_wxyz"], -1)).as_matrix()
        pose[:3, 3] = rec["position"]
        for h in hulls:
            h.apply_transform(pose)
        solid = trimesh.util.concatenate(hulls)
        truth = obj.mesh()
        truth.apply_transform(synth_to_realsim)  # the conversion levels and centres the scene its own way
        rows.append({**row, "iou": volume_iou(hulls, truth), "size_err_mm": float(np.max(np.abs(obb_extents(solid) - obb_extents(truth))) * 1000),
                     "label": rec["label"], "hollow": any("open container" in n for n in rec["notes"])})
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", nargs="*", type=int, default=[0, 1, 2])
    parser.add_argument("--objects", type=int, default=5)
    parser.add_argument("--baseline", action="store_true", help="without free-space carving, hollow containers and mirroring")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        rows = [r for seed in args.seeds for r in measure(seed, args.objects, Path(tmp), args.baseline)]
    print(f"{'seed':>4s} {'object':28s} {'pixels':>7s} {'found':>5s} {'IoU':>5s} {'size err mm':>11s}  name given")
    for r in rows:
        print(f"{r['seed']:4d} {r['name']:28s} {r['pixels']:7d} {r['clusters']:5d} {r['iou']:5.2f} {r['size_err_mm']:11.1f}  "
              f"{r.get('label', '-')}{' (hollow)' if r.get('hollow') else ''}")
    ious = [r["iou"] for r in rows]
    errs = [r["size_err_mm"] for r in rows if np.isfinite(r["size_err_mm"])]
    print(f"\n{len(rows)} objects: median volume IoU {np.median(ious):.2f} (min {np.min(ious):.2f}), median oriented size error "
          f"{np.median(errs):.1f} mm, found once {sum(r['clusters'] == 1 for r in rows)}/{len(rows)}")


if __name__ == "__main__":
    main()
