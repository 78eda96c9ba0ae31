"""One IK solver stood at several base poses answers as a solver built at each pose (the pose
search reuses one): nothing of an earlier solve carries over."""

from __future__ import annotations

import numpy as np

from realsim.composition.robot_placement import SCORING_IK, TOP_DOWN, bare_panda, score_pose
from realsim.geometry import yaw_quat
from realsim.robot.ik import ArmIK

POSES = [(-0.7, 0.0, 0.0), (0.0, -0.65, np.pi / 2), (0.55, 0.3, np.pi)]
TARGETS = [np.array([0.05, 0.1, 0.9]), np.array([-0.2, -0.1, 0.85]), np.array([0.3, 0.2, 1.0]), np.array([1.5, 1.5, 0.8])]


def _answers(ik: ArmIK) -> list[tuple]:
    out = []
    for t in TARGETS:
        res = ik.solve(t, TOP_DOWN)
        out.append((res.converged, res.iterations, res.method, res.q.tobytes(), res.manipulability))
    return out


def test_placed_solver_answers_as_a_fresh_one():
    reused = ArmIK(np.zeros(3), np.array([1.0, 0.0, 0.0, 0.0]), SCORING_IK, scene=bare_panda())
    for x, y, yaw in POSES:
        base, quat = np.array([x, y, 0.75]), np.array(yaw_quat(yaw))
        fresh = ArmIK(base, quat, SCORING_IK, scene=bare_panda())
        reused.place(base, quat)
        assert _answers(reused) == _answers(fresh)


def test_score_pose_repeats_exactly():
    first = [score_pose(p, 0.75, TARGETS) for p in POSES]
    assert [score_pose(p, 0.75, TARGETS) for p in reversed(POSES)] == first[::-1]
    assert any(reach > 0 for _, reach, _ in first)
