"""Benchmark of object segmentation on the annotated mOSD Kinect scenes.

For each scene: ground-truth object count, predicted count, mean per-object point IoU (Hungarian
matching of predicted to ground-truth objects; an unmatched ground-truth object scores 0), the
per-object IoUs and the segmentation time. The same table is printed for a plain Open3D
baseline (RANSAC plane + DBSCAN). Ground truth: the PCD ``label`` field, object id = label // 10
for labels >= 20 (mOSD convention).

Run: ``/work/venv/bin/python bench/bench_segmentation.py``
"""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import open3d as o3d
from scipy.spatial import Delaunay, cKDTree

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from realsim.metrics import matched_iou, mosd_object_ids  # noqa: E402
from realsim.perception.capture import load_capture  # noqa: E402
from realsim.perception.planes import detect_planes  # noqa: E402
from realsim.perception.segment import SegmentParams, segment_objects  # noqa: E402

MOSD = REPO.parent / "shared" / "data" / "pcl_scenes" / "mOSD"
SCENES = ("test0", "test31", "test45", "test55")


@dataclass
class Score:
    gt_count: int
    pred_count: int
    ious: np.ndarray  # per ground-truth object, in ground-truth id order
    seconds: float

    @property
    def mean_iou(self) -> float:
        return float(self.ious.mean()) if len(self.ious) else 0.0


def score(pred: np.ndarray, gt: np.ndarray, seconds: float) -> Score:
    return Score(len(np.unique(gt[gt > 0])), len(np.unique(pred[pred > 0])), matched_iou(pred, gt)[0], seconds)


def open3d_baseline(camera_points: np.ndarray, seed: int = 0, eps: float = 0.008) -> np.ndarray:
    """Plain Open3D: RANSAC table plane, points above it inside the table hull, DBSCAN clusters.

    ``camera_points`` (N, 3) in the camera frame with NaN rows; returns labels (0 background,
    -1 noise, k object) in input order.
    """
    labels = np.zeros(len(camera_points), dtype=np.int64)
    finite = np.flatnonzero(np.isfinite(camera_points).all(axis=1))
    pts = camera_points[finite]
    o3d.utility.random.seed(seed)
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(pts))
    (a, b, c, d), inliers = pcd.segment_plane(distance_threshold=0.01, ransac_n=3, num_iterations=1000)
    normal = np.array([a, b, c])
    if d < 0:  # orient toward the camera at the origin
        normal, d = -normal, -d
    dist = pts @ normal + d
    u = np.cross(normal, [1.0, 0.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    hull = Delaunay(np.stack([pts[inliers] @ u, pts[inliers] @ v], axis=1)[::10])
    above = (dist > 0.01) & (dist < 0.5) & (hull.find_simplex(np.stack([pts @ u, pts @ v], axis=1)) >= 0)
    # DBSCAN on a 3 mm voxel copy (full resolution is slow in Open3D), labels carried back by nearest neighbour
    obj = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(pts[above])).voxel_down_sample(0.003)
    coarse = np.asarray(obj.cluster_dbscan(eps=eps, min_points=5))
    _, nearest = cKDTree(np.asarray(obj.points)).query(pts[above])
    cluster = coarse[nearest]
    sizes = np.bincount(cluster[cluster >= 0]) if (cluster >= 0).any() else np.zeros(0, dtype=np.int64)
    keep = np.flatnonzero(sizes >= 200)
    remap = np.full(len(sizes) + 1, -1)
    remap[keep] = np.arange(1, len(keep) + 1)
    out = np.where(cluster >= 0, remap[cluster], -1)
    labels[finite[above]] = out
    return labels


def print_table(title: str, scores: dict[str, Score]) -> None:
    print(f"\n{title}")
    print(f"{'scene':8s} {'GT':>3s} {'pred':>4s} {'mean IoU':>8s} {'time s':>7s}  per-object IoU")
    for name, s in scores.items():
        ious = " ".join(f"{x:.2f}" for x in s.ious)
        flag = "" if s.gt_count == s.pred_count else " *"
        print(f"{name:8s} {s.gt_count:3d} {s.pred_count:4d}{flag:2s}{s.mean_iou:7.3f} {s.seconds:7.2f}  {ious}")
    all_ious = np.concatenate([s.ious for s in scores.values()])
    right = sum(s.gt_count == s.pred_count for s in scores.values())
    print(f"{'total':8s} mean IoU over {len(all_ious)} objects = {all_ious.mean():.3f}; "
          f"right count in {right}/{len(scores)} scenes")


def main() -> None:
    ours: dict[str, Score] = {}
    base: dict[str, Score] = {}
    params = SegmentParams()
    for name in SCENES:
        path = MOSD / f"{name}.pcd"
        scene = detect_planes(load_capture(path))
        gt = mosd_object_ids(scene.annotations)
        t0 = time.perf_counter()
        result = segment_objects(scene.points, scene.colors, scene.planes, scene.grid_shape, params, seed=0)
        ours[name] = score(result.labels, gt, time.perf_counter() - t0)
        stacked = {k: v for k, v in result.resting_on.items() if v is not None}
        if stacked:
            print(f"{name}: stacked objects (object -> object below): {stacked}")

        camera = np.linalg.solve(scene.capture.input_to_world[:3, :3], (scene.points - scene.capture.input_to_world[:3, 3]).T).T
        t0 = time.perf_counter()
        labels = open3d_baseline(camera)
        base[name] = score(labels, gt, time.perf_counter() - t0)
    print_table("realsim.perception.segment (supervoxels + convexity merging)", ours)
    print_table("Open3D baseline (RANSAC plane + DBSCAN eps 8 mm)", base)


if __name__ == "__main__":
    main()
