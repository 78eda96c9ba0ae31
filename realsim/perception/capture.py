"""Load a capture (a single file or a folder) into a :class:`Scene`.

A capture is either one file — a point cloud (PCD, PLY) or an environment mesh (OBJ, STL, PLY,
GLB/glTF, sampled to points) — or a folder holding ``scene.*`` (the environment),
``objects/*`` (object meshes) and an optional ``capture.yaml``::

    units: m            # m | cm | mm (detected when absent)
    up: "-y"            # +z | -z | +y | -y | +x | -x (detected when absent)
    labels: {2: mug}    # names of the objects annotated in the cloud's ``label`` field
                        # (object id = label // 10 for labels >= 20, the mOSD convention),
                        # or of object files by file stem
    support_height: 0.75  # assumed height of the lowest support when no floor is seen
    text: "a table with a mug and two soda cans"  # a scene from a description (the `text` pipeline)

A scene can also come from a description alone: ``load_capture(None, LoadParams(text=...))``
(the CLI's ``--text``) or a ``.txt`` file holding it.

Loading converts units and the up axis; the `level` stage then aligns gravity with the
dominant support. Both transforms are composed into ``capture.input_to_world``.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from realsim.errors import InputError
from realsim.perception.capture_config import NAMED_ONLY_UNITS, CaptureConfig, read_capture_config
from realsim.perception.formats import (
    MESH_SUFFIXES,
    POINT_CLOUD_SUFFIXES,
    USD_SUFFIXES,
    forget_mesh_files,
    is_point_cloud_ply,
    read_mesh_file,
)
from realsim.perception.lone_object import is_lone_object
from realsim.perception.resolution import UNIT_SCALE, check_scale, detect_up, distant_origin, plausible_units, point_spacing
from realsim.perception.rgbd import FusionParams, is_rgbd_sequence
from realsim.scene import CaptureInfo, Scene
from realsim.viewer.splat import is_splat_ply, read_splat_ply

UP_AXES = ("+x", "-x", "+y", "-y", "+z", "-z")
MIN_CAPTURE_POINTS = 100  # fewer finite points than this cannot show a support and an object


@dataclass(frozen=True)
class LoadParams:
    """Parameters of the load stage."""

    units: str | None = None  # override unit detection
    up: str | None = None  # override up-axis detection
    mesh_sample_spacing: float = 0.005  # environment meshes are sampled by area this finely (m): 3 cm objects
    mesh_max_points: int = 2_000_000  # ... up to this many points
    mesh_pilot_points: int = 100_000  # points sampled first to find the up axis and the units
    text: str | None = None  # a scene description (``--text``): wins over capture.yaml's ``text:``


@dataclass
class RawCloud:
    """Points as read from the file, before any transform."""

    points: np.ndarray
    colors: np.ndarray | None
    grid_shape: tuple[int, int] | None
    is_camera_view: bool
    fmt: str
    annotations: np.ndarray | None = None
    mesh: Any = None  # trimesh.Trimesh of an environment mesh (points are a pilot sample until resampled)
    units_hint: str | None = None  # units and up axis the file itself declares (USD, RGB-D sequences)
    up_hint: str | None = None
    splat: Path | None = None  # a Gaussian splat PLY read as its centres
    normals: np.ndarray | None = None  # (N, 3) unit face normals of points sampled from a consistently wound mesh
    faces_turned: bool = False  # the mesh was wound inward and was turned (mesh_sides)


def up_rotation(up: str) -> np.ndarray:
    """Rotation (3x3) taking the given input up axis to world +Z (a proper rotation)."""
    if up not in UP_AXES:
        raise InputError(f"unknown up axis {up!r}: use one of {', '.join(UP_AXES)}")
    axis = np.zeros(3)
    axis["xyz".index(up[1])] = 1.0 if up[0] == "+" else -1.0
    z = np.array([0.0, 0.0, 1.0])
    if np.allclose(axis, z):
        return np.eye(3)
    if np.allclose(axis, -z):
        return np.diag([1.0, -1.0, -1.0])
    # Camera-style frames (+y down / +y up): keep the input's forward (+z) pointing along world +x
    # where possible, so a camera capture looks along +x in the world.
    if up in ("-y", "+y"):
        forward = np.array([0.0, 0.0, 1.0])
    else:
        forward = np.cross(z, axis)
        forward /= np.linalg.norm(forward)
    left = np.cross(axis, forward)
    # Rows are the world axes expressed in input coordinates: world x = forward, y = left, z = up.
    return np.vstack([forward, left, axis])


def _read_point_file(path: Path) -> RawCloud:
    suffix = path.suffix.lower()
    if suffix == ".pcd":
        from realsim.perception.pcd_io import read_pcd

        data = read_pcd(path)
        is_camera = data.grid_shape is not None and data.grid_shape[0] > 1
        return RawCloud(data.points, data.colors, data.grid_shape, is_camera, "pcd", data.labels)
    if suffix in (".xyz", ".pts"):
        from realsim.perception.text_points import read_text_points

        pts, colors = read_text_points(path)
        return RawCloud(pts, colors, None, False, suffix[1:])
    raise InputError(f"{path}: unsupported point cloud format {suffix!r}")


def _load_mesh_points(path: Path, count: int, seed: int) -> RawCloud:
    """Sample an environment mesh to points (seeded), keeping vertex/face colour when present."""
    import trimesh

    try:
        as_points = path.suffix.lower() == ".ply" and is_point_cloud_ply(path)
        loaded = trimesh.load(path, process=False) if as_points else read_mesh_file(path)
    except InputError:
        raise
    except Exception as exc:  # trimesh raises many types for corrupt files
        raise InputError(f"{path}: cannot read mesh ({type(exc).__name__}: {exc})") from None
    if isinstance(loaded, trimesh.PointCloud):
        pts = np.asarray(loaded.vertices, dtype=np.float64)
        cols = None
        if getattr(loaded, "colors", None) is not None and len(loaded.colors) == len(pts):
            cols = np.asarray(loaded.colors)[:, :3] / 255.0
        return RawCloud(pts, cols, None, False, path.suffix[1:].lower())
    if not isinstance(loaded, trimesh.Trimesh) or len(loaded.faces) == 0:
        verts = getattr(loaded, "vertices", np.zeros((0, 3)))
        if len(verts) == 0:
            raise InputError(f"{path}: the file holds no geometry")
        return RawCloud(np.asarray(verts, dtype=np.float64), None, None, False, path.suffix[1:].lower())
    check_mesh_arrays(path, np.asarray(loaded.vertices), np.asarray(loaded.faces))
    pts, cols, _ = sample_mesh(loaded, count, seed, path)
    return RawCloud(pts, cols, None, False, path.suffix[1:].lower(), mesh=loaded)


def sample_mesh(mesh: Any, count: int, seed: int, path: Path) -> tuple[np.ndarray, np.ndarray | None, np.ndarray]:
    """``count`` points sampled by area (seeded): points, colours in [0, 1] (vertex, face or texture
    colour; None without colour) and the face normal of each point."""
    import trimesh

    try:
        pts, face_idx = trimesh.sample.sample_surface(mesh, count, seed=seed)
    except (ValueError, IndexError, TypeError) as exc:  # degenerate data trimesh cannot sample
        raise InputError(f"{path}: corrupt mesh ({type(exc).__name__}: {exc})") from None
    cols = None
    try:
        visual = mesh.visual
        if visual.kind == "texture" and getattr(visual.material, "image", None) is not None:
            visual = visual.to_color()
        if visual.kind == "vertex":  # a face's mean colour, once per face when the samples outnumber the faces
            faces = np.asarray(mesh.faces)
            if len(face_idx) > len(faces):
                cols = np.asarray(visual.vertex_colors)[faces, :3].mean(axis=1)[face_idx] / 255.0
            else:
                cols = np.asarray(visual.vertex_colors)[faces[face_idx], :3].mean(axis=1) / 255.0
        elif visual.kind == "face":
            cols = np.asarray(visual.face_colors)[face_idx, :3] / 255.0
    except Exception:  # colour is optional: a broken material leaves the points uncoloured
        cols = None
    return np.asarray(pts, dtype=np.float64), cols, np.asarray(mesh.face_normals)[face_idx]


def resample_mesh(cloud: RawCloud, to_world: np.ndarray, params: LoadParams, seed: int, path: Path,
                  origin: np.ndarray | None = None) -> RawCloud:
    """Sample an environment mesh by area at ``mesh_sample_spacing`` (in metres, through
    ``to_world``; shifted by ``-origin`` when given), dropping points on downward-facing faces: the underside of a table top or a
    floor slab is never a support, and object bottoms are hidden on their support. Faces wound inward
    are turned first (:mod:`realsim.perception.mesh_sides`)."""
    from realsim.perception.mesh_sides import with_outward_faces

    scale = float(abs(np.linalg.det(to_world))) ** (1.0 / 3.0)  # metres per input unit
    area_m2 = float(cloud.mesh.area) * scale**2
    count = int(np.clip(area_m2 / params.mesh_sample_spacing**2, params.mesh_pilot_points, params.mesh_max_points))
    up = to_world[2, :3] / np.linalg.norm(to_world[2, :3])  # world +Z in input coordinates
    mesh, turned = with_outward_faces(cloud.mesh, up, scale)
    pts, cols, normals = sample_mesh(mesh, count, seed, path)
    keep = normals @ up > -0.3
    pts = pts if origin is None else pts - origin
    outward = normals[keep] if mesh.is_winding_consistent else None  # else the sides of faces cannot be told
    return RawCloud(pts[keep], None if cols is None else cols[keep], None, False, cloud.fmt, normals=outward,
                    faces_turned=turned)


def normals_to_world(normals: np.ndarray | None, to_world: np.ndarray) -> np.ndarray | None:
    """Unit normals through the linear part of ``to_world`` (inverse transpose; None stays None)."""
    if normals is None:
        return None
    out = normals @ np.linalg.inv(to_world[:3, :3])
    unit: np.ndarray = out / np.maximum(np.linalg.norm(out, axis=1, keepdims=True), 1e-12)
    return unit


def check_mesh_arrays(path: Path, vertices: np.ndarray, faces: np.ndarray) -> None:
    """InputError unless vertices are (N, 3) finite, faces (M, 3) index existing vertices."""
    if vertices.ndim != 2 or vertices.shape[1] != 3 or faces.ndim != 2 or faces.shape[1] != 3:
        raise InputError(f"{path}: corrupt mesh (vertices {vertices.shape}, faces {faces.shape}; expected (N, 3) and (M, 3))")
    if faces.size and (faces.min() < 0 or faces.max() >= len(vertices)):
        raise InputError(f"{path}: corrupt mesh (faces refer to vertices the file does not hold)")
    if not np.isfinite(vertices).all():
        raise InputError(f"{path}: corrupt mesh (non-finite vertex coordinates)")


def read_environment(path: Path, params: LoadParams, seed: int) -> RawCloud:
    """Read the environment file (point cloud or mesh) of a capture."""
    if not path.exists():
        raise InputError(f"{path}: no such file")
    if path.is_file() and path.stat().st_size == 0:
        raise InputError(f"{path}: the file is empty")
    suffix = path.suffix.lower()
    if path.is_dir():
        from realsim.perception.rgbd import fuse_sequence

        pts, cols = fuse_sequence(path)
        cloud = RawCloud(pts, cols, None, False, "rgbd", units_hint="m", up_hint="+y")
    elif suffix == ".ply" and is_splat_ply(path):
        try:
            splats = read_splat_ply(path)
        except (ValueError, KeyError) as exc:  # a truncated or malformed body
            raise InputError(f"{path}: corrupt Gaussian splat PLY ({str(exc)[:80]}); re-export it") from None
        solid = splats.opacities[:, 0] >= 0.2  # faint splats are floaters, not surfaces
        cloud = RawCloud(splats.centers[solid].astype(np.float64), splats.rgbs[solid].astype(np.float64), None, False, "ply", splat=path)
    elif suffix == ".ply" and is_point_cloud_ply(path):
        cloud = _load_mesh_points(path, params.mesh_pilot_points, seed)
    elif suffix in POINT_CLOUD_SUFFIXES - {".ply"}:
        cloud = _read_point_file(path)
    elif suffix in MESH_SUFFIXES:
        cloud = _load_mesh_points(path, params.mesh_pilot_points, seed)
    elif suffix in USD_SUFFIXES:
        from realsim.perception.usd_mesh import read_usd_mesh

        mesh, units_hint, up_hint = read_usd_mesh(path)
        usd_points, usd_colours, _ = sample_mesh(mesh, params.mesh_pilot_points, seed, path)
        cloud = RawCloud(usd_points, usd_colours, None, False, "usd", mesh=mesh, units_hint=units_hint, up_hint=up_hint)
    else:
        raise InputError(
            f"{path}: unsupported capture format {suffix or '(no extension)'!r}; "
            "use PCD, PLY, XYZ, OBJ, STL, GLB, glTF or USD (or an RGB-D sequence folder)"
        )
    if cloud.points.ndim != 2 or cloud.points.shape[1] != 3:
        raise InputError(f"{path}: corrupt point data (shape {cloud.points.shape}, expected (N, 3))")
    finite = np.isfinite(cloud.points).all(axis=1)
    if not finite.any():
        raise InputError(f"{path}: the point cloud has no finite points (all NaN or infinite)")
    if finite.sum() < MIN_CAPTURE_POINTS:
        raise InputError(f"{path}: only {int(finite.sum())} finite point(s); a scene capture needs at least {MIN_CAPTURE_POINTS}")
    return cloud


def _find_environment(folder: Path) -> Path | None:
    candidates = sorted(p for p in folder.glob("scene.*") if p.suffix.lower() in POINT_CLOUD_SUFFIXES | MESH_SUFFIXES)
    return candidates[0] if candidates else None


def _object_files(folder: Path) -> list[Path]:
    objects = folder / "objects"
    if not objects.is_dir():
        return []
    files = sorted(p for p in objects.rglob("*") if p.is_file() and p.suffix.lower() in MESH_SUFFIXES)
    return files


def _text_capture(text: str, source: Path) -> Scene:
    """A capture made of a description only (realsim.text builds its objects)."""
    capture = CaptureInfo(source=source, kind="text", environment_file=None, units="m", up="+z", units_detected=False,
                          up_detected=False, input_to_world=np.eye(4), config=CaptureConfig(text=text))
    return Scene(capture=capture)


PHOTO_SUFFIXES = (".jpg", ".jpeg", ".png", ".webp")


def _photo_capture(photo: Path, config: CaptureConfig, seed: int) -> Scene:
    """A capture made of a photo only (realsim.understanding.photo_scene describes it)."""
    capture = CaptureInfo(source=photo, kind="photo", environment_file=None, units="m", up="+z", units_detected=False,
                          up_detected=False, input_to_world=np.eye(4), config=config, photo=photo)
    return Scene(capture=capture, seed=seed, support=config.support)


def _description(path: Path) -> str:
    """The scene description a ``.txt`` file holds; binary bytes (a scan saved under a wrong
    suffix) are refused, never read as words."""
    raw = path.read_bytes()
    text = raw.decode("utf-8", errors="replace")  # a Latin-1 accent is one odd letter, not binary
    if any(not (c.isprintable() or c.isspace()) for c in text):
        raise InputError(f"{path}: not a text description (binary data); a scan needs its format's suffix (.ply, .pcd, ...)")
    return text.strip()


def load_capture(path: Path | None, params: LoadParams = LoadParams(), seed: int = 0) -> Scene:
    """Read a capture file or folder into a Scene in a gravity-agnostic Z-up frame.

    Units and up axis come from ``params`` (the CLI's ``--units``/``--up``), then
    ``capture.yaml``, then detection.
    """
    if path is None:
        if not params.text:
            raise InputError("no capture given: pass a capture file or folder, or --text \"a table with a mug\"")
        scene = _text_capture(params.text, Path("text"))
        scene.seed = seed
        return scene
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: no such file or folder")
    if path.is_file() and path.stat().st_size == 0:  # before any reader guesses its kind from the bytes
        raise InputError(f"{path}: the file is empty")
    if path.is_file() and path.suffix.lower() == ".txt":
        text = params.text or _description(path)
        if not text:
            raise InputError(f"{path}: the description file is empty")
        scene = _text_capture(text, path)
        scene.seed = seed
        return scene
    if path.is_file() and path.suffix.lower() in PHOTO_SUFFIXES:
        return _photo_capture(path, CaptureConfig(), seed)
    config = CaptureConfig()
    object_files: list[Path] = []
    if path.is_dir():
        config = read_capture_config(path)
        env = _find_environment(path) or (path if is_rgbd_sequence(path) else None)
        object_files = _object_files(path)
        photos = [p for p in path.glob("photo.*") if p.suffix.lower() in (".jpg", ".jpeg", ".png", ".webp")]
        if params.text:
            config = config.model_copy(update={"text": params.text})
        if env is None and not object_files and not photos and not config.text:
            raise InputError(f"{path}: the capture folder holds neither scene.*, objects/* nor photo.*")
        if env is None and not object_files and photos and not config.text:
            return _photo_capture(sorted(photos)[0], config, seed)
    elif is_lone_object(path):
        env, object_files = None, [path]
    else:
        env = path
    units = params.units or config.units
    up = params.up or config.up
    scales = {**UNIT_SCALE, **NAMED_ONLY_UNITS}
    if units is not None and units not in scales:
        raise InputError(f"unknown units {units!r}: use {', '.join(scales)}")
    if up is not None and up not in UP_AXES:
        raise InputError(f"unknown up axis {up!r}: use one of {', '.join(UP_AXES)}")

    scene_points = scene_colors = scene_normals = annotations = None
    grid_shape = None
    kind = "text" if config.text and env is None and not object_files else "objects"
    units_reason = splat = None
    spacing: float | None = None
    camera_view = faces_turned = False
    detail: float | None = None
    units_detected = up_detected = False
    transform = np.eye(4)
    if env is not None:
        cloud = read_environment(env, params, seed)
        origin = distant_origin(cloud.points)  # input coordinates moved by -origin (None: kept)
        if origin is not None:
            cloud.points = cloud.points - origin
        kind = "pointcloud" if cloud.fmt in ("pcd", "xyz", "pts", "rgbd") or (cloud.fmt == "ply" and cloud.mesh is None) else "mesh"
        units, up = units or cloud.units_hint, up or cloud.up_hint
        if up is None:
            up, up_detected = detect_up(cloud.points, cloud.is_camera_view, cloud.fmt, seed), True
        if units is None:
            units, units_reason = plausible_units(cloud.points, up_rotation(up)[2])
            units_detected = True
        else:
            check_scale(cloud.points * scales[units], units)
        transform[:3, :3] = up_rotation(up) * scales[units]
        if cloud.mesh is not None:
            cloud = resample_mesh(cloud, transform, params, seed, env, origin)
        if origin is not None:
            transform[:3, 3] = -transform[:3, :3] @ origin
        with np.errstate(invalid="ignore", over="ignore"):  # an infinite coordinate becomes non-finite, as NaN ones stay
            scene_points = cloud.points @ transform[:3, :3].T
        spacing = point_spacing(scene_points, seed)
        if cloud.fmt == "rgbd":  # the fused crossings lie a voxel apart; the TSDF averaged over trunc_voxels of them
            detail = FusionParams().trunc_voxels * spacing
        splat = cloud.splat
        scene_colors = cloud.colors
        scene_normals = normals_to_world(cloud.normals, transform)
        grid_shape = cloud.grid_shape
        annotations = cloud.annotations
        camera_view = cloud.is_camera_view
        faces_turned = cloud.faces_turned
        forget_mesh_files()
    capture = CaptureInfo(
        source=path,
        kind=kind,
        environment_file=env,
        units=units or "m",
        up=up or "+z",
        units_detected=units_detected,
        up_detected=up_detected,
        input_to_world=transform,
        config=config,
        units_reason=units_reason,
        point_spacing=spacing,
        camera_view=camera_view,
        surface_detail=detail,
        splat=splat,
        faces_turned=faces_turned,
    )
    return Scene(
        capture=capture,
        seed=seed,
        points=scene_points,
        colors=scene_colors,
        normals=scene_normals,
        grid_shape=grid_shape,
        annotations=annotations,
        object_files=object_files,
        support=config.support,
    )
