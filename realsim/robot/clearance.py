"""Clearance: how near the arm at a posture comes to each object, in metres.

A kinematic check that only rejects penetration lets a planned path pass a hair from an object;
the arm then follows it a few millimetres off (tracking lag, the wrist's torque limit) and shoves
the object. :class:`ClearanceCheck` measures the gap instead, with MuJoCo's own collision
pipeline on a private copy of the scene model whose robot geoms (and the held object's) carry a
contact margin of ``reach``: every arm-object pair nearer than that yields a contact whose
``dist`` is the signed gap. The static scene (the table) is not measured here.
"""

from __future__ import annotations

import copy
from collections.abc import Iterable

import mujoco
import numpy as np

from realsim.robot.world import WORLD, SceneGeometry

__all__ = ["ClearanceCheck", "keeps", "required_gaps"]


class ClearanceCheck:
    """Gaps between the robot (and a carried object) and the other objects of ``model``."""

    def __init__(self, model: mujoco.MjModel, geometry: SceneGeometry, reach: float) -> None:
        self.geometry, self.reach = geometry, float(reach)
        self.model = copy.deepcopy(model)  # margins change contact generation: never on the live model
        self.data = mujoco.MjData(self.model)
        self.robot = set(geometry.robot_bodies)
        self._base_margin = self.model.geom_margin.copy()
        self._robot_geoms = np.array([g for g in range(self.model.ngeom) if int(self.model.geom_bodyid[g]) in self.robot], int)

    def gaps(self, qpos: np.ndarray, qadr: np.ndarray, q_arm: np.ndarray, ignore: Iterable[str] = (),
             carried: dict[str, tuple[np.ndarray, np.ndarray]] | None = None) -> dict[str, float]:
        """The least gap (m, negative when they overlap) from the robot at arm joints ``q_arm`` (the
        rest of the state ``qpos``), and from ``carried`` objects moved to a world (position,
        quaternion), to each other object within ``reach``; objects in ``ignore`` and the static
        scene are left out."""
        m, d = self.model, self.data
        d.qpos[:] = qpos
        d.qpos[qadr] = q_arm
        near = set(self.robot)
        m.geom_margin[:] = self._base_margin
        m.geom_margin[self._robot_geoms] = self.reach
        for name, (pos, quat) in (carried or {}).items():
            b = self.geometry.body(name)
            adr = m.jnt_qposadr[m.body_jntadr[b]]
            d.qpos[adr:adr + 3], d.qpos[adr + 3:adr + 7] = pos, quat
            parts = set(self.geometry.subtree(b))
            near |= parts
            m.geom_margin[np.isin(m.geom_bodyid, list(parts))] = self.reach
        mujoco.mj_kinematics(m, d)
        mujoco.mj_collision(m, d)
        skip = set(ignore) | set(carried or {}) | {WORLD}
        out: dict[str, float] = {}
        for i in range(d.ncon):
            c = d.contact[i]
            b1, b2 = int(m.geom_bodyid[c.geom1]), int(m.geom_bodyid[c.geom2])
            for rb, ob in ((b1, b2), (b2, b1)):
                if rb in near and ob not in near:
                    owner = self.geometry.owner(ob)
                    if owner not in skip:
                        out[owner] = min(out.get(owner, np.inf), float(c.dist))
        return out


def required_gaps(ends: Iterable[dict[str, float]], clearance: float) -> dict[str, float]:
    """The gap a path must keep to each object: ``clearance``, or less where one of its end
    postures (``ends``: their gaps) already comes nearer (a goal beside an object is reached)."""
    need: dict[str, float] = {}
    for gaps in ends:
        for owner, gap in gaps.items():
            need[owner] = min(need.get(owner, clearance), max(gap, 0.0))
    return need


def keeps(gaps: dict[str, float], need: dict[str, float], clearance: float) -> bool:
    """Whether every gap is at least what ``need`` asks (``clearance`` where it asks nothing)."""
    return all(gap >= need.get(owner, clearance) for owner, gap in gaps.items())
