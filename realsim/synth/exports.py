"""Write a SynthScene in the file forms phone and scanning apps export, in any frame.

A capture frame is given by one 4x4 world -> capture transform (:func:`capture_transform`:
units, any of the six up axes, a turn about up, a tilt, an origin far away). Clouds go to PLY
(binary or ASCII, float or double), PCD (ascii, binary, binary_compressed), XYZ and PTS; meshes
to OBJ (+MTL), PLY, STL, GLB, glTF and USDA/USDZ (with ``metersPerUnit`` and ``upAxis``).
Every writer takes capture-frame data; the caller keeps the transform as ground truth.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from realsim.synth.forms import UNIT_SCALE
from realsim.synth.scene import PART_FLOOR, SynthScene

CLOUD_KINDS = ("ply", "ply_ascii", "ply_double", "pcd_ascii", "pcd_binary", "pcd_binary_compressed", "xyz", "pts")
MESH_KINDS = ("obj", "ply", "stl", "glb", "gltf", "usda", "usdz")


def up_matrix(up: str) -> np.ndarray:
    """Proper rotation taking world +Z onto the capture axis ``up`` (``+x`` ... ``-z``)."""
    i, s = "xyz".index(up[1]), 1.0 if up[0] == "+" else -1.0
    e = np.eye(3)
    z, x = s * e[i], e[(i + 1) % 3]
    return np.column_stack([x, np.cross(z, x), z])


def capture_transform(units: str = "m", up: str = "+z", yaw_deg: float = 0.0, tilt_deg: float = 0.0,
                      offset_m: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> np.ndarray:
    """4x4 world -> capture: tilt about world x, turn about world z, then the capture's up axis
    and units, then an origin ``offset_m`` metres away (in capture axes)."""
    from scipy.spatial.transform import Rotation

    rot = Rotation.from_euler("zx", [yaw_deg, tilt_deg], degrees=True).as_matrix()
    t = np.eye(4)
    t[:3, :3] = up_matrix(up) @ rot * UNIT_SCALE[units]
    t[:3, 3] = np.asarray(offset_m, dtype=np.float64) * UNIT_SCALE[units]
    return t


def without_floor(scene: SynthScene, margin: float = 0.05) -> SynthScene:
    """The scene as a tabletop scan: only what lies above the lowest non-floor support top less
    ``margin`` (no floor in view, so its support height is unknown to a converter)."""
    low = min(s.height for s in scene.supports if s.kind != "floor")
    keep = (scene.mesh.triangles_center[:, 2] >= low - margin) & (scene.face_part != PART_FLOOR)
    mesh = scene.mesh.submesh([np.flatnonzero(keep)], append=True)
    return replace(scene, supports=[s for s in scene.supports if s.kind != "floor"], mesh=mesh,
                   face_object=scene.face_object[keep], face_part=scene.face_part[keep])


def write_cloud(path: Path, points: np.ndarray, colours: np.ndarray, kind: str) -> Path:
    """Capture-frame points (N, 3) with uint8 colours (N, 3) as a file of ``kind`` (CLOUD_KINDS)."""
    path = Path(path)
    cols = np.asarray(colours, dtype=np.uint8)
    if kind.startswith("ply"):
        _write_ply(path, points, cols, ascii_=kind == "ply_ascii", double=kind != "ply")
    elif kind.startswith("pcd"):
        from realsim.perception.pcd_write import write_pcd

        write_pcd(path, points, colors=cols, encoding=kind[4:])
    elif kind == "xyz":
        np.savetxt(path, np.hstack([points, cols]), fmt=["%.6f"] * 3 + ["%d"] * 3)
    elif kind == "pts":  # Leica PTS: the point count, then x y z intensity r g b
        body = np.hstack([points, np.full((len(points), 1), 0.5), cols])
        np.savetxt(path, body, fmt=["%.6f"] * 3 + ["%.3f"] + ["%d"] * 3, header=str(len(points)), comments="")
    else:
        raise ValueError(f"unknown cloud kind {kind!r}: {CLOUD_KINDS}")
    return path


def _write_ply(path: Path, points: np.ndarray, cols: np.ndarray, ascii_: bool, double: bool) -> None:
    ftype, fname = ("<f8", "double") if double else ("<f4", "float")
    data = np.zeros(len(points), dtype=[("x", ftype), ("y", ftype), ("z", ftype), ("red", "u1"), ("green", "u1"), ("blue", "u1")])
    data["x"], data["y"], data["z"] = np.asarray(points).T
    data["red"], data["green"], data["blue"] = cols.T
    fmt = "ascii" if ascii_ else "binary_little_endian"
    header = (f"ply\nformat {fmt} 1.0\nelement vertex {len(data)}\n" + "".join(f"property {fname} {a}\n" for a in "xyz")
              + "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n").encode("ascii")
    if ascii_:
        rows = np.hstack([np.asarray(points), cols]).astype(object)
        text = "\n".join(" ".join(f"{v:.6f}" if j < 3 else str(int(v)) for j, v in enumerate(r)) for r in rows) + "\n"
        path.write_bytes(header + text.encode("ascii"))
    else:
        path.write_bytes(header + data.tobytes())


def write_mesh_file(path: Path, scene: SynthScene, to_capture: np.ndarray, usd_up: str = "+z") -> Path:
    """The merged scene mesh through ``to_capture`` as ``path``'s kind (MESH_KINDS by suffix).
    USD stages declare ``usd_up`` (+y or +z) and ``metersPerUnit`` from the transform's scale;
    their points are written in metres times that scale, as ``to_capture`` says."""
    path = Path(path)
    kind = path.suffix.lower()[1:]
    mesh = scene.mesh.copy()
    mesh.apply_transform(to_capture)
    if kind in ("usda", "usdz", "usd"):
        _write_usd(path, mesh, 1.0 / float(np.cbrt(abs(np.linalg.det(to_capture[:3, :3])))), usd_up)
    elif kind in ("glb", "gltf"):  # float32 vertices: a far origin goes into the node's (float64) matrix
        import trimesh

        local, node = scene.mesh.copy(), np.eye(4)
        linear = np.eye(4)
        linear[:3, :3] = to_capture[:3, :3]
        local.apply_transform(linear)
        node[:3, 3] = to_capture[:3, 3]
        sc = trimesh.Scene()
        sc.add_geometry(local, node_name="scan", transform=node)
        if kind == "glb":
            path.write_bytes(sc.export(file_type="glb"))
        else:
            for name, data in sc.export(file_type="gltf").items():
                (path.parent / (path.name if name == "model.gltf" else name)).write_bytes(data)
    else:
        mesh.export(path)
    return path


def _write_usd(path: Path, mesh, meters_per_unit: float, up: str) -> None:  # noqa: ANN001 - trimesh.Trimesh
    from pxr import Gf, Usd, UsdGeom, UsdUtils, Vt

    layer = path.with_suffix(".usdc") if path.suffix.lower() == ".usdz" else path
    stage = Usd.Stage.CreateNew(str(layer))
    UsdGeom.SetStageMetersPerUnit(stage, meters_per_unit)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z if up == "+z" else UsdGeom.Tokens.y)
    root = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(root.GetPrim())
    geom = UsdGeom.Mesh.Define(stage, "/World/scan")
    geom.CreatePointsAttr(Vt.Vec3fArray([Gf.Vec3f(*map(float, v)) for v in mesh.vertices]))
    geom.CreateFaceVertexCountsAttr(Vt.IntArray([3] * len(mesh.faces)))
    geom.CreateFaceVertexIndicesAttr(Vt.IntArray(mesh.faces.reshape(-1).tolist()))
    colours = np.asarray(mesh.visual.vertex_colors)[:, :3] / 255.0
    geom.CreateDisplayColorPrimvar(UsdGeom.Tokens.vertex).Set(Vt.Vec3fArray([Gf.Vec3f(*map(float, c)) for c in colours]))
    stage.GetRootLayer().Save()
    if path.suffix.lower() == ".usdz":
        UsdUtils.CreateNewUsdzPackage(str(layer), str(path))
        layer.unlink()
