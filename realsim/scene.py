"""The typed record that flows through the conversion stages.

Everything here is in the world frame: right-handed, Z up, metres, kilograms, seconds.
Quaternions are MuJoCo order (w, x, y, z).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import trimesh

from realsim.perception.capture_config import CaptureConfig, DeclaredSupport

if TYPE_CHECKING:
    from realsim.assets import PreparedObject
    from realsim.physics import ObjectManifest


@dataclass
class CaptureInfo:
    """Where the capture came from and how it was brought into the world frame."""

    source: Path | None  # None only before the load stage, for a description alone
    kind: str  # "unread" (before load) | "pointcloud" | "mesh" | "objects" | "text" | ...
    environment_file: Path | None
    units: str  # "m" | "mm" | "cm"
    up: str  # "+z", "-y", "+y", ...
    units_detected: bool
    up_detected: bool
    input_to_world: np.ndarray  # (4, 4), maps input coordinates to world coordinates
    config: CaptureConfig = field(default_factory=CaptureConfig)  # what capture.yaml (and --text) said
    units_reason: str | None = None  # why detection chose the units
    point_spacing: float | None = None  # m: the capture's own resolution (median neighbour distance)
    camera_view: bool = False  # an organized view from one camera (its grid is a photo)
    surface_detail: float | None = None  # m: the finest detail the surface holds where the capture smoothed it
    # beyond its spacing (a fused sweep: its TSDF truncation band, over which creases are rounded); None: its spacing
    splat: Path | None = None  # the Gaussian splat PLY the points came from, kept for the viewer
    faces_turned: bool = False  # an environment mesh wound inward, turned before sampling
    photo: Path | None = None  # the photo of a photo-only capture
    fitted_intrinsics: Any = None  # realsim.perception.intrinsics.Intrinsics fitted from the grid, once


@dataclass
class SupportPlane:
    """A horizontal support surface (floor, table, counter, shelf) in the world frame."""

    id: int
    kind: str  # "floor" | "table" | "shelf"
    normal: np.ndarray  # (3,) unit normal, pointing up
    height: float  # z of the surface in the world frame
    polygon: np.ndarray  # (K, 2) convex hull of the inliers in xy, counter-clockwise
    rect_center: np.ndarray  # (2,) oriented rectangle centre (xy)
    rect_size: np.ndarray  # (2,) oriented rectangle side lengths
    rect_yaw: float  # oriented rectangle yaw (rad)
    inlier_count: int
    observed: bool = True  # False for an assumed surface (e.g. a floor below a table)

    @property
    def offset(self) -> float:
        """d of the plane equation n.x + d = 0."""
        return float(-self.normal[2] * self.height)

    def rect_local(self, xy: np.ndarray) -> np.ndarray:
        """World xy (..., 2) -> the oriented rectangle's frame (centre at 0, x along ``rect_size[0]``)."""
        c, s = np.cos(self.rect_yaw), np.sin(self.rect_yaw)
        return np.asarray((np.asarray(xy) - self.rect_center) @ np.array([[c, -s], [s, c]]))


@dataclass
class SceneObject:
    """One object: where it is, what it is made of and the geometry MuJoCo needs.

    ``position`` is the centre of the object's base in the world frame; the meshes are in the
    object frame whose origin is that point (Z up).
    """

    id: int
    name: str  # unique, MJCF-safe
    label: str
    position: np.ndarray  # (3,)
    quat: np.ndarray  # (4,) w, x, y, z
    size: np.ndarray  # (3,) axis-aligned extents in the object frame
    support_id: int | None = None  # plane the object rests on
    resting_on: int | None = None  # object id it is stacked on, if any
    point_count: int = 0
    color: np.ndarray | None = None  # (3,) mean RGB in [0, 1]
    visual: trimesh.Trimesh | None = None  # detailed mesh, object frame
    collision: list[trimesh.Trimesh] = field(default_factory=list)  # convex parts, object frame
    mass: float | None = None
    com: np.ndarray | None = None  # (3,) object frame
    inertia: np.ndarray | None = None  # (3, 3) about com, object frame
    friction: tuple[float, float, float] = (1.0, 0.005, 0.0001)
    solref: tuple[float, float] = (0.02, 1.0)
    manifest: Any = None  # ObjectManifest when the physics stage ran
    source_file: Path | None = None
    texture_png: bytes | None = None  # PNG for the visual mesh, when it has UVs
    notes: list[str] = field(default_factory=list)


