"""Cleaning, scale normalization, watertight solids and mass properties."""

from __future__ import annotations

import math
import warnings

import manifold3d as mf
import numpy as np
import trimesh

from realsim.physics.size_table import lookup

GENERIC_SIZE = (0.01, 0.15, 3.0)  # min / typical / max largest extent when the label is unknown
UNIT_FACTORS = ((0.001, "millimetres"), (0.01, "centimetres"), (0.0254, "inches"), (0.1, "decimetres"), (10.0, "decametres"), (100.0, "hundredths of a metre"), (1000.0, "kilometres/thousandths"))


def clean_geometry(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """Geometry only: vertices merged by position, degenerate and duplicate faces dropped."""
    g = trimesh.Trimesh(np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces), process=True)
    g.update_faces(g.nondegenerate_faces(height=1e-10))
    g.update_faces(g.unique_faces())
    g.remove_unreferenced_vertices()
    return g


def plausible_scale(extents: np.ndarray, label: str, margin: float = 1.6) -> tuple[float, str | None]:
    """(factor, warning) bringing the largest extent into the size table's range for ``label``."""
    size = float(np.max(extents))
    m = lookup(label)
    lo, typ, hi = m.category.size if m else GENERIC_SIZE
    what = f"a {m.category.name}" if m else "an object of unknown kind"
    if size <= 0:
        return 1.0, None
    if lo / margin <= size <= hi * margin:
        return 1.0, None
    fits = [(abs(math.log(size * f / typ)), f, unit) for f, unit in UNIT_FACTORS if lo <= size * f <= hi]
    if fits:
        _, f, unit = min(fits)
        why = f"looks like {unit}" if f < 1 or f <= 100 else "unit mix-up"
    else:
        f, why = typ / size, "no unit fits; scaled to the typical size"
    msg = (f"{label}: largest extent {size:.4g} m is implausible for {what} (expected {lo:g}-{hi:g} m); "
           f"rescaled by {f:g} to {size * f:.3g} m ({why})")
    return f, msg


def _to_manifold(m: trimesh.Trimesh) -> mf.Manifold | None:
    mesh = mf.Mesh(vert_properties=np.asarray(m.vertices, dtype=np.float32), tri_verts=np.asarray(m.faces, dtype=np.uint32))
    man = mf.Manifold(mesh)
    if man.status() != mf.Error.NoError or man.is_empty():
        return None
    return man


def _from_manifold(man: mf.Manifold) -> trimesh.Trimesh:
    out = man.to_mesh()
    return trimesh.Trimesh(np.asarray(out.vert_properties)[:, :3].astype(np.float64), np.asarray(out.tri_verts), process=True)


def make_solid(g: trimesh.Trimesh, voxel_pitch: float = 0.003) -> tuple[trimesh.Trimesh, str, list[str]]:
    """A watertight solid for volume, inertia and decomposition: (solid, method, notes).

    Every shell is closed (holes filled) and turned into a manifold, the shells are unioned (so
    disconnected pieces of one object become one solid); a shell that can't be closed contributes
    its convex hull. When nothing works the whole mesh is voxel-filled, else convex-hulled.
    """
    notes: list[str] = []
    total_area = float(g.area) or 1.0
    pieces: list[mf.Manifold] = []
    hulled = 0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        comps = g.split(only_watertight=False)
        for c in comps:
            if c.area < 1e-4 * total_area and not c.is_watertight:
                continue  # scan noise
            if not c.is_watertight:
                trimesh.repair.fill_holes(c)
            man = None
            if c.is_watertight:
                if c.volume < 0:
                    c.invert()
                if abs(c.volume) > 0:
                    man = _to_manifold(c)
            if man is None and len(c.vertices) >= 4:
                try:
                    h = c.convex_hull
                    if h.volume > 1e-12:
                        man = _to_manifold(h)
                        hulled += 1
                except Exception:
                    man = None
            if man is not None and man.volume() > 0:
                pieces.append(man)
    if pieces:
        union = mf.Manifold.batch_boolean(pieces, mf.OpType.Add) if len(pieces) > 1 else pieces[0]
        if not union.is_empty() and union.volume() > 0:
            solid = _from_manifold(union)
            method = "manifold"
            if len(pieces) > 1:
                notes.append(f"merged {len(pieces)} disconnected shells into one solid")
            if hulled:
                method = "manifold+hull"
                notes.append(f"{hulled} open shell(s) could not be closed; used their convex hulls")
            return solid, method, notes
    try:
        vox = g.voxelized(voxel_pitch).fill()
        solid = vox.marching_cubes
        solid.apply_transform(vox.transform)
        if solid.is_watertight and solid.volume > 0:
            notes.append(f"mesh could not be made manifold; used a voxel fill at {voxel_pitch * 1000:.1f} mm")
            return solid, "voxel", notes
    except Exception:
        pass
    notes.append("mesh could not be made manifold or voxel-filled; used its convex hull")
    return g.convex_hull, "convex_hull", notes


def solid_inertia_unit(solid: trimesh.Trimesh) -> tuple[np.ndarray, np.ndarray]:
    """(com, inertia about com for mass 1) of a uniform-density solid."""
    mp = solid.mass_properties
    vol = float(mp["volume"])
    return np.asarray(mp["center_mass"], float), np.asarray(mp["inertia"], float) / vol


def shell_inertia_unit(mesh: trimesh.Trimesh) -> tuple[np.ndarray, np.ndarray]:
    """(com, inertia about com for mass 1) of a thin uniform shell on the mesh surface."""
    tri = mesh.triangles
    area = mesh.area_faces
    A = area.sum()
    s = tri.sum(axis=1)  # (F, 3)
    com = (area[:, None] * s / 3.0).sum(axis=0) / A
    # second moment of each triangle: A/12 * (sum v v^T + s s^T)
    vv = np.einsum("fij,fik->fjk", tri, tri)
    ss = np.einsum("fj,fk->fjk", s, s)
    C = (area[:, None, None] * (vv + ss)).sum(axis=0) / 12.0 / A  # per unit mass, about origin
    C = C - np.outer(com, com)
    inertia = np.trace(C) * np.eye(3) - C
    return com, inertia


def blend_inertia(parts: list[tuple[float, np.ndarray, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    """Combine (mass fraction, com, inertia-unit) parts into one unit-mass body (parallel axis)."""
    w = np.array([p[0] for p in parts], float)
    w = w / w.sum()
    com = sum(wi * p[1] for wi, p in zip(w, parts))
    I = np.zeros((3, 3))
    for wi, (_, c, Ii) in zip(w, parts):
        d = c - com
        I += wi * (Ii + (d @ d) * np.eye(3) - np.outer(d, d))
    return com, I
