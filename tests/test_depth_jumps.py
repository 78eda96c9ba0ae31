"""Depth jumps of an organized view: a link is a jump when it is much longer than the links around it."""

from __future__ import annotations

import numpy as np

from realsim.perception.depth_jumps import link_lengths, pixel_jumps
from realsim.synth.camera import kinect_noise

JUMP, FACTOR, WINDOW = 0.008, 2.5, 5


def _view(depth: np.ndarray, f: float = 525.0) -> np.ndarray:
    """Back-project a depth image (optical frame, pinhole with focal ``f`` pixels, centred)."""
    h, w = depth.shape
    v, u = np.mgrid[0:h, 0:w].astype(float)
    return np.stack([(u - (w - 1) / 2) / f * depth, (v - (h - 1) / 2) / f * depth, depth], axis=-1).reshape(-1, 3)


def _step_scene(distance: float, step: float, seed: int = 0) -> tuple[np.ndarray, tuple[int, int]]:
    """A face-on wall at ``distance`` whose right half stands ``step`` farther, with Kinect-like noise."""
    h, w = 60, 80
    depth = np.full((h, w), distance)
    depth[:, w // 2:] += step
    return _view(kinect_noise(depth, np.random.default_rng(seed))), (h, w)


def _cut_shares(distance: float, step: float) -> tuple[float, float, float]:
    """Share of same-surface links cut by the per-pixel limit, by the fixed one, and share of the
    links across the step that the per-pixel limit cuts."""
    pts, shape = _step_scene(distance, step)
    h, w = shape
    jumps = pixel_jumps(pts, shape, JUMP, FACTOR, WINDOW).reshape(h, w)
    across = link_lengths(pts, shape)[:, :, 0][:, :-1]  # right-neighbour links, (h, w - 1)
    limit = np.minimum(jumps[:, :-1], jumps[:, 1:])
    edge = np.zeros_like(across, dtype=bool)
    edge[:, w // 2 - 1] = True
    return float((across[~edge] >= limit[~edge]).mean()), float((across[~edge] >= JUMP).mean()), float((across[edge] >= limit[edge]).mean())


def test_far_surfaces_stay_linked_where_a_fixed_length_cuts_them() -> None:
    kept_cut, fixed_cut, step_cut = _cut_shares(3.0, 0.10)
    assert fixed_cut > 0.5  # 8 mm cuts most of a wall's links at 3 m: it falls apart into noise
    assert kept_cut < 0.1  # a few stray links: the wall stays one connected surface
    assert step_cut > 0.95  # a 10 cm step is still a jump


def test_near_surfaces_keep_the_fixed_length() -> None:
    pts, shape = _step_scene(1.0, 0.02)
    jumps = pixel_jumps(pts, shape, JUMP, FACTOR, WINDOW).reshape(shape)
    assert np.allclose(jumps[:, : shape[1] // 2 - WINDOW], JUMP)  # at 1 m the links are short: the fixed limit holds
    kept_cut, _, step_cut = _cut_shares(1.0, 0.02)
    assert kept_cut < 0.01 and step_cut > 0.95


def test_missing_pixels_get_the_fixed_length() -> None:
    pts, shape = _step_scene(2.0, 0.05)
    pts[:200] = np.nan
    jumps = pixel_jumps(pts, shape, JUMP, FACTOR, WINDOW)
    assert np.all(jumps[:200] >= JUMP) and np.isfinite(jumps).all()


def test_link_lengths_are_the_neighbour_distances() -> None:
    pts = np.array([[0, 0, 1], [0.1, 0, 1], [0, 0.2, 1], [0.1, 0.2, 1]], dtype=float)
    lengths = link_lengths(pts, (2, 2))
    assert np.allclose(lengths[0, 0], [0.1, np.nan, 0.2, np.nan], equal_nan=True)
    assert np.allclose(lengths[1, 1], [np.nan, 0.1, np.nan, 0.2], equal_nan=True)
