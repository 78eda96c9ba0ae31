"""Write a SynthScene in every capture form, each with the transform back to the ground-truth world.

Every writer returns a dict for ``ground_truth.json``'s ``forms`` entry: the file(s), their
units and up axis, and ``capture_to_world`` (4x4: capture coordinates -> ground-truth world),
so a converter's output can be compared in the ground-truth frame.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

from realsim.synth.camera import backproject, kinect_noise, kinect_view, orbit, out_of_view, render
from realsim.synth.meshes import raycaster
from realsim.synth.scene import SynthScene

UNIT_SCALE = {"m": 1.0, "cm": 100.0, "mm": 1000.0}  # capture units per metre
# world (Z up) -> capture axes, for each supported up axis of the written file
FORMS = ("view", "sequence", "cloud", "mesh", "splat")  # what write_all can write
_UP = {"+z": np.eye(3), "+y": np.array([[1.0, 0, 0], [0, 0, 1.0], [0, -1.0, 0]])}


def world_to_capture(units: str = "m", up: str = "+z", offset: np.ndarray | None = None) -> np.ndarray:
    """4x4 taking world points to a capture frame with these units, up axis and origin offset."""
    t = np.eye(4)
    t[:3, :3] = _UP[up] * UNIT_SCALE[units]
    if offset is not None:
        t[:3, 3] = offset
    return t


def apply(t: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """Points through a 4x4 transform."""
    return pts @ t[:3, :3].T + t[:3, 3]


def write_organized_view(scene: SynthScene, path: Path, seed: int = 0, width: int = 640, height: int = 480) -> dict[str, Any]:
    """A Kinect-like organized PCD in the camera optical frame (metres, +y down) with the mOSD
    ``label`` field (1 support top, 2 other furniture, 3 floor, 4 background, 10 * id objects). The
    camera frames every object; ``out_of_view`` names any it could not hold in the picture."""
    from realsim.perception.pcd_io import write_pcd

    rng = np.random.default_rng([seed, 11])
    cam = kinect_view(scene, rng, width, height)
    frame = render(scene, cam)
    depth = kinect_noise(frame.depth, rng)
    pts = backproject(depth, cam).reshape(-1, 3)
    labels = np.where(np.isfinite(pts).all(axis=1), frame.part.reshape(-1), 0)
    write_pcd(path, pts, colors=frame.color.reshape(-1, 3), labels=labels, grid_shape=(height, width), encoding="binary_compressed")
    return {"file": path.name, "form": "organized_view", "units": "m", "up": "-y", "capture_to_world": cam.pose,
            "intrinsics": cam.matrix, "out_of_view": out_of_view(scene, cam), "label_field": "mOSD: 1 support top, 2 furniture, 3 floor, 4 background, 10*id object"}


def write_rgbd_sequence(scene: SynthScene, folder: Path, frames: int = 30, seed: int = 0, width: int = 640,
                        height: int = 480) -> dict[str, Any]:
    """A hand-held RGB-D sweep in the Stray Scanner layout (see ``realsim.perception.rgbd``): ``rgb/NNNNNN.png``,
    ``depth/NNNNNN.png`` (uint16 mm, 0 = none), ``camera_matrix.csv``, ``odometry.csv`` (ARKit
    camera poses in a gravity-aligned Y-up world whose origin is the first camera)."""
    from PIL import Image

    rng = np.random.default_rng([seed, 13])
    cams = orbit(scene, frames, rng, width, height)
    (folder / "rgb").mkdir(parents=True, exist_ok=True)
    (folder / "depth").mkdir(parents=True, exist_ok=True)
    # capture (ARKit) world: Y up, origin at the first camera
    to_cap = world_to_capture("m", "+y")
    to_cap[:3, 3] = -to_cap[:3, :3] @ cams[0].pose[:3, 3]
    rc = raycaster(scene.mesh)
    arkit_from_optical = np.diag([1.0, -1.0, -1.0])
    rows = ["timestamp, frame, x, y, z, qx, qy, qz, qw"]
    from scipy.spatial.transform import Rotation

    for i, cam in enumerate(cams):
        frame = render(scene, cam, raycaster=rc)
        depth = kinect_noise(frame.depth, rng)
        mm = np.where(np.isfinite(depth), np.clip(np.round(depth * 1000), 0, 65535), 0).astype(np.uint16)
        Image.fromarray(frame.color).save(folder / "rgb" / f"{i:06d}.png")
        Image.fromarray(mm).save(folder / "depth" / f"{i:06d}.png")
        pose = to_cap @ cam.pose
        rot = pose[:3, :3] @ arkit_from_optical
        q = Rotation.from_matrix(rot).as_quat()  # x, y, z, w
        x, y, z = pose[:3, 3]
        rows.append(f"{i / 30:.6f}, {i}, {x:.6f}, {y:.6f}, {z:.6f}, {q[0]:.8f}, {q[1]:.8f}, {q[2]:.8f}, {q[3]:.8f}")
    (folder / "odometry.csv").write_text("\n".join(rows) + "\n")
    k = cams[0].matrix
    (folder / "camera_matrix.csv").write_text("\n".join(", ".join(f"{v:.6f}" for v in row) for row in k) + "\n")
    return {"file": folder.name, "form": "rgbd_sequence", "units": "m", "up": "+y", "frames": frames,
            "capture_to_world": np.linalg.inv(to_cap)}


def visible_faces(scene: SynthScene, seed: int = 0, views: int = 24) -> np.ndarray:
    """Faces seen from a ring of viewpoints around and above the scene (what a scanner could see)."""
    import open3d as o3d

    rng = np.random.default_rng([seed, 17])
    sup = scene.primary_support()
    centre = np.array([sup.center[0], sup.center[1], sup.height])
    eyes = []
    for i in range(views):
        ang = 2 * np.pi * i / views + rng.uniform(0, 0.2)
        r = [0.9, 1.4, 2.0][i % 3]
        eyes.append(centre + [r * np.cos(ang), r * np.sin(ang), [0.5, 0.9, 0.2][i % 3]])
    rc = raycaster(scene.mesh)
    c = scene.mesh.triangles_center
    n = scene.mesh.face_normals
    seen = np.zeros(len(c), dtype=bool)
    origin = c + n * 1e-4
    for eye in eyes:
        d = eye - origin
        dist = np.linalg.norm(d, axis=1)
        facing = (d * n).sum(axis=1) > 0
        rays = np.hstack([origin, d / dist[:, None]]).astype(np.float32)
        t = rc.cast_rays(o3d.core.Tensor(rays[facing]))["t_hit"].numpy()
        idx = np.flatnonzero(facing)
        seen[idx[t >= dist[idx] - 1e-3]] = True
    return seen


def sample_cloud(scene: SynthScene, count: int, seed: int = 0, noise: float = 0.002) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``count`` world points sampled by area on the visible faces, with isotropic Gaussian
    ``noise`` (m): (points (N, 3), colours (N, 3) uint8, object id (N,))."""
    pts, pick = sample_surface(scene, count, seed, noise)
    vcol = scene.mesh.visual.vertex_colors[:, :3]
    return pts, vcol[scene.mesh.faces[pick, 0]], scene.face_object[pick]


