"""Attached parts: a handle meeting its body along its height joins the body; a box resting on
another at its own foot, or standing behind a nearer one that hides its foot, stays an object."""

from __future__ import annotations

import numpy as np

from realsim.perception.attached_parts import join_attached_parts

ALONG_Y = np.array([0.0, 1.0, 0.0])  # the camera looks along +y


def _block(lo: tuple[float, float, float], hi: tuple[float, float, float], spacing: float) -> np.ndarray:
    """Points filling a box on a regular grid ``spacing`` apart."""
    axes = [np.arange(a, b + 1e-9, spacing) for a, b in zip(lo, hi)]
    return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)


def _join(parts: list[np.ndarray], resting_on: dict[int, int | None]) -> tuple[np.ndarray, np.ndarray]:
    """Join the parts (labels 1, 2, ...), their points taken as a one-row image (no pixel under another)."""
    points = np.vstack(parts)
    labels = np.concatenate([np.full(len(p), k + 1, dtype=np.int32) for k, p in enumerate(parts)])
    return join_attached_parts(points, labels, points[:, 2], resting_on, 0.015, 0.016, 0.008, ALONG_Y, (1, len(points))), labels


def test_a_handle_joins_its_body() -> None:
    """A handle hanging on a body's side, meeting it at its top and bottom, its foot 3 cm up."""
    body = _block((0.0, 0.0, 0.0), (0.1, 0.1, 0.12), 0.01)
    handle = np.vstack([_block((0.11, 0.04, 0.03), (0.14, 0.06, 0.04), 0.01),  # lower arm
                        _block((0.11, 0.04, 0.09), (0.14, 0.06, 0.1), 0.01),  # upper arm
                        _block((0.14, 0.04, 0.05), (0.14, 0.06, 0.08), 0.01)])  # grip
    out, _ = _join([body, handle], {1: None, 2: 1})
    assert np.all(out == 1)


def test_a_box_resting_on_a_box_stays() -> None:
    """A small box standing on a larger one's top meets it only at its own foot."""
    base = _block((0.0, 0.0, 0.0), (0.2, 0.2, 0.06), 0.01)
    top = _block((0.05, 0.05, 0.07), (0.12, 0.12, 0.14), 0.01)
    out, labels = _join([base, top], {1: None, 2: 1})
    assert np.array_equal(out, labels)


def test_a_floating_handle_joins_the_body_it_touches() -> None:
    """A handle with nothing under it (its body is beside it, not below) joins the body it touches."""
    body = _block((0.0, 0.0, 0.0), (0.1, 0.1, 0.12), 0.01)
    handle = _block((0.11, 0.04, 0.03), (0.13, 0.06, 0.1), 0.01)
    out, _ = _join([body, handle], {1: None, 2: None})
    assert np.all(out == 1)


def _depth_image(boxes: list[tuple[tuple[float, float], tuple[float, float], float]], cell: float = 0.01
                 ) -> tuple[np.ndarray, np.ndarray, tuple[int, int]]:
    """An orthographic view along +y of box faces (x range, z range, depth y), the first box in
    front: per pixel its point and box label (0 none)."""
    xs, zs = np.arange(0.0, 0.2 + 1e-9, cell), np.arange(0.0, 0.2 + 1e-9, cell)
    grid = np.zeros((len(zs), len(xs)), dtype=np.int32)
    depth = np.zeros_like(grid, dtype=np.float64)
    for k, ((x0, x1), (z0, z1), y) in reversed(list(enumerate(boxes))):
        inside = (xs[None, :] >= x0 - 1e-9) & (xs[None, :] <= x1 + 1e-9) & (zs[:, None] >= z0 - 1e-9) & (zs[:, None] <= z1 + 1e-9)
        grid[inside], depth[inside] = k + 1, y
    zz, xx = np.meshgrid(zs, xs, indexing="ij")
    return np.stack([xx, depth, zz], axis=-1).reshape(-1, 3), grid.ravel(), grid.shape


def test_an_object_whose_foot_a_nearer_one_hides_stays() -> None:
    """A box behind a larger one, seen only above it: it floats in the view and its points come
    within reach of the nearer box, yet that box hides its foot: no part of it."""
    points, labels, shape = _depth_image([((0.0, 0.2), (0.0, 0.12), 0.0), ((0.05, 0.1), (0.0, 0.16), 0.012)])
    out = join_attached_parts(points, labels, points[:, 2], {1: None, 2: None}, 0.015, 0.016, 0.008, ALONG_Y, shape)
    assert np.array_equal(out, labels)


