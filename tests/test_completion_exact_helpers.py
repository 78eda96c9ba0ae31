"""Lean replicas of trimesh properties give trimesh's values bit for bit (volume, unique edges)."""

from __future__ import annotations

import numpy as np
import trimesh

from realsim.completion.hull import trimesh_hull, volume
from realsim.completion.neighbours import clip_convex, unique_edges


def _meshes() -> list[trimesh.Trimesh]:
    rng = np.random.default_rng(4)
    clouds = [rng.normal(size=(int(rng.integers(4, 2500)), 3)) * rng.uniform(0.005, 1.0, 3) + rng.normal(size=3) for _ in range(60)]
    out = [trimesh_hull(c) for c in clouds]
    out += [p for p in (clip_convex(m, rng.normal(size=3), 0.0) for m in out[:20]) if p is not None]
    return out + [trimesh.creation.icosphere(3), trimesh.creation.box([0.1, 0.2, 0.3]), trimesh.creation.cylinder(0.05, 0.2)]


def test_volume_is_trimesh_volume_bit_for_bit() -> None:
    for mesh in _meshes():
        fresh = trimesh.Trimesh(mesh.vertices.copy(), mesh.faces.copy(), process=False)
        assert np.float64(volume(mesh)).tobytes() == np.float64(fresh.volume).tobytes()


def test_unique_edges_are_trimesh_edges_unique_in_its_order() -> None:
    for mesh in _meshes():
        fresh = trimesh.Trimesh(mesh.vertices.copy(), mesh.faces.copy(), process=False)
        mine = unique_edges(mesh.faces)
        assert mine.dtype == fresh.edges_unique.dtype and np.array_equal(mine, fresh.edges_unique)


def _columns_reference(mesh: trimesh.Trimesh, step: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """carving._columns written plainly: every face's bound for every column in one (M, F) array."""
    lo, hi = mesh.bounds
    gx, gy = (np.arange(a + step / 2, b, step) for a, b in zip(lo[:2], hi[:2]))
    xy = np.stack(np.meshgrid(gx, gy, indexing="ij"), axis=-1).reshape(-1, 2)
    n = mesh.face_normals
    d = np.einsum("fk,fk->f", n, mesh.triangles[:, 0, :])
    rhs = d[None, :] - xy @ n[:, :2].T
    up, down, side = n[:, 2] > 1e-6, n[:, 2] < -1e-6, np.abs(n[:, 2]) <= 1e-6
    z_top = np.min(rhs[:, up] / n[up, 2], axis=1) if up.any() else np.full(len(xy), hi[2])
    z_bot = np.max(rhs[:, down] / n[down, 2], axis=1) if down.any() else np.full(len(xy), lo[2])
    ok = (z_top > z_bot) & (np.all(rhs[:, side] >= -1e-9, axis=1) if side.any() else True)
    return xy[ok], np.maximum(z_bot[ok], lo[2]), np.minimum(z_top[ok], hi[2])


def test_voxel_columns_are_the_plain_computation_bit_for_bit() -> None:
    from realsim.completion.carving import _columns

    for mesh in _meshes():
        mesh = trimesh.Trimesh(mesh.vertices * (0.12 / np.max(mesh.extents)), mesh.faces, process=False)  # object sized
        step = float(np.clip(np.max(mesh.extents) / 25, 0.001, 0.005))
        for got, want in zip(_columns(mesh, step), _columns_reference(mesh, step)):
            assert got.shape == want.shape and got.tobytes() == want.tobytes()