def sample_surface(scene: SynthScene, count: int, seed: int = 0, noise: float = 0.002) -> tuple[np.ndarray, np.ndarray]:
    """``count`` noisy world points by area on the visible faces, and the face each lies on."""
    rng = np.random.default_rng([seed, 19])
    faces = np.flatnonzero(visible_faces(scene, seed))
    area = scene.mesh.area_faces[faces]
    pick = faces[rng.choice(len(faces), size=count, p=area / area.sum())]
    tri = scene.mesh.triangles[pick]
    r = rng.random((count, 2))
    flip = r.sum(axis=1) > 1
    r[flip] = 1 - r[flip]
    pts = tri[:, 0] + r[:, :1] * (tri[:, 1] - tri[:, 0]) + r[:, 1:] * (tri[:, 2] - tri[:, 0])
    pts += rng.standard_normal(pts.shape) * noise
    return pts, pick


def write_point_cloud(scene: SynthScene, path: Path, count: int = 200_000, seed: int = 0, noise: float = 0.002,
                      units: str = "m", up: str = "+z") -> tuple[dict[str, Any], np.ndarray]:
    """An unorganized cloud (binary PLY, or ASCII ``.xyz``) in the given units and up axis.
    Returns the ground-truth entry and the object id of every written point (file order)."""
    import open3d as o3d

    pts, cols, ids = sample_cloud(scene, count, seed, noise)
    t = world_to_capture(units, up)
    cap = apply(t, pts)
    if path.suffix.lower() == ".xyz":
        np.savetxt(path, np.hstack([cap, cols]), fmt=["%.6f"] * 3 + ["%d"] * 3)
    else:
        pcd = o3d.t.geometry.PointCloud(o3d.core.Tensor(cap.astype(np.float32)))
        pcd.point.colors = o3d.core.Tensor(cols.astype(np.uint8))
        o3d.t.io.write_point_cloud(str(path), pcd, write_ascii=False)
    return {"file": path.name, "form": "point_cloud", "units": units, "up": up, "points": count, "noise_m": noise,
            "capture_to_world": np.linalg.inv(t)}, ids


