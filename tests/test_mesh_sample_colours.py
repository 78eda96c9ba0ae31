"""sample_mesh's vertex colours: the mean of each sample's face corners, whether the samples
outnumber the faces (per-face means gathered) or not (per-sample means)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from realsim.perception.capture import sample_mesh


@pytest.mark.parametrize("count", [500, 50_000])  # fewer and more samples than faces
def test_vertex_colours_are_face_corner_means(count: int) -> None:
    mesh = trimesh.creation.icosphere(subdivisions=3)  # 1280 faces
    rng = np.random.default_rng(4)
    mesh.visual = trimesh.visual.ColorVisuals(mesh, vertex_colors=rng.integers(0, 256, (len(mesh.vertices), 4), dtype=np.uint8))
    pts, cols, normals = sample_mesh(mesh, count, 0, Path("sphere.ply"))
    _, face_idx = trimesh.sample.sample_surface(mesh, count, seed=0)
    expected = np.asarray(mesh.visual.vertex_colors)[mesh.faces[face_idx], :3].mean(axis=1) / 255.0
    assert len(pts) == count and normals.shape == (count, 3)
    assert np.array_equal(cols, expected)
