"""A fragment seen beyond an occluder joins the object on its other side; its hidden middle is
bridged (generated ground truth: boxes on a table, ray-cast from a camera in front and above)."""

from __future__ import annotations

import numpy as np
import open3d as o3d
import trimesh

from realsim.completion.extrusion import complete_slabs
from realsim.completion.fragments import join_occluded_fragments
from realsim.completion.view import DepthView
from realsim.composition.layout import declared_support
from realsim.perception.intrinsics import Intrinsics
from realsim.scene import Scene, SceneObject

TABLE = 0.75
INTR = Intrinsics(300.0, 300.0, 160.0, 120.0, 320, 240)


def _look_at(eye: np.ndarray, target: np.ndarray) -> np.ndarray:
    """Optical-to-world pose of a camera at ``eye`` looking at ``target`` (x right, y down, z forward)."""
    z = (target - eye) / np.linalg.norm(target - eye)
    x = np.cross(z, [0.0, 0.0, 1.0])
    x /= np.linalg.norm(x)
    pose = np.eye(4)
    pose[:3, :3] = np.column_stack([x, np.cross(z, x), z])
    pose[:3, 3] = eye
    return pose


def _box(lo: tuple[float, float, float], hi: tuple[float, float, float]) -> trimesh.Trimesh:
    return trimesh.creation.box(bounds=np.array([lo, hi], float))


def _capture(bodies: list[trimesh.Trimesh]) -> tuple[np.ndarray, np.ndarray, np.ndarray, DepthView]:
    """World points (one per pixel), which body each pixel shows (0 table, k body k) and the view."""
    pose = _look_at(np.array([0.0, -0.55, TABLE + 0.45]), np.array([0.0, 0.05, TABLE]))
    w2o = np.linalg.inv(pose)
    scene = o3d.t.geometry.RaycastingScene()
    for mesh in [_box((-0.6, -0.4, TABLE - 0.02), (0.6, 0.4, TABLE)), *bodies]:
        v = mesh.vertices @ w2o[:3, :3].T + w2o[:3, 3]
        scene.add_triangles(o3d.core.Tensor(v.astype(np.float32)), o3d.core.Tensor(np.asarray(mesh.faces, np.uint32)))
    v, u = np.mgrid[0:INTR.height, 0:INTR.width]
    ray = np.stack([(u - INTR.cx) / INTR.fx, (v - INTR.cy) / INTR.fy, np.ones(u.shape)], axis=-1).reshape(-1, 3)
    hit = scene.cast_rays(o3d.core.Tensor(np.hstack([np.zeros_like(ray), ray]).astype(np.float32)))
    t, body = hit["t_hit"].numpy(), hit["geometry_ids"].numpy().astype(int)
    optical = ray * np.where(np.isfinite(t), t, np.nan)[:, None]
    world = optical @ pose[:3, :3].T + pose[:3, 3]
    which = np.where(np.isfinite(t), body, 0)  # geometry 0 is the table
    return world, which, optical[:, 2].reshape(INTR.height, INTR.width), w2o


def _scene(world: np.ndarray, labels: np.ndarray, ids: list[int]) -> Scene:
    plane = declared_support(None)
    scene = Scene.unread(None)
    scene.points, scene.labels, scene.planes = world, labels.astype(np.int32), [plane]
    scene.objects = [SceneObject(id=k, name=f"obj{k}", label="object", position=np.zeros(3), quat=np.array([1.0, 0, 0, 0]),
                                 size=np.full(3, 0.1), support_id=plane.id) for k in ids]
    return scene


def test_a_bar_seen_on_both_sides_of_a_box_is_one_object() -> None:
    bar = _box((-0.12, 0.05, TABLE), (0.12, 0.08, TABLE + 0.03))  # lying behind the box
    box = _box((-0.04, -0.02, TABLE), (0.04, 0.02, TABLE + 0.12))  # standing in front of the bar's middle
    world, which, depth, w2o = _capture([bar, box])
    labels = np.where(which == 2, 1, 0)  # the box: object 1
    labels[(which == 1) & (world[:, 0] < 0)] = 2  # the bar's left end: object 2
    labels[(which == 1) & (world[:, 0] > 0)] = -1  # its right end, too small alone: noise
    right = np.count_nonzero(labels == -1)
    assert right > 100 and np.count_nonzero(labels == 2) > 100
    scene = _scene(world, labels, [1, 2])
    view = DepthView(INTR, w2o, 1.0, depth, scene.labels.reshape(INTR.height, INTR.width))
    assert join_occluded_fragments(scene, view, 0.004) == [(2, right)]
    assert scene.labels is not None and np.count_nonzero(scene.labels == 2) == np.count_nonzero(which == 1)


def test_a_fragment_beside_an_object_over_bare_table_stays_noise() -> None:
    bar = _box((-0.12, 0.05, TABLE), (-0.02, 0.08, TABLE + 0.03))
    crumb = _box((0.03, 0.05, TABLE), (0.06, 0.08, TABLE + 0.03))  # a small thing 5 cm beside it, the table seen between
    world, which, depth, w2o = _capture([bar, crumb])
    labels = np.where(which == 1, 1, np.where(which == 2, -1, 0))
    scene = _scene(world, labels, [1])
    view = DepthView(INTR, w2o, 1.0, depth, scene.labels.reshape(INTR.height, INTR.width))
    assert join_occluded_fragments(scene, view, 0.004) == []
    assert scene.labels is not None and np.count_nonzero(scene.labels == -1) == np.count_nonzero(which == 2)


def test_the_hidden_middle_of_a_bent_body_is_bridged_between_its_ends() -> None:
    """A banana-like arc (radius 15 cm, 100 degrees, 3 cm thick) seen on both ends, its middle third
    hidden: the slabs bridge the middle along the arc and keep off the chord's concave side."""
    rng = np.random.default_rng(0)
    angle = rng.uniform(np.radians(40), np.radians(140), 6000)
    radius = 0.15 + rng.uniform(-0.015, 0.015, 6000)
    z = TABLE + rng.uniform(0.0, 0.03, 6000)
    pts = np.column_stack([radius * np.cos(angle), radius * np.sin(angle) - 0.15, z])
    seen = pts[np.abs(angle - np.pi / 2) > np.radians(17)]
    pieces = complete_slabs(seen, TABLE, TABLE + 0.03, 0.025, 8, 0.8)
    assert pieces is not None
    along = [np.array([np.cos(a) * 0.15, np.sin(a) * 0.15 - 0.15, TABLE + 0.015]) for a in np.radians([75, 90, 105])]
    assert all(any(_inside(p, x) for p in pieces) for x in along)  # the arc's hidden middle is filled along the arc
    chord = np.array([0.0, 0.15 * np.sin(np.radians(40)) - 0.15, TABLE + 0.015])  # on the chord between its ends
    assert not any(_inside(p, chord) for p in pieces)


def _inside(piece: trimesh.Trimesh, x: np.ndarray) -> bool:
    """Whether ``x`` lies in the convex ``piece``."""
    return bool(np.all(piece.face_normals @ x - np.einsum("fk,fk->f", piece.face_normals, piece.triangles[:, 0]) <= 1e-9))