def _cloud_join(parts: list[np.ndarray], resting_on: dict[int, int | None]) -> tuple[np.ndarray, np.ndarray]:
    """Join the parts of a cloud seen from around (no view): linked to their 8 nearest neighbours, on a 1 cm grid."""
    from realsim.perception.supervoxels import knn_links

    points = np.vstack(parts)
    labels = np.concatenate([np.full(len(p), k + 1, dtype=np.int32) for k, p in enumerate(parts)])
    a, b = knn_links(points, np.ones(len(points), dtype=bool), 8)
    keep = np.linalg.norm(points[a] - points[b], axis=1) < 0.025
    return join_attached_parts(points, labels, points[:, 2], resting_on, 0.015, 0.05, 0.025, links=(a[keep], b[keep]),
                               base_gap=0.01), labels


def test_in_a_cloud_a_piece_of_wall_joins_its_body_and_a_resting_box_stays() -> None:
    """A cloud's cluster resting on its body's side away from its own foot (a handle, a patch of a
    pitcher's wall) joins it; a box on a box, meeting it at its own foot, stays."""
    body = _block((0.0, 0.0, 0.0), (0.1, 0.1, 0.12), 0.01)
    handle = np.vstack([_block((0.11, 0.04, 0.03), (0.14, 0.06, 0.04), 0.01),
                        _block((0.11, 0.04, 0.09), (0.14, 0.06, 0.1), 0.01),
                        _block((0.14, 0.04, 0.05), (0.14, 0.06, 0.08), 0.01)])
    out, _ = _cloud_join([body, handle], {1: None, 2: 1})
    assert np.all(out == 1)
    base = _block((0.0, 0.0, 0.0), (0.2, 0.2, 0.06), 0.01)
    top = _block((0.05, 0.05, 0.07), (0.12, 0.12, 0.14), 0.01)
    out, labels = _cloud_join([base, top], {1: None, 2: 1})
    assert np.array_equal(out, labels)


def _rod_on(body: np.ndarray, far: np.ndarray, foot_gap: float) -> tuple[np.ndarray, np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """A thin rod (1 cm, along x at y = 0.1, its foot at z = 0.065) on ``body`` plus the ``far`` points of it; links: the
    rod's foot to the body's points ``foot_gap`` beside it, its middle and top to the ``far`` ones (the view's
    neighbours across the rod's far outline, within reach but over a depth jump)."""
    xs = np.arange(0.05, 0.151, 0.01)
    rod = np.concatenate([np.stack([xs, np.full_like(xs, 0.1), np.full_like(xs, z)], axis=1) for z in (0.065, 0.07, 0.075)])
    points = np.vstack([body, far, rod])
    labels = np.concatenate([np.ones(len(body) + len(far), dtype=np.int32), np.full(len(rod), 2, dtype=np.int32)])
    tree = {tuple(np.round(p, 4)): i for i, p in enumerate(points)}
    a, b = [], []
    for k, x in enumerate(xs):
        foot, mid, top = len(body) + len(far) + k, len(body) + len(far) + len(xs) + k, len(body) + len(far) + 2 * len(xs) + k
        a.append(foot), b.append(tree[(round(x, 4), round(0.1 - foot_gap, 4), 0.06)])
        for end in (mid, top) if len(far) else ():
            a.append(end), b.append(tree[(round(x, 4), 0.105, 0.06)])
    return points, labels, (np.array(a), np.array(b))


def test_a_thin_body_lying_on_a_top_meets_it_at_the_crease_under_it() -> None:
    """A rod lying on a box top: its foot meets the top at a depth-continuous crease, its far outline only
    comes within reach of the top behind it (over a depth jump): it rests on the box and stays."""
    xs = np.arange(0.05, 0.151, 0.01)
    body = _block((0.0, 0.0, 0.0), (0.2, 0.2, 0.06), 0.01)
    far = np.stack([xs, np.full_like(xs, 0.105), np.full_like(xs, 0.06)], axis=1)
    points, labels, links = _rod_on(body, far, 0.0)
    out = join_attached_parts(points, labels, points[:, 2], {1: None, 2: 1}, 0.015, 0.016, 0.008, links=links)
    assert np.array_equal(out, labels)


def test_a_body_lying_on_an_upward_face_rests_however_little_of_it_is_seen() -> None:
    """A rod whose foot meets an upward face of a body seen only beside it (its foot over none of that
    body from above) rests on it given the normals; on a wall (normals sideways) it is the body's part."""
    body = _block((0.0, 0.0, 0.0), (0.2, 0.09, 0.06), 0.01)
    points, labels, links = _rod_on(body, np.zeros((0, 3)), 0.01)
    up = np.tile([0.0, 0.0, 1.0], (len(points), 1))
    side = np.tile([0.0, -1.0, 0.0], (len(points), 1))
    args = (points, labels, points[:, 2], {1: None, 2: 1}, 0.015, 0.016, 0.008)
    assert np.array_equal(join_attached_parts(*args, links=links, normals=up), labels)
    assert np.all(join_attached_parts(*args, links=links, normals=side) == 1)
    assert np.all(join_attached_parts(*args, links=links) == 1)
