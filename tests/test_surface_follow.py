"""A scanned object's visual surface takes the depth the camera saw (realsim.composition.surface_follow)."""

from __future__ import annotations

import numpy as np
import trimesh

from realsim.composition.appearance import subdivided
from realsim.composition.surface_follow import follow_seen_depth
from realsim.perception.intrinsics import Intrinsics

INTR = Intrinsics(525.0, 525.0, 159.5, 119.5, 320, 240)


def _seen_box(offset: float) -> tuple[trimesh.Trimesh, np.ndarray, np.ndarray]:
    """A 10 cm box 0.8 m in front of the camera (optical frame) and a capture of its front face
    ``offset`` farther than the mesh says (a fit a little off the real surface)."""
    box = subdivided(trimesh.creation.box([0.1, 0.1, 0.1]), 0.02)
    box.apply_translation([0.0, 0.0, 0.8])
    h, w = INTR.height, INTR.width
    v, u = np.mgrid[0:h, 0:w]
    x = (u - INTR.cx) / INTR.fx
    y = (v - INTR.cy) / INTR.fy
    front = 0.75 + offset
    hit = (np.abs(x * front) < 0.05) & (np.abs(y * front) < 0.05)
    depth = np.where(hit, front, np.nan)
    return box, depth, hit


def test_facing_vertices_slide_to_the_seen_depth_and_the_rest_stay() -> None:
    box, depth, mask = _seen_box(0.008)
    out, moved = follow_seen_depth(box, np.eye(4), depth, mask, INTR.fx, INTR.project)
    verts, new = np.asarray(box.vertices), np.asarray(out.vertices)
    front = np.isclose(verts[:, 2], 0.75)
    inner = front & (np.abs(verts[:, 0]) < 0.04) & (np.abs(verts[:, 1]) < 0.04)
    assert moved >= inner.sum() > 0
    assert np.allclose(new[inner, 2], 0.758, atol=5e-4)
    back = np.isclose(verts[:, 2], 0.85)
    assert np.allclose(new[back], verts[back])  # faces away from the camera: never moved
    # moved along the line of sight: every vertex still projects to the same pixel
    assert np.allclose(INTR.project(new), INTR.project(verts), atol=1e-6)


def test_a_surface_farther_than_the_bound_is_not_followed() -> None:
    box, depth, mask = _seen_box(0.05)
    out, moved = follow_seen_depth(box, np.eye(4), depth, mask, INTR.fx, INTR.project, max_shift=0.02)
    assert moved == 0
    assert np.allclose(out.vertices, box.vertices)


def test_pixels_of_another_object_do_not_pull_a_vertex() -> None:
    box, depth, _ = _seen_box(0.008)
    out, moved = follow_seen_depth(box, np.eye(4), depth, np.zeros(depth.shape, bool), INTR.fx, INTR.project)
    assert moved == 0


def _loop_follow(mesh: trimesh.Trimesh, depth: np.ndarray, mask: np.ndarray, max_shift: float = 0.02) -> np.ndarray:
    """The rule vertex by vertex (the reference the vectorized windows must match bit for bit)."""
    verts = np.asarray(mesh.vertices)
    normals = np.asarray(mesh.vertex_normals)
    facing = np.einsum("ij,ij->i", normals, -verts) > 0.2 * np.linalg.norm(verts, axis=1)
    pix, z = INTR.project(verts), verts[:, 2]
    half_edge = 0.25 * float(np.median(mesh.edges_unique_length))
    out = verts.copy()
    for i in np.flatnonzero(facing & (z > 1e-3)):
        r = int(np.clip(round(half_edge * INTR.fx / z[i]), 1, 8))
        ui, vi = int(round(pix[i, 0])), int(round(pix[i, 1]))
        if not (0 <= ui < INTR.width and 0 <= vi < INTR.height):
            continue
        win = (slice(max(0, vi - r), vi + r + 1), slice(max(0, ui - r), ui + r + 1))
        seen = depth[win][mask[win]]
        seen = seen[np.isfinite(seen)]
        if len(seen) >= max(3, 0.5 * (2 * r + 1) ** 2) and abs(float(np.median(seen)) - z[i]) <= max_shift:
            out[i] = verts[i] * (float(np.median(seen)) / z[i])
    return out


def test_windows_match_the_vertex_by_vertex_rule_on_noisy_partial_views() -> None:
    rng = np.random.default_rng(3)
    for trial in range(4):  # boxes and spheres at several ranges, cut by the image border, holes in the depth
        shape = subdivided(trimesh.creation.box([0.1, 0.08, 0.12]), 0.01) if trial % 2 else trimesh.creation.icosphere(3, 0.06)
        shape.apply_translation([rng.uniform(-0.25, 0.25), rng.uniform(-0.2, 0.2), rng.uniform(0.5, 1.5)])
        depth = rng.normal(shape.vertices[:, 2].min() + 0.01, 0.004, (INTR.height, INTR.width))
        depth[rng.random(depth.shape) < 0.2] = np.nan
        mask = rng.random(depth.shape) < 0.8
        out, moved = follow_seen_depth(shape, np.eye(4), depth, mask, INTR.fx, INTR.project)
        expected = _loop_follow(shape, depth, mask)
        assert moved > 0 and np.array_equal(np.asarray(out.vertices), expected), trial
