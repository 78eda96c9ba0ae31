"""Depth jumps of an organized view: a link is a jump when it is longer than the sensor's footprint
and noise allow at its depth (measured on the view), whatever the links around it."""

from __future__ import annotations

import numpy as np

from realsim.perception.depth_jumps import depth_noise, link_lengths, pixel_jumps
from realsim.perception.segment_params import SegmentParams
from realsim.perception.supervoxels import grid_normals
from realsim.synth.camera import kinect_noise

F = 525.0
JUMP, ANGLE, SIGMAS = SegmentParams.jump_distance, SegmentParams.jump_max_angle, SegmentParams.jump_sigmas


def _view(depth: np.ndarray, f: float = F) -> np.ndarray:
    """Back-project a depth image (optical frame, pinhole with focal ``f`` pixels, centred)."""
    h, w = depth.shape
    v, u = np.mgrid[0:h, 0:w].astype(float)
    return np.stack([(u - (w - 1) / 2) / f * depth, (v - (h - 1) / 2) / f * depth, depth], axis=-1).reshape(-1, 3)


def _noisy(depth: np.ndarray, seed: int = 0) -> np.ndarray:
    return kinect_noise(depth, np.random.default_rng(seed))


def _step(distance: float, step: float, h: int = 120, w: int = 160) -> np.ndarray:
    """A face-on wall at ``distance`` whose right half stands ``step`` farther (noise-free depth)."""
    depth = np.full((h, w), distance)
    depth[:, w // 2:] += step
    return depth


def _cut_shares(depth: np.ndarray, edge_col: int) -> tuple[float, float, float]:
    """Share of same-surface right links the sensor limit cuts, share the fixed one cuts, and share of
    the links across column ``edge_col`` the sensor limit cuts."""
    h, w = depth.shape
    pts = _view(depth)
    jumps = pixel_jumps(depth, F, JUMP, ANGLE, SIGMAS).reshape(h, w)
    across = link_lengths(pts, (h, w))[:, :, 0][:, :-1]  # right-neighbour links, (h, w - 1)
    limit = np.minimum(jumps[:, :-1], jumps[:, 1:])
    edge = np.zeros_like(across, dtype=bool)
    edge[:, edge_col] = True
    return float((across[~edge] >= limit[~edge]).mean()), float((across[~edge] >= JUMP).mean()), float((across[edge] >= limit[edge]).mean())


def test_measured_noise_follows_the_noise_the_view_has() -> None:
    """A wall receding from 0.8 to 3 m with depth noise sigma = c z^2: the noise read off the image
    is the one added (within 5 %) for two sensors c; the generator's Kinect-like noise (not exactly
    z^2) within 20 % from 1 to 3 m; a noise-free view measures none."""
    h, w = 90, 240
    clean = np.repeat(np.linspace(0.8, 3.0, w)[None, :], h, axis=0)
    rng = np.random.default_rng(0)
    for c in (0.001, 0.003):
        sigma = depth_noise(clean + rng.standard_normal(clean.shape) * c * clean**2)
        assert np.allclose(np.median(sigma, axis=0) / (c * clean[0] ** 2), 1.0, atol=0.05)
    sigma = depth_noise(_noisy(clean))
    for z in (1.0, 2.0, 3.0):
        col = int(np.argmin(np.abs(clean[0] - z)))
        truth = 0.0008 + 0.0012 * (z - 0.4) ** 2  # the generator's noise at z
        assert abs(np.median(sigma[:, col]) / truth - 1) < 0.2, (z, np.median(sigma[:, col]), truth)
    assert np.nanmax(depth_noise(clean)) < 1e-5


def test_far_surfaces_stay_linked_where_a_fixed_length_cuts_them() -> None:
    depth = _noisy(_step(3.0, 0.10))
    kept_cut, fixed_cut, step_cut = _cut_shares(depth, depth.shape[1] // 2 - 1)
    assert fixed_cut > 0.5  # 8 mm cuts most of a wall's links at 3 m: it falls apart into noise
    assert kept_cut < 0.02  # a few stray links: the wall stays one connected surface
    assert step_cut > 0.95  # a 10 cm step is still a jump


def test_near_steps_stay_jumps() -> None:
    depth = _noisy(_step(1.0, 0.02))
    kept_cut, _, step_cut = _cut_shares(depth, depth.shape[1] // 2 - 1)
    assert kept_cut < 0.01 and step_cut > 0.95


def test_steep_near_surfaces_do_not_raise_the_limit() -> None:
    """Two surfaces seen almost edge-on (their links are long, like a silhouette's), the
    second 1 cm behind where the first would go on: they get the limit of a face-on surface at their depth, so
    the step between them stays a jump (a limit taken from the lengths of the links around a pixel
    joins them)."""
    h, w = 120, 160
    slope = np.tan(np.radians(80.0)) / F  # relative depth gained per pixel along rows and along columns
    v, u = np.mgrid[0:h, 0:w]
    ramp = np.exp(slope * (u - w // 2 + v - h // 2))  # z grows by z * slope each pixel either way
    clean = np.where(u < w // 2, ramp, ramp + 0.01)  # the step 1 cm longer than the links, at 0.5-1.9 m
    depth = _noisy(clean)
    limits = pixel_jumps(depth, F, JUMP, ANGLE, SIGMAS).reshape(h, w)
    face_on = pixel_jumps(_noisy(np.full((h, w), 1.0)), F, JUMP, ANGLE, SIGMAS).reshape(h, w)
    assert abs(limits[h // 2, w // 2 - 1] / np.median(face_on) - 1) < 0.15
    _, _, step_cut = _cut_shares(depth, w // 2 - 1)
    assert step_cut > 0.95


def test_missing_pixels_get_the_fixed_length() -> None:
    depth = _noisy(_step(2.0, 0.05))
    depth[:2, :] = np.nan
    jumps = pixel_jumps(depth, F, JUMP, ANGLE, SIGMAS)
    assert np.allclose(jumps[: 2 * depth.shape[1]], JUMP) and np.isfinite(jumps).all()
    assert np.all(jumps >= JUMP)


def test_link_lengths_are_the_neighbour_distances() -> None:
    pts = np.array([[0, 0, 1], [0.1, 0, 1], [0, 0.2, 1], [0.1, 0.2, 1]], dtype=float)
    lengths = link_lengths(pts, (2, 2))
    assert np.allclose(lengths[0, 0], [0.1, np.nan, 0.2, np.nan], equal_nan=True)
    assert np.allclose(lengths[1, 1], [np.nan, 0.1, np.nan, 0.2], equal_nan=True)


def test_far_normals_take_the_sensor_limits() -> None:
    """A face-on wall at 3 m: tangents kept by the sensor's limits (not a fixed 16 mm, which keeps the
    ones whose noise happens to be small, and leaves some pixels none) give truer normals."""
    h, w = 120, 160
    depth = _noisy(np.full((h, w), 3.0))
    pts, valid = _view(depth), np.ones(h * w, dtype=bool)
    errors = []
    for step in (JUMP, pixel_jumps(depth, F, JUMP, ANGLE, SIGMAS)):
        normals = grid_normals(pts, valid, (h, w), 5, step)
        errors.append(np.nanmedian(np.degrees(np.arccos(np.clip(-normals[:, 2], -1, 1)))))
    fixed, sensor = errors
    assert sensor < 0.85 * fixed, (fixed, sensor)