def write_mesh(scene: SynthScene, path: Path, units: str = "mm", up: str = "+y") -> dict[str, Any]:
    """The merged world mesh with vertex colours; glTF/GLB default Y-up millimetres (any trimesh format)."""
    t = world_to_capture(units, up)
    mesh = scene.mesh.copy()
    mesh.apply_transform(t)
    mesh.export(path)
    return {"file": path.name, "form": "mesh", "units": units, "up": up, "faces": len(mesh.faces),
            "capture_to_world": np.linalg.inv(t)}


def ground_truth(scene: SynthScene, forms: list[dict[str, Any]]) -> dict[str, Any]:
    """The ground-truth record (world frame: Z up, metres, floor top at z = 0)."""
    spec = scene.spec
    return _jsonable({
        "generator": "realsim.synth",
        "spec": {"layout": spec.layout, "objects": [o.name for o in scene.objects], "seed": spec.seed,
                 "stacked": spec.stacked, "touching": spec.touching, "floor_size": spec.floor_size},
        "world_frame": "right-handed, Z up, metres, floor top at z = 0",
        "supports": [{"name": s.name, "kind": s.kind, "height": s.height, "center": s.center, "size": s.size, "yaw": s.yaw,
                      "thickness": s.thickness} for s in scene.supports],
        "objects": [{"id": o.id, "name": o.name, "mesh_file": str(o.mesh_file), "pose": o.pose, "support": o.support,
                     "resting_on": o.resting_on, "touching": o.touching, "color": o.color,
                     "size": o.mesh().extents} for o in scene.objects],
        "forms": forms,
    })


def _jsonable(v: Any) -> Any:
    if isinstance(v, dict):
        return {str(k): _jsonable(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_jsonable(x) for x in v]
    if isinstance(v, np.ndarray):
        return _jsonable(v.tolist())
    if isinstance(v, (float, np.floating)):
        r = round(float(v), 6)
        return 0.0 if r == 0 else r
    if isinstance(v, np.integer):
        return int(v)
    return v


def write_all(scene: SynthScene, dest: Path, forms: tuple[str, ...] = ("view", "sequence", "cloud", "mesh"),
              cloud_points: int = 200_000, frames: int = 30, seed: int = 0) -> Path:
    """Write the chosen forms into ``dest`` (``view.pcd``, ``sequence/``, ``cloud.ply`` with
    ``cloud_labels.npy``, ``mesh.glb``, ``splat.ply`` with ``splat_labels.npy``) and
    ``ground_truth.json``. Returns ``dest``."""
    from realsim.errors import InputError

    unknown = sorted(set(forms) - set(FORMS))
    if unknown:
        raise InputError(f"unknown capture form {', '.join(unknown)}: choose from {', '.join(FORMS)}")
    dest = Path(dest)
    dest.mkdir(parents=True, exist_ok=True)
    entries = []
    if "view" in forms:
        entries.append(write_organized_view(scene, dest / "view.pcd", seed))
    if "sequence" in forms:
        entries.append(write_rgbd_sequence(scene, dest / "sequence", frames, seed))
    if "cloud" in forms:
        entry, ids = write_point_cloud(scene, dest / "cloud.ply", cloud_points, seed)
        np.save(dest / "cloud_labels.npy", ids.astype(np.int32))
        entry["labels"] = "cloud_labels.npy"
        entries.append(entry)
    if "mesh" in forms:
        entries.append(write_mesh(scene, dest / "mesh.glb"))
    if "splat" in forms:
        from realsim.synth.splat import write_splat  # splat.py builds on this module's sampling

        entry, ids = write_splat(scene, dest / "splat.ply", cloud_points, seed)
        np.save(dest / "splat_labels.npy", ids.astype(np.int32))
        entry["labels"] = "splat_labels.npy"
        entries.append(entry)
    (dest / "ground_truth.json").write_text(json.dumps(ground_truth(scene, entries), indent=1) + "\n")
    return dest
