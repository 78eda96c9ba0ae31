"""DepthView.denoised: each object pixel's depth from the plane fitted to its own object's window."""

from __future__ import annotations

import numpy as np
import pytest

from realsim.completion.view import DepthView
from realsim.perception.intrinsics import Intrinsics

INTR = Intrinsics(525.0, 525.0, 79.5, 59.5, 160, 120)


def _view(depth: np.ndarray, labels: np.ndarray) -> DepthView:
    return DepthView(INTR, np.eye(4), 1.0, depth, labels)


def test_a_tilted_plane_is_recovered_at_silhouettes_borders_and_holes_and_the_rest_is_left() -> None:
    rng = np.random.default_rng(2)
    v, u = np.mgrid[0:INTR.height, 0:INTR.width]
    plane = 0.8 + 0.001 * u - 0.0005 * v
    labels = np.zeros(plane.shape, np.int32)
    labels[:60, :90] = 1  # touches the image's top and left borders
    labels[70:, 100:] = 2
    noisy = plane + rng.normal(0.0, 0.002, plane.shape)
    noisy[rng.random(plane.shape) < 0.1] = np.nan  # holes in the depth
    far = np.where(labels == 0, 2.0, noisy)  # the background behind the objects is far away
    out = _view(far, labels).denoised(5).depth
    obj = (labels > 0) & np.isfinite(out)
    assert np.nanmedian(np.abs(out[obj] - plane[obj])) < 0.4 * np.nanmedian(np.abs(noisy[obj] - plane[obj]))
    assert np.nanmax(np.abs(out[obj] - plane[obj])) < 0.01  # the far background never pulls an edge pixel
    assert np.array_equal(out[labels == 0], far[labels == 0])
    exact = _view(np.where(labels == 0, 2.0, plane), labels).denoised(5).depth  # a noiseless plane comes back as it was
    assert np.allclose(exact[labels > 0], plane[labels > 0], atol=1e-9)
    assert np.array_equal(_view(noisy, np.zeros_like(labels)).denoised(5).depth, noisy, equal_nan=True)


def _denoised_reference(depth: np.ndarray, labels: np.ndarray, window: int = 5) -> np.ndarray:
    """The plane fit written plainly (2-D gathers, one (window^2, n, 3) product summed over its first axis)."""
    v, u = np.nonzero(labels > 0)
    r = window // 2
    padded, plabels = np.pad(depth, r, constant_values=np.nan), np.pad(labels, r)
    offsets = [(i - r, j - r) for i in range(window) for j in range(window)]
    d = np.stack([padded[v + r + di, u + r + dj] for di, dj in offsets])
    ok = np.stack([plabels[v + r + di, u + r + dj] == labels[v, u] for di, dj in offsets]) & np.isfinite(d)
    basis = np.array([[1.0, dj, di] for di, dj in offsets])
    wgt = ok.astype(float)
    normal = np.tensordot(wgt, basis[:, :, None] * basis[:, None, :], axes=(0, 0))
    rhs = ((wgt * np.nan_to_num(d))[:, :, None] * basis[:, None, :]).sum(axis=0)
    fit = (wgt.sum(axis=0) >= 6) & (np.abs(np.linalg.det(normal)) > 1e-6)
    out = depth.copy()
    out[v[fit], u[fit]] = np.linalg.solve(normal[fit], rhs[fit][..., None])[:, 0, 0]
    return out


def test_the_fit_gives_the_plain_computation_bit_for_bit() -> None:
    rng = np.random.default_rng(5)
    labels = rng.integers(0, 4, (INTR.height, INTR.width)).astype(np.int32)
    labels[30:90, 40:120] = 2  # a large object among speckled ones
    depth = 0.9 + rng.normal(0.0, 0.01, labels.shape)
    depth[rng.random(labels.shape) < 0.05] = np.nan
    out = _view(depth, labels).denoised(5).depth
    assert out.tobytes() == _denoised_reference(depth, labels).tobytes()


DOWN = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, -1.0, 0.0, 0.0], [0.0, 0.0, -1.0, 1.0], [0.0, 0.0, 0.0, 1.0]])  # looking down from 1 m


