"""The arm's reach by geometry: sound (no posture of the arm lies past it) and close enough to
rule out a far push before any IK."""

from __future__ import annotations

import numpy as np

from realsim.robot.grasps import frame_from
from realsim.robot.ik import ArmIK
from realsim.robot.reach import ReachBound


def test_no_posture_passes_the_bound_and_a_pose_past_it_has_no_ik() -> None:
    ik = ArmIK(np.array([0.2, -0.1, 0.75]), np.array([np.cos(0.3), 0.0, 0.0, np.sin(0.3)]))  # turned 0.6 rad
    bound = ReachBound.of(ik)
    rng = np.random.default_rng(0)
    for q in rng.uniform(ik.lower, ik.upper, (400, 7)):  # every posture the joints allow
        pos, rot = ik.fk(q)
        assert bound.excess(pos, rot) <= 1e-9
    down = frame_from(np.array([0.0, 0.0, -1.0]), np.array([0.0, 1.0, 0.0]))
    ahead = np.array([np.cos(0.6), np.sin(0.6), 0.0])
    near = ik.base_pos + 0.5 * ahead + [0, 0, 0.05]
    assert bound.excess(near, down) < 0 and ik.solve(near, _quat(down), q_init=ik.home).converged
    far = [ik.base_pos + r * ahead + [0, 0, 0.05] for r in (0.9, 1.2, 1.6)]
    assert all(bound.excess(p, down) > 0 for p in far)
    assert not ik.solve(far[0], _quat(down), q_init=ik.home).converged  # the nearest of them: IK agrees


def _quat(rot: np.ndarray) -> np.ndarray:
    from realsim.robot.ik import mat_to_quat

    return mat_to_quat(rot)
