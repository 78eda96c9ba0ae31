"""Two segments of a camera view that meet at a depth step where one body's piece hides its own other piece.

A lying drill's battery hides the foot of its grip: the view shows the grip's surface continuing
beneath the battery's rim, a step in depth along their whole shared border and no pixel linking the
two. A body's nearer piece there turns away from the camera at its rim (an occluding contour, not a
face seen edge-on) and that rim lies on the hidden continuation of the farther piece's surface: the
farther surface, extended beneath the step, runs into the nearer piece. A separate body seen behind
another lies farther back than that (its surface passes behind the occluder, centimetres under its
rim), and two touching bodies side by side meet in a depth-continuous fold
(:mod:`realsim.perception.shallow_folds`), and a body lying on another shows their contact: a
depth-continuous crease along part of the border. Two segments are joined when their border is a
step on at least ``min_links`` pixel links and continuous on fewer, the same segment nearer on at least ``consistent_share`` of
them, the nearer side's surface turned from the camera (|n . view| under ``max_facing``) and its rim
within ``max_gap`` of the farther side's tangent plane (medians over the border's links).
"""

from __future__ import annotations

import numpy as np

from realsim.perception.supervoxels import link_components

__all__ = ["join_hidden_steps", "step_measures"]


def _border_links(labels: np.ndarray, grid_shape: tuple[int, int]) -> tuple[np.ndarray, np.ndarray]:
    """Pixel index pairs of image 4-neighbours in two different segments (``labels`` >= 0)."""
    h, w = grid_shape
    idx = np.arange(h * w).reshape(h, w)
    a = np.concatenate([idx[:, :-1].ravel(), idx[:-1].ravel()])
    b = np.concatenate([idx[:, 1:].ravel(), idx[1:].ravel()])
    border = (labels[a] >= 0) & (labels[b] >= 0) & (labels[a] != labels[b])
    return a[border], b[border]


def step_measures(labels: np.ndarray, points: np.ndarray, normals: np.ndarray, grid_shape: tuple[int, int],
                  axis: np.ndarray, jump: np.ndarray | float) -> dict[tuple[int, int], tuple[int, int, float, float, float]]:
    """Per pair of bordering segments (lower label first): the border's link count, its step links
    (longer than ``jump``, m, or per pixel: the shorter end's), the share of step links on which the
    more often nearer segment is nearer (depth along the viewing ``axis``), the median |n . axis| of
    the nearer side's pixels (their ``normals``) and the median distance (m) of the nearer side's end
    from the farther side's tangent plane."""
    a, b = _border_links(labels, grid_shape)
    limit = np.minimum(jump[a], jump[b]) if isinstance(jump, np.ndarray) else jump
    with np.errstate(invalid="ignore"):
        step = ~(np.linalg.norm(points[a] - points[b], axis=1) <= limit)
    a_near = points[a] @ axis < points[b] @ axis
    near, far = np.where(a_near, a, b), np.where(a_near, b, a)
    lo, hi = np.minimum(labels[a], labels[b]), np.maximum(labels[a], labels[b])
    base = int(labels.max(initial=0)) + 1
    keys, inverse = np.unique(lo.astype(np.int64) * base + hi, return_inverse=True)
    inverse = inverse.ravel()
    total = np.bincount(inverse, minlength=len(keys))
    out: dict[tuple[int, int], tuple[int, int, float, float, float]] = {}
    for k in np.flatnonzero(np.bincount(inverse, step, minlength=len(keys)) > 0):
        sel = (inverse == k) & step
        nearer = labels[near[sel]]
        share = float(max(np.mean(nearer == nearer[0]), np.mean(nearer != nearer[0])))
        facing = float(np.nanmedian(np.abs(normals[near[sel]] @ axis)))
        gap = float(np.nanmedian(np.abs(((points[near[sel]] - points[far[sel]]) * normals[far[sel]]).sum(axis=1))))
        out[(int(keys[k] // base), int(keys[k] % base))] = (int(total[k]), int(sel.sum()), share, facing, gap)
    return out


def join_hidden_steps(labels: np.ndarray, points: np.ndarray, normals: np.ndarray, grid_shape: tuple[int, int],
                      axis: np.ndarray, jump: np.ndarray | float, max_gap: float, max_facing: float, min_links: int,
                      consistent_share: float) -> np.ndarray:
    """``labels`` (>= 0 segments, -1 none, one per pixel of ``grid_shape``) with every two segments
    joined whose border is a depth step (at least ``min_links`` step links, fewer continuous ones: no
    contact seen) where one body's nearer piece hides its farther
    piece (:func:`step_measures`: nearer on ``consistent_share`` of the steps, facing under
    ``max_facing``, rim within ``max_gap``, m, of the farther surface)."""
    pairs = [k for k, (total, steps, share, facing, gap) in
             step_measures(labels, points, normals, grid_shape, axis, jump).items()
             if steps >= min_links and total - steps < min_links and share >= consistent_share
             and facing < max_facing and gap <= max_gap]
    if not pairs:
        return labels
    joined = np.array(pairs, dtype=np.int64)
    root = link_components(int(labels.max(initial=0)) + 1, joined[:, 0], joined[:, 1])
    return np.where(labels >= 0, root[np.maximum(labels, 0)], labels)