@dataclass
class Scene:
    """The record every stage reads and extends."""

    capture: CaptureInfo
    seed: int = 0
    points: np.ndarray | None = None  # (N, 3) world frame, input order, NaN kept
    colors: np.ndarray | None = None  # (N, 3) float in [0, 1], or None
    normals: np.ndarray | None = None  # (N, 3) world-frame outward unit normals (a mesh capture's faces), or None
    grid_shape: tuple[int, int] | None = None  # (H, W) for organized clouds
    annotations: np.ndarray | None = None  # (N,) per-point labels shipped with the capture, if any
    planes: list[SupportPlane] = field(default_factory=list)
    labels: np.ndarray | None = None  # (N,) int32: 0 support/background, -1 noise, k object
    objects: list[SceneObject] = field(default_factory=list)
    object_files: list[Path] = field(default_factory=list)
    timings: dict[str, float] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    spec: Any = None  # mujoco.MjSpec once composed
    compiled: Any = None  # (spec, mujoco.MjModel): the spec as the stage just run compiled and left it, for the next stage (the pipeline keeps it one stage)
    assets: dict[str, bytes] = field(default_factory=dict)  # files of assets/, by name
    keyframe_qpos: np.ndarray | None = None
    settle_report: dict[str, Any] = field(default_factory=dict)
    robot: dict[str, Any] | None = None  # where the Panda stands, when the robot stage ran
    llm: dict[str, Any] | None = None  # Claude calls, tokens, cost, failures (realsim.understanding), when used
    support: DeclaredSupport | None = None  # the support objects go on without a scan (capture.yaml's, or the text's)
    scene_spec: Any = None  # realsim.text.schema.SceneSpec to build (from a photo), read by the text stage
    articulations: dict[str, dict[str, Any]] = field(default_factory=dict)  # child body -> joint (realsim.text), read by compose
    object_sites: dict[str, dict[str, list[float]]] = field(default_factory=dict)  # body -> {site: [x, y, z]} (realsim.text)
    photo_asset: str | None = None  # the photo kept in the output (assets/...), for the viewer

    @classmethod
    def unread(cls, source: Path | None, seed: int = 0) -> "Scene":
        """The record before the load stage: where the capture is, nothing read yet."""
        capture = CaptureInfo(source=source, kind="unread", environment_file=None, units="m", up="+z", units_detected=False,
                              up_detected=False, input_to_world=np.eye(4))
        return cls(capture=capture, seed=seed)

    @property
    def floor_height(self) -> float:
        """z of the floor: the lowest support (0 when there is none)."""
        floors = [p.height for p in self.planes if p.kind == "floor"]
        return min(floors) if floors else 0.0

    def plane(self, plane_id: int) -> SupportPlane:
        """The support plane with this id."""
        for p in self.planes:
            if p.id == plane_id:
                return p
        raise KeyError(plane_id)

    def warn(self, message: str) -> None:
        """Record a warning for the conversion report."""
        self.warnings.append(message)


def primary_support(scene: Scene) -> SupportPlane:
    """The main work surface: the largest non-floor support (observed ones first), else the floor."""
    tables = [p for p in scene.planes if p.kind != "floor"]
    return max(tables or scene.planes, key=lambda p: (p.observed, p.inlier_count, float(np.prod(p.rect_size))))


def scene_object(prepared: PreparedObject, manifest: ObjectManifest, object_id: int, name: str) -> SceneObject:
    """A SceneObject (object frame at the base centre) from a prepared mesh and its manifest."""
    ixx, iyy, izz, ixy, ixz, iyz = manifest.inertia
    return SceneObject(
        id=object_id,
        name=name,
        label=prepared.label,
        position=np.zeros(3),
        quat=np.array([1.0, 0.0, 0.0, 0.0]),
        size=np.asarray(prepared.size, dtype=np.float64),
        color=np.asarray(prepared.color, dtype=np.float64) if prepared.color is not None else None,
        visual=prepared.visual,
        collision=list(prepared.hulls),
        mass=manifest.mass_kg,
        com=np.asarray(manifest.com, dtype=np.float64),
        inertia=np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]),
        friction=manifest.friction,
        solref=manifest.solref,
        manifest=manifest,
        source_file=prepared.source,
        texture_png=prepared.texture_png,
        notes=list(prepared.warnings),
    )
