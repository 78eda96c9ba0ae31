"""Pinhole cameras over a SynthScene: poses and ray-cast RGB-D frames with per-pixel ground truth.

Rendering is an exact ray cast (Open3D ``RaycastingScene``) of the merged world mesh, shaded
with a fixed light; depth is along the optical axis. Kinect-like noise is added by the caller.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from realsim.synth.meshes import raycaster as make_raycaster
from realsim.synth.scene import SynthScene


@dataclass(frozen=True)
class Camera:
    """Intrinsics (pixels) and the optical-frame pose (+x right, +y down, +z forward) in the world."""

    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    pose: np.ndarray  # (4, 4) optical frame -> world

    @property
    def matrix(self) -> np.ndarray:
        return np.array([[self.fx, 0.0, self.cx], [0.0, self.fy, self.cy], [0.0, 0.0, 1.0]])


def look_at(eye: np.ndarray, target: np.ndarray, width: int = 640, height: int = 480, fovy_deg: float = 45.0,
            roll_deg: float = 0.0) -> Camera:
    """A camera at ``eye`` looking at ``target``, level or turned ``roll_deg`` about its optical axis
    (positive: the picture's +x axis dips below the horizon)."""
    fwd = np.asarray(target, float) - np.asarray(eye, float)
    fwd /= np.linalg.norm(fwd)
    right = np.cross(fwd, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    down = np.cross(fwd, right)
    if roll_deg:
        c, s = math.cos(math.radians(roll_deg)), math.sin(math.radians(roll_deg))
        right, down = c * right + s * down, c * down - s * right
    pose = np.eye(4)
    pose[:3, :3] = np.stack([right, down, fwd], axis=1)
    pose[:3, 3] = eye
    f = 0.5 * height / math.tan(math.radians(fovy_deg) / 2)
    return Camera(width, height, f, f, (width - 1) / 2, (height - 1) / 2, pose)


MAX_RANGE = 3.0  # m: farthest depth ``render`` returns (a Kinect's working range)
NEAR = 0.4  # m: nearest depth a Kinect measures


def object_points(scene: SynthScene) -> list[np.ndarray]:
    """World vertices of each ground-truth object, in ``scene.objects`` order."""
    faces = scene.mesh.faces
    return [scene.mesh.vertices[np.unique(faces[scene.face_object == obj.id])] for obj in scene.objects]


def out_of_view(scene: SynthScene, cam: Camera, margin_px: float = 0.0, max_range: float = MAX_RANGE) -> list[str]:
    """Names of the objects not wholly in the picture: a vertex projecting outside the image (less
    ``margin_px``), behind the camera or beyond ``max_range``."""
    world_to_optical = np.linalg.inv(cam.pose)
    names = []
    for obj, pts in zip(scene.objects, object_points(scene)):
        c = pts @ world_to_optical[:3, :3].T + world_to_optical[:3, 3]
        with np.errstate(divide="ignore", invalid="ignore"):
            u, v = cam.fx * c[:, 0] / c[:, 2] + cam.cx, cam.fy * c[:, 1] / c[:, 2] + cam.cy
        inside = ((c[:, 2] > 0) & (c[:, 2] <= max_range) & (u >= margin_px - 0.5) & (u <= cam.width - 0.5 - margin_px)
                  & (v >= margin_px - 0.5) & (v <= cam.height - 0.5 - margin_px))
        if not inside.all():
            names.append(obj.name)
    return names


def frame_points(points: np.ndarray, fwd: np.ndarray, distance: float, width: int = 640, height: int = 480,
                 fovy_deg: float = 45.0, margin_px: float = 24.0, roll_deg: float = 0.0) -> Camera:
    """A camera looking along ``fwd`` (turned ``roll_deg``) that holds every point in the picture
    ``margin_px`` in from the edges: aimed at the points' middle in the image, as far back as
    ``distance`` or as needed."""
    cam = look_at(np.zeros(3), np.asarray(fwd, float), width, height, fovy_deg, roll_deg)
    rot = cam.pose[:3, :3]
    kx = (width / 2 - margin_px) / cam.fx  # the largest |x / z| and |y / z| in the picture
    ky = (height / 2 - margin_px) / cam.fy

    def back(a: np.ndarray) -> float:  # the least distance holding points ``a`` (optical, about the target)
        return max(distance, float(np.max(np.maximum(np.abs(a[:, 0]) / kx, np.abs(a[:, 1]) / ky) - a[:, 2])), NEAR - float(a[:, 2].min()))

    target = points.mean(axis=0)
    for _ in range(4):  # centre the projected bounds (the last distance holds them whatever the centring)
        a = (points - target) @ rot  # optical coordinates about the target; depth is a_z + d
        d = back(a)
        x, y = a[:, 0] / (a[:, 2] + d), a[:, 1] / (a[:, 2] + d)
        target = target + rot[:, :2] @ (d * np.array([(x.min() + x.max()) / 2, (y.min() + y.max()) / 2]))
    d = back((points - target) @ rot)
    return look_at(target - d * rot[:, 2], target, width, height, fovy_deg, roll_deg)


def kinect_view(scene: SynthScene, rng: np.random.Generator, width: int = 640, height: int = 480,
                margin_px: float = 24.0, pitch_deg: tuple[float, float] = (38.0, 48.0), roll_deg: float = 0.0) -> Camera:
    """A tripod camera in front of the primary support looking down at its middle (like mOSD), seeded
    (pitch drawn from ``pitch_deg``; ``roll_deg`` tips it as a hand-held camera is tipped); when
    that picture would not hold every object wholly (``margin_px`` in from the edges), the same
    pitch, yaw and roll re-aimed at the objects and pulled back as far as needed (``out_of_view``
    names any the range still cannot hold)."""
    sup = scene.primary_support()
    distance = rng.uniform(1.0, 1.2) * (1.5 if sup.kind == "floor" else 1.0)
    pitch = math.radians(rng.uniform(*pitch_deg))
    yaw = math.radians(90.0 + rng.uniform(-10.0, 10.0))  # in front (-y), looking along +y
    target = np.array([sup.center[0] + rng.uniform(-0.05, 0.05), sup.center[1] + rng.uniform(-0.05, 0.05), sup.height])
    fwd = np.array([math.cos(yaw) * math.cos(pitch), math.sin(yaw) * math.cos(pitch), -math.sin(pitch)])
    cam = look_at(target - distance * fwd, target, width, height, roll_deg=roll_deg)
    if not scene.objects or not out_of_view(scene, cam, margin_px):
        return cam
    return frame_points(np.vstack(object_points(scene)), fwd, distance, width, height, margin_px=margin_px, roll_deg=roll_deg)


def orbit(scene: SynthScene, frames: int, rng: np.random.Generator, width: int = 640, height: int = 480,
          arc_deg: float = 200.0) -> list[Camera]:
    """A hand-held sweep: ``frames`` cameras on an arc around the primary support, looking at it
    (around the middle of all the tables, further out by their spread, when there are several)."""
    sup = scene.primary_support()
    centres = np.array([s.center for s in scene.supports if s.kind != "floor"] or [sup.center])
    middle = centres.mean(axis=0)
    spread = float(np.max(np.linalg.norm(centres - middle, axis=1)))
    target = np.array([middle[0], middle[1], sup.height + 0.05])
    start = math.radians(-90.0 - arc_deg / 2 + rng.uniform(-10, 10))
    cams = []
    for i in range(frames):
        ang = start + math.radians(arc_deg) * i / max(frames - 1, 1)
        radius = 0.95 + spread + 0.05 * math.sin(3 * ang) + rng.normal(0, 0.01)
        eye = target + np.array([radius * math.cos(ang), radius * math.sin(ang), 0.55 + rng.normal(0, 0.01)])
        cams.append(look_at(eye, target + rng.normal(0, 0.01, size=3), width, height))
    return cams


@dataclass
class Frame:
    """One rendered view: colour (H, W, 3) uint8, depth (H, W) metres (NaN: no surface), part and
    object id per pixel (0 none)."""

    color: np.ndarray
    depth: np.ndarray
    part: np.ndarray
    object_id: np.ndarray


def render(scene: SynthScene, cam: Camera, max_range: float = 3.0, raycaster=None) -> Frame:  # noqa: ANN001
    """Ray-cast the scene from ``cam``: noiseless depth along the optical axis, shaded colour."""
    import open3d as o3d

    rc = raycaster or make_raycaster(scene.mesh)
    u, v = np.meshgrid(np.arange(cam.width), np.arange(cam.height))
    dirs_cam = np.stack([(u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, np.ones_like(u, dtype=float)], axis=-1).reshape(-1, 3)
    rot = cam.pose[:3, :3]
    dirs = dirs_cam @ rot.T
    rays = np.hstack([np.broadcast_to(cam.pose[:3, 3], dirs.shape), dirs]).astype(np.float32)
    hit = rc.cast_rays(o3d.core.Tensor(rays))
    t = hit["t_hit"].numpy().astype(np.float64)  # in units of the (unnormalized) direction: t = depth
    prim = hit["primitive_ids"].numpy().astype(np.int64)
    ok = np.isfinite(t) & (t <= max_range)
    prim = np.where(ok, prim, 0)
    depth = np.where(ok, t, np.nan)
    normals = scene.mesh.face_normals[prim]
    light = np.array([0.3, -0.4, 1.0])
    light /= np.linalg.norm(light)
    shade = 0.45 + 0.55 * np.abs(normals @ light)
    vcol = scene.mesh.visual.vertex_colors[:, :3].astype(np.float64) / 255.0
    fcol = vcol[scene.mesh.faces[prim]].mean(axis=1)
    color = np.where(ok[:, None], fcol * shade[:, None], 0.0)
    shape = (cam.height, cam.width)
    return Frame(
        (np.clip(color, 0, 1) * 255).round().astype(np.uint8).reshape(*shape, 3),
        depth.reshape(shape),
        np.where(ok, scene.face_part[prim], 0).reshape(shape).astype(np.int32),
        np.where(ok, scene.face_object[prim], 0).reshape(shape).astype(np.int32),
    )


def kinect_noise(depth: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Axial Kinect-like noise (Nguyen et al. 2012, softened): ~1.2 mm at 1 m, 2.3 mm at 1.5 m."""
    z = np.nan_to_num(depth, nan=1.0)
    return depth + rng.standard_normal(depth.shape) * (0.0008 + 0.0012 * (z - 0.4) ** 2)


def view_cloud(scene: SynthScene, cam: Camera, rng: np.random.Generator) -> tuple[np.ndarray, Frame]:
    """What a Kinect-like camera captures: optical-frame points (H * W, 3) with seeded depth noise
    (NaN where nothing is in range) and the rendered frame (colour, parts, object ids)."""
    frame = render(scene, cam)
    return backproject(kinect_noise(frame.depth, rng), cam).reshape(-1, 3), frame


def backproject(depth: np.ndarray, cam: Camera) -> np.ndarray:
    """Depth (H, W) -> points (H, W, 3) in the optical frame (NaN where depth is NaN)."""
    u, v = np.meshgrid(np.arange(cam.width, dtype=float), np.arange(cam.height, dtype=float))
    return np.stack([(u - cam.cx) / cam.fx * depth, (v - cam.cy) / cam.fy * depth, depth], axis=-1)
