"""Read a USD / USDA / USDC / USDZ stage (usd-core) as one triangle mesh with its declared units and up axis."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from realsim.errors import InputError

_UNITS = {1.0: "m", 0.01: "cm", 0.001: "mm"}


def read_usd_mesh(path: Path):  # noqa: ANN201 - (trimesh.Trimesh, units or None, up or None)
    """Every ``UsdGeom.Mesh`` in world space (polygons fanned into triangles, ``displayColor``
    kept), with the stage's ``metersPerUnit`` (m, cm, mm; other scales baked in as metres) and
    ``upAxis`` (+y or +z)."""
    import trimesh
    from pxr import Usd, UsdGeom

    try:
        stage = Usd.Stage.Open(str(path))
    except Exception as exc:  # pxr raises Tf errors of its own type
        del exc  # pxr's message names its own source lines, not the user's problem
        raise InputError(f"{path}: cannot open the USD stage (a corrupt or truncated file); re-export it") from None
    if stage is None:
        raise InputError(f"{path}: cannot open the USD stage")
    mpu = float(UsdGeom.GetStageMetersPerUnit(stage))
    up = "+z" if UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z else "+y"
    units = next((u for scale, u in _UNITS.items() if abs(mpu - scale) < 1e-9 * max(scale, 1)), None)
    bake = 1.0 if units is not None else mpu
    verts, faces, colors, offset = [], [], [], 0
    cache = UsdGeom.XformCache(Usd.TimeCode.Default())
    for prim in stage.Traverse():
        if not prim.IsA(UsdGeom.Mesh) or UsdGeom.Imageable(prim).ComputeVisibility() == UsdGeom.Tokens.invisible:
            continue
        mesh = UsdGeom.Mesh(prim)
        pts = np.asarray(mesh.GetPointsAttr().Get() or [], dtype=np.float64).reshape(-1, 3)
        counts = np.asarray(mesh.GetFaceVertexCountsAttr().Get() or [], dtype=np.int64)
        index = np.asarray(mesh.GetFaceVertexIndicesAttr().Get() or [], dtype=np.int64)
        if len(pts) == 0 or len(counts) == 0:
            continue
        xf = np.asarray(cache.GetLocalToWorldTransform(prim), dtype=np.float64).T  # USD is row-vector
        world = pts @ xf[:3, :3].T + xf[:3, 3]
        tri = _fan(counts, index)
        if len(tri) == 0:
            continue
        if tri.max() >= len(pts):
            raise InputError(f"{path}: mesh {prim.GetPath()} has face indices beyond its points")
        col = UsdGeom.PrimvarsAPI(prim).GetPrimvar("displayColor")
        c = np.asarray(col.Get(), dtype=np.float64).reshape(-1, 3) if col and col.HasValue() else np.empty((0, 3))
        if len(c) == len(pts):
            vc = c
        elif len(c) >= 1:
            vc = np.tile(c[0], (len(pts), 1))
        else:
            vc = np.full((len(pts), 3), 0.7)
        verts.append(world * bake)
        faces.append(tri + offset)
        colors.append(vc)
        offset += len(pts)
    if not verts:
        raise InputError(f"{path}: the USD stage holds no mesh")
    rgba = np.hstack([np.clip(np.vstack(colors), 0, 1), np.ones((offset, 1))])
    out = trimesh.Trimesh(np.vstack(verts), np.vstack(faces), vertex_colors=(rgba * 255).round().astype(np.uint8), process=False)
    return out, units or "m", up


def _fan(counts: np.ndarray, index: np.ndarray) -> np.ndarray:
    """Polygons (vertex counts, flat indices) fanned into triangles, vectorized per polygon size."""
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    out = []
    for c in np.unique(counts[counts >= 3]):
        s = starts[counts == c]
        for k in range(1, c - 1):
            out.append((s, np.stack([index[s], index[s + k], index[s + k + 1]], axis=1)))
    if not out:
        return np.zeros((0, 3), np.int64)
    order = np.concatenate([s for s, _ in out])
    tris = np.concatenate([t for _, t in out])
    return tris[np.argsort(order, kind="stable")]
