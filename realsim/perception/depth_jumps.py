"""How far apart two neighbouring pixels of a camera view may lie and still be on one surface.

Two neighbouring pixels at depth z see points s = z/f apart across their rays (f the focal length
in pixels). On a surface turned by an angle a from facing the camera the link between them runs
s/cos(a) along the surface, and the sensor's depth noise (sigma(z); for a Kinect it grows with the
square of the depth) moves its two ends along their rays independently: the mean square link is
(s/cos a)^2 + 2 sigma^2 (the cross term averages out). A link longer than that for the steepest
surface still taken as one (``max_angle``) with the noise at ``sigmas`` standard deviations
crosses a depth jump. The limit thus follows the sensor at each depth: a fixed length that parts
two objects at 1 m cuts every link of an object at 3 m into noise. It does not follow the lengths
of the links around a pixel, which are long exactly at silhouettes and on steep near surfaces.

The noise is the capture's own: the second difference of the depth along image rows and columns
(noise of standard deviation sigma gives sqrt(6) sigma; a smooth surface adds next to nothing),
its robust spread taken over pixels of similar depth, and one scale c of sigma = c z^2 (a
structured-light or stereo sensor's noise) the median over those ranges: a range whose surfaces
add texture, or whose depth is quantized flat, moves one range's estimate, not the sensor's.
"""

from __future__ import annotations

import numpy as np

__all__ = ["depth_noise", "link_lengths", "pixel_jumps"]

NOISE_BINS = 16  # depth ranges (equal pixel counts) over which the noise is measured
MIN_BIN_PIXELS = 500  # fewer second differences per range measure no spread


def link_lengths(points: np.ndarray, grid_shape: tuple[int, int]) -> np.ndarray:
    """(H, W, 4) distance from each pixel to its right, left, lower and upper neighbour (NaN where
    either is missing or off the image)."""
    h, w = grid_shape
    p = np.asarray(points, dtype=np.float64).reshape(h, w, 3)
    out = np.full((h, w, 4), np.nan)
    across = np.linalg.norm(np.diff(p, axis=1), axis=2)
    down = np.linalg.norm(np.diff(p, axis=0), axis=2)
    out[:, :-1, 0], out[:, 1:, 1] = across, across
    out[:-1, :, 2], out[1:, :, 3] = down, down
    return out


def depth_noise(depth: np.ndarray) -> np.ndarray:
    """(H, W) the standard deviation (m) of the depth noise at each pixel's depth, measured on the
    depth image (H, W; NaN where none): 1.4826 times the median absolute second difference along
    rows and columns over sqrt(6), per range of depth (of the three pixels' mean, whose noise is
    independent of their second difference's; the middle pixel's is not), as one sensor's c z^2 with c
    the median over the ranges of sigma / z^2; 0 where the image has too few pixels to tell."""
    d = np.asarray(depth, dtype=np.float64)
    z_parts, e_parts = [], []
    for img in (d, d.T):
        second = img[:, :-2] - 2.0 * img[:, 1:-1] + img[:, 2:]
        ok = np.isfinite(second)
        z_parts.append(((img[:, :-2] + img[:, 1:-1] + img[:, 2:]) / 3.0)[ok])  # independent of the second difference
        e_parts.append(np.abs(second[ok]))
    z, e = np.concatenate(z_parts), np.concatenate(e_parts)
    bins = min(NOISE_BINS, len(z) // MIN_BIN_PIXELS)
    if bins < 1:
        return np.where(np.isfinite(d), 0.0, np.nan)
    order = np.argsort(z, kind="stable")
    parts = np.array_split(order, bins)
    at = np.array([np.median(z[p]) for p in parts])
    sigma = np.array([1.4826 * np.median(e[p]) / np.sqrt(6.0) for p in parts])
    scale = float(np.median(sigma / at**2))  # one sensor: sigma = scale z^2, whatever each range's surfaces add
    out: np.ndarray = scale * d**2  # NaN depths stay NaN
    return out


def pixel_jumps(depth: np.ndarray, focal: float, least: float, max_angle: float, sigmas: float) -> np.ndarray:
    """(H*W,) per pixel of a depth image (H, W; NaN where none), the length beyond which a link from
    it crosses a depth jump: the root sum square of its footprint ``depth / focal`` on a surface
    turned ``max_angle`` degrees from the camera and ``sigmas`` standard deviations of the
    difference of two pixels' measured noise there (:func:`depth_noise`); never under ``least``,
    ``least`` without depth."""
    d = np.asarray(depth, dtype=np.float64)
    footprint = d / focal / np.cos(np.radians(max_angle))
    limit = np.hypot(footprint, sigmas * np.sqrt(2.0) * depth_noise(d))
    out: np.ndarray = np.maximum(least, np.nan_to_num(limit, nan=least)).ravel()
    return out
