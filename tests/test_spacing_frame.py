"""The point spacing and the RANSAC proposals are properties of the points, not of the frame they
are written in: a floor lying on the input's z = 0 (a grid plane of an origin-anchored grid) or
moved by half a cell, a scene in metres or centimetres, give the same measures."""

from __future__ import annotations

import numpy as np
import pytest

from realsim.perception.planes import PlaneParams, ransac_proposals
from realsim.perception.resolution import point_spacing


def _room(seed: int = 0) -> np.ndarray:
    """A 3 x 3 m floor at z = 0 with 1 mm of noise and a 1 x 0.8 m table top 0.75 m above it."""
    rng = np.random.default_rng(seed)
    floor = np.column_stack([rng.uniform(-1.5, 1.5, (60_000, 2)), rng.normal(0.0, 0.001, 60_000)])
    top = np.column_stack([rng.uniform([-0.5, -0.4], [0.5, 0.4], (15_000, 2)), 0.75 + rng.normal(0.0, 0.001, 15_000)])
    return np.vstack([floor, top])


def test_spacing_moves_and_scales_with_the_points() -> None:
    pts = _room()
    spacing = point_spacing(pts)
    half_cell = np.array([0.0, 0.0, 0.015])  # the grid's cells are extent / 100 = 3 cm
    assert point_spacing(pts + half_cell) == pytest.approx(spacing, rel=1e-6)
    assert point_spacing(pts * 100.0) == pytest.approx(100.0 * spacing, rel=1e-6)
    assert 0.008 < spacing < 0.012  # 75k points on 9.8 m^2: 1 / sqrt(density) = 11.4 mm


def test_ransac_proposals_follow_the_points() -> None:
    pts = _room(1)
    params = PlaneParams()
    moved = ransac_proposals(pts + np.array([0.00031, -0.00047, 0.00023]), params, seed=0)
    plain = ransac_proposals(pts, params, seed=0)
    assert len(moved) == len(plain) >= 2
    for (n0, d0, in0), (n1, d1, in1) in zip(plain, moved):
        assert len(in0) == len(in1) and np.allclose(n0, n1, atol=1e-9)