def test_the_support_seen_in_a_gap_frees_the_space_just_above_it() -> None:
    depth = np.full((INTR.height, INTR.width), 1.0)  # the support plane z = 0, one metre below the camera
    labels = np.zeros(depth.shape, np.int32)
    u, v = (int(round(c)) for c in INTR.project(np.array([[0.0, 0.0, 1.0]]))[0])
    labels[v - 10:v + 10, u - 30:u], depth[v - 10:v + 10, u - 30:u] = 1, 0.99  # a body 1 cm thin left of x = 0
    view = DepthView(INTR, DOWN, 1.0, depth, labels)
    points = np.array([[0.02, 0.0, 0.004], [0.02, 0.0, 0.001], [0.02, 0.0, -0.004], [-0.02, 0.0, 0.004]])
    assert view.over_support(points, 0.0).tolist() == [True, False, False, False]  # in the gap, above the margin only
    assert not view.seen_through(points[:1], 0.005).any()  # the depth test alone keeps it: within the noise
    assert view.over_support(points, 0.01).tolist() == [False] * 4  # a support at another height is not the one seen
    depth[v - 10:v + 10, u:u + 30] = 0.997  # what the pixel shows is 3 mm off the plane: not that support
    assert not view.over_support(points[:1], 0.0).any()


def test_a_camera_sized_view_is_fitted_on_two_threads_bit_for_bit(monkeypatch: pytest.MonkeyPatch) -> None:
    import realsim.completion.view as view_module

    monkeypatch.setenv("REALSIM_WORKERS", "2")
    calls: list[int] = []
    split = view_module.split_rows
    monkeypatch.setattr(view_module, "split_rows", lambda fn, n: calls.append(n) or split(fn, n))
    rng = np.random.default_rng(6)
    intr = Intrinsics(525.0, 525.0, 319.5, 239.5, 640, 480)
    labels = rng.integers(0, 4, (480, 640)).astype(np.int32)
    labels[100:400, 150:500] = 2
    depth = 0.9 + rng.normal(0.0, 0.01, labels.shape)
    depth[rng.random(labels.shape) < 0.05] = np.nan
    out = DepthView(intr, np.eye(4), 1.0, depth, labels).denoised(5).depth
    from realsim.rowsplit import LEAST_ROWS

    assert calls == [int((labels > 0).sum())] and calls[0] >= LEAST_ROWS  # halved between two threads
    assert out.tobytes() == _denoised_reference(depth, labels).tobytes()


def test_front_hits_are_where_every_pixels_ray_enters_a_convex_piece() -> None:
    """front_hits: one point per pixel whose ray meets the piece, at the nearest crossing (what a ray
    caster finds), on a turned box seen from above: no pixel of its silhouette is skipped."""
    import open3d as o3d
    import trimesh

    box = trimesh.creation.box([0.05, 0.03, 0.02])
    box.apply_transform(trimesh.transformations.rotation_matrix(0.4, [0.3, 1.0, 0.2]))
    box.apply_translation([0.01, -0.005, 0.0])
    view = DepthView(INTR, DOWN, 1.0, np.full((INTR.height, INTR.width), 1.0), None)
    planes = np.column_stack([box.face_normals, np.einsum("fk,fk->f", box.face_normals, box.triangles[:, 0, :])])
    hits = view.front_hits(planes, np.asarray(box.vertices))
    rc = o3d.t.geometry.RaycastingScene()
    opt = box.vertices @ DOWN[:3, :3].T + DOWN[:3, 3]
    rc.add_triangles(o3d.core.Tensor(opt.astype(np.float32)), o3d.core.Tensor(box.faces.astype(np.uint32)))
    v, u = np.mgrid[0:INTR.height, 0:INTR.width]
    ray = np.stack([(u - INTR.cx) / INTR.fx, (v - INTR.cy) / INTR.fy, np.ones(u.shape)], axis=-1).reshape(-1, 3)
    t = rc.cast_rays(o3d.core.Tensor(np.hstack([np.zeros_like(ray), ray]).astype(np.float32)))["t_hit"].numpy()
    seen = np.isfinite(t)
    assert 100 < len(hits) and abs(len(hits) - np.count_nonzero(seen)) <= 2  # the same pixels (rays grazing an edge aside)
    depth = np.sort((hits @ DOWN[:3, :3].T + DOWN[:3, 3])[:, 2])
    assert np.allclose(depth[:len(depth) // 2], np.sort(t[seen])[:len(depth) // 2], atol=1e-5)  # at the entry, not the exit
