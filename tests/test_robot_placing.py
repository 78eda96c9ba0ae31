"""Release poses: the footprint a spot must keep over its support, spots within a free area."""

from __future__ import annotations

import numpy as np
import pytest

from realsim.robot.placing import ReleaseParams, footprint_ring, release_poses, spots


def test_footprint_ring_reaches_half_way_to_the_edge_in_every_direction() -> None:
    rng = np.random.default_rng(0)
    box = rng.uniform([-0.1, -0.02, 0.0], [0.1, 0.02, 0.05], (2000, 3)) + [0.3, 0.2, 0.0]  # a 20 x 4 cm banana-like footprint
    ring = footprint_ring(box)
    assert np.allclose(ring[0], 0.0)
    assert np.abs(ring[:, 0]).max() == pytest.approx(0.05, abs=0.002)  # half of the 10 cm half-length
    assert np.abs(ring[:, 1]).max() == pytest.approx(0.01, abs=0.002)


def test_spots_and_poses_try_the_centre_first_then_nearer_the_robot() -> None:
    base = np.array([0.0, -1.0])
    near = spots(np.zeros(2), 0.04, base, ring=6)
    assert np.allclose(near[0], 0.0) and len(near) == 13
    assert np.linalg.norm(near[1] - base) <= np.linalg.norm(near[6] - base)
    poses = release_poses(near, ReleaseParams())
    assert len(poses) == 6 + 6 + 12 * 3 <= ReleaseParams().max_poses
    assert {round(y, 3) for _, y, _ in poses[:6]} == {round(y, 3) for y in ReleaseParams().yaws}  # every yaw at the first spot
    assert all(d == ReleaseParams().drops[0] for _, _, d in poses[:42])  # the other spots before any higher release
    assert all(np.allclose(xy, 0.0) and d > ReleaseParams().drops[0] for xy, _, d in poses[42:])  # higher releases last, within the limit
