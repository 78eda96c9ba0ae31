"""A lying body kept as tiles reaches no farther than its outline from above (completion.carving.under_outline)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import open3d as o3d
import trimesh

from realsim.completion import CompletionParams, DepthView
from realsim.completion.carving import carve, under_outline
from realsim.perception.intrinsics import Intrinsics

INTR = Intrinsics(300.0, 300.0, 159.5, 119.5, 320, 240)
BARS = [((-0.06, -0.04, 0.0), (0.06, -0.03, 0.03)), ((-0.06, 0.03, 0.0), (0.06, 0.04, 0.03)), ((-0.06, -0.04, 0.0), (-0.05, 0.04, 0.03))]  # a U lying open


def _u_seen_at_45() -> tuple[DepthView, np.ndarray]:
    """A U of 1 cm bars 3 cm high on a table at z = 0, seen from 45 degrees above its open side
    (the near bar hides the table behind it, inside the U): the view and the U's seen points."""
    camera = np.array([0.0, -0.5, 0.5])
    forward = -camera / np.linalg.norm(camera)
    right = np.cross(forward, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    down = np.cross(forward, right)
    to_world = np.eye(4)
    to_world[:3, :3], to_world[:3, 3] = np.column_stack([right, down, forward]), camera
    scene = o3d.t.geometry.RaycastingScene()
    for lo, hi in [((-1.0, -1.0, -0.01), (1.0, 1.0, 0.0)), *BARS]:
        box = trimesh.creation.box(bounds=[lo, hi])
        scene.add_triangles(o3d.core.Tensor(box.vertices.astype(np.float32)), o3d.core.Tensor(box.faces.astype(np.uint32)))
    v, u = np.mgrid[0:INTR.height, 0:INTR.width]
    rays = np.stack([(u - INTR.cx) / INTR.fx, (v - INTR.cy) / INTR.fy, np.ones(u.shape)], axis=-1).reshape(-1, 3)
    world = rays @ to_world[:3, :3].T
    hit = scene.cast_rays(o3d.core.Tensor(np.hstack([np.tile(camera, (len(world), 1)), world]).astype(np.float32)))
    depth = hit["t_hit"].numpy().astype(float)  # along (x, y, 1): the optical depth
    points = camera + world * depth[:, None]
    on_u = points[:, 2] > 0.0005
    view = DepthView(INTR, np.linalg.inv(to_world), 1.0, depth.reshape(INTR.height, INTR.width), np.where(on_u, 1, 0).reshape(INTR.height, INTR.width))
    return view, points[on_u]


def _inside(pieces: list[trimesh.Trimesh], pts: np.ndarray) -> np.ndarray:
    out = np.zeros(len(pts), bool)
    for p in pieces:
        out |= np.all(pts @ p.face_normals.T - np.einsum("fk,fk->f", p.triangles[:, 0, :], p.face_normals)[None, :] <= 1e-9, axis=1)
    return out


def test_under_outline_keeps_the_columns_near_a_point_from_above() -> None:
    outline = np.array([[0.0, 0.0, 0.01], [0.01, 0.0, 0.02]])
    xy = np.array([[0.0, 0.004], [0.014, 0.0], [0.0045, 0.0], [0.03, 0.03]])
    assert under_outline(xy, outline, 0.005).tolist() == [True, True, True, False]


def test_the_hidden_inside_of_a_lying_u_is_not_kept_as_body() -> None:
    view, seen = _u_seen_at_45()
    hull = trimesh.creation.box(bounds=[[-0.06, -0.04, 0.0], [0.06, 0.04, seen[:, 2].max()]])
    inside_u = np.column_stack([np.linspace(-0.03, 0.04, 8), np.full(8, -0.02), np.full(8, 0.004)])  # behind the near bar, low: hidden
    assert not view.seen_through(inside_u, 0.003, own=1, footprint=False).any()
    params = CompletionParams()
    kept = carve(hull, view, 0.0, seen, params, own=1, outline=seen)
    assert kept.tiles is not None
    assert not _inside(kept.tiles, inside_u).any()
    bars = np.vstack([np.column_stack([np.linspace(-0.04, 0.04, 9), np.full(9, y), np.full(9, 0.015)]) for y in (-0.035, 0.035)])
    assert _inside(kept.tiles, bars).all()  # the bars stay
    filled = carve(hull, view, 0.0, seen, replace(params, tile_outline_steps=0.0), own=1, outline=seen)
    assert filled.tiles is not None and _inside(filled.tiles, inside_u).any()  # without the rule the hidden inside is body
