"""DepthView.denoised: each object pixel's depth from the plane fitted to its own object's window."""

from __future__ import annotations

import numpy as np

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
