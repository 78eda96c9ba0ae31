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
