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
