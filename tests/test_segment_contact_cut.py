"""Contact cuts: touching objects given as one cluster are cut along their concave contact; a
single object, or a handle meeting its body at both ends, is not cut."""

from __future__ import annotations

import numpy as np

from realsim.metrics import matched_iou
from realsim.perception.contact_cut import CutParams, cut_contacts
from realsim.perception.supervoxels import knn_links

STEP = 0.004  # m between samples


def _box(centre: tuple[float, float], half: float, height: float) -> tuple[np.ndarray, np.ndarray]:
    """Points and outward normals of a box's four sides and top, standing on z = 0."""
    g = np.arange(-half + STEP / 2, half, STEP)
    zs = np.arange(STEP / 2, height, STEP)
    pts, nrm = [], []
    for axis, sign in ((0, 1.0), (0, -1.0), (1, 1.0), (1, -1.0)):
        u, z = np.meshgrid(g, zs)
        p = np.zeros((u.size, 3))
        p[:, axis], p[:, 1 - axis], p[:, 2] = sign * half, u.ravel(), z.ravel()
        n = np.zeros_like(p)
        n[:, axis] = sign
        pts.append(p)
        nrm.append(n)
    u, v = np.meshgrid(g, g)
    pts.append(np.stack([u.ravel(), v.ravel(), np.full(u.size, height)], axis=1))
    nrm.append(np.tile([0.0, 0.0, 1.0], (u.size, 1)))
    p = np.concatenate(pts)
    p[:, :2] += centre
    return p, np.concatenate(nrm)


def _can(centre: tuple[float, float], r: float, height: float) -> tuple[np.ndarray, np.ndarray]:
    """Points and outward normals of a closed cylinder's side and top, standing on z = 0."""
    a, z = np.meshgrid(np.arange(0.0, 2 * np.pi, STEP / r), np.arange(STEP / 2, height, STEP))
    side = np.stack([np.cos(a.ravel()), np.sin(a.ravel()), np.zeros(a.size)], axis=1)
    pts = [np.c_[r * side[:, :2], z.ravel()]]
    nrm = [side]
    for rr in np.arange(STEP, r, STEP):
        t = np.arange(0.0, 2 * np.pi, STEP / rr)
        pts.append(np.stack([rr * np.cos(t), rr * np.sin(t), np.full(len(t), height)], axis=1))
        nrm.append(np.tile([0.0, 0.0, 1.0], (len(t), 1)))
    p = np.concatenate(pts)
    p[:, :2] += centre
    return p, np.concatenate(nrm)


def _cut(parts: list[tuple[np.ndarray, np.ndarray]], seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """All parts as one cluster (1 mm noise), cut; returns (cut labels, ground-truth part ids 1..K)."""
    points = np.concatenate([p for p, _ in parts])
    normals = np.concatenate([n for _, n in parts])
    gt = np.concatenate([np.full(len(p), k + 1) for k, (p, _) in enumerate(parts)])
    points = points + np.random.default_rng(seed).normal(0.0, 0.001, points.shape)
    a, b = knn_links(points, np.ones(len(points), dtype=bool), 8)
    labels = cut_contacts(points, normals, points[:, 2], np.zeros(len(points), dtype=np.int64), a, b,
                          CutParams(min_size=0.02, min_points=30))
    return labels, gt


def test_a_box_against_a_can_is_cut_along_the_contact() -> None:
    """A 5.6 cm box whose face touches a can's side (a flat face against a curved side, the pair
    that merged before) comes apart into the two objects, at two seeds of noise."""
    for seed in (0, 1):
        labels, gt = _cut([_box((0.0, 0.0), 0.028, 0.056), _can((0.028 + 0.04, 0.0), 0.04, 0.09)], seed)
        assert len(np.unique(labels)) == 2
        ious, _ = matched_iou(labels + 1, gt)
        assert ious.min() > 0.9, ious


def test_a_single_object_and_a_handle_are_not_cut() -> None:
    """A box alone stays whole; a can with a box-shaped handle attached high on its side (the
    handle meets the body above its own base, so it does not rest on it) is not cut either."""
    labels, _ = _cut([_box((0.0, 0.0), 0.04, 0.1)])
    assert len(np.unique(labels)) == 1
    can = _can((0.0, 0.0), 0.04, 0.1)
    handle, hn = _box((0.055, 0.0), 0.015, 0.03)
    handle[:, 2] += 0.05  # from 5 to 8 cm high, pressed against the side
    keep = handle[:, 0] > 0.04
    labels, _ = _cut([can, (handle[keep], hn[keep])])
    assert len(np.unique(labels)) == 1


def test_a_box_on_a_box_is_cut_but_a_piece_hanging_beside_is_not() -> None:
    """A small box stacked on a larger one rests on its top (its foot lies over the base seen from
    above) and is cut off; a piece joined to a can's side only at its own foot, hanging beside the
    can over nothing (a handle's lower end), meets it in its lowest part too but rests on nothing,
    so it stays with the can."""
    base, bn = _box((0.0, 0.0), 0.06, 0.05)
    top, tn = _box((0.01, 0.0), 0.025, 0.05)
    top[:, 2] += 0.05
    labels, gt = _cut([(base, bn), (top, tn)])
    assert len(np.unique(labels)) == 2
    ious, _ = matched_iou(labels + 1, gt)
    assert ious.min() > 0.9, ious
    can = _can((0.0, 0.0), 0.04, 0.1)
    piece, pn = _box((0.065, 0.0), 0.015, 0.04)
    piece[:, 2] += 0.02  # from 2 to 6 cm high, 1 cm off the can's side
    foot, fn = _box((0.045, 0.0), 0.0075, 0.012)
    foot[:, 2] += 0.02  # the only join: a 1.5 cm bar from the can to the piece's foot
    keep = (foot[:, 0] > 0.04) & (foot[:, 0] < 0.05)
    labels, _ = _cut([can, (piece, pn), (foot[keep], fn[keep])])
    assert len(np.unique(labels)) == 1
