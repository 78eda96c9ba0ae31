"""Whether a tcp pose is beyond the arm's reach, by geometry alone (no IK).

In a chain of hinges, each joint's anchor keeps its distance to the next joint's anchor whatever
the joint angles are, and the first joint's anchor never moves. The wrist (the last joint's
anchor) is rigid with the tcp, so a tcp pose puts the wrist at one point; when that point lies
further from the first anchor than the sum of the anchor-to-anchor lengths, no posture reaches
the pose. The bound is loose (the links cannot all line up), so a pose it keeps may still be
out of reach, but a pose it rules out is out of reach for certain.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from realsim.robot.ik import ArmIK
from realsim.robot.model import ARM_JOINTS, PREFIX

__all__ = ["ReachBound"]


@dataclass(frozen=True)
class ReachBound:
    """The arm's first joint anchor (world), the longest the chain can stretch from it to the
    wrist, and where the wrist sits in the tcp frame."""

    shoulder: np.ndarray
    length: float
    wrist_in_tcp: np.ndarray

    @classmethod
    def of(cls, ik: ArmIK) -> ReachBound:
        """The bound of the arm ``ik`` solves for (its kinematics at the home posture)."""
        data = ik.data
        data.qpos[:] = ik.full_q(np.asarray(ik.home, float))
        mujoco.mj_kinematics(ik.model, data)
        anchors = np.array([data.xanchor[ik.model.joint(PREFIX + j).id] for j in ARM_JOINTS])
        tcp = data.site_xpos[ik.site_id]
        tcp_rot = data.site_xmat[ik.site_id].reshape(3, 3)
        length = float(np.linalg.norm(np.diff(anchors, axis=0), axis=1).sum())
        shoulder = ik.base_rot @ anchors[0] + ik.base_pos
        return cls(shoulder, length, tcp_rot.T @ (anchors[-1] - tcp))

    def excess(self, pos: np.ndarray, rot: np.ndarray) -> float:
        """How far (m) the wrist of a tcp at world ``pos`` with rotation ``rot`` lies past the
        chain's longest stretch (<= 0: perhaps reachable, > 0: out of reach)."""
        wrist = np.asarray(pos, float) + np.asarray(rot, float) @ self.wrist_in_tcp
        return float(np.linalg.norm(wrist - self.shoulder)) - self.length
