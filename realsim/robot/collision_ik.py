"""Collision-aware IK: mink on the scene model itself, the arm kept clear of what it must not touch.

:class:`ArmIK` solves on a robot-only model and knows nothing of the scene. :class:`CollisionIK`
solves the same tcp task on the compiled scene (the robot where it stands, every object at the
state it is given), with every degree of freedom but the arm's frozen (mink ``DofFreezingTask``
as equality constraints) and mink's ``CollisionAvoidanceLimit`` between the arm's collision geoms
and the obstacles: the links keep ``clearance`` from every object except those ignored (the held
one), the hand and fingers too except from the objects they may touch (the one being pushed), and
the forearm and wrist (links 3 and beyond) from the static scene (the table). The limit bounds
how fast a link may approach an obstacle, so a solve warm-started from a clear posture stays clear.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import mink
import mujoco
import numpy as np

from realsim.robot.ik import IKParams, IKResult, rotation_angle
from realsim.robot.model import PREFIX
from realsim.robot.world import WORLD, SceneGeometry

__all__ = ["AvoidParams", "CollisionIK"]

Key = tuple[frozenset[str], frozenset[str]]


@dataclass(frozen=True)
class AvoidParams:
    """Distances and solver settings of :class:`CollisionIK`."""

    clearance: float = 0.015  # m kept between an arm geom and an obstacle
    detect: float = 0.05  # m at which an arm-obstacle pair starts to constrain the motion
    gain: float = 0.85  # fraction of the remaining gap a link may close per step
    max_iters: int = 300
    dt: float = 0.02  # s per differential-IK step
    posture_cost: float = 1e-2
    world_links_from: int = 3  # links from this index on keep clear of the static scene
    stall_window: int = 15  # iterations between progress checks
    stall_progress: float = 5e-4  # m (rotation weighted by ``rot_weight`` m/rad) the error must fall per window
    rot_weight: float = 0.1


class CollisionIK:
    """Collision-aware IK of the tcp site on the scene ``model`` (see module docstring).

    ``qadr``/``dadr``: the arm joints' qpos and dof addresses; ``hand_bodies``: the hand and
    fingers; ``geometry``: the scene's object geometry (who owns which body)."""

    def __init__(self, model: mujoco.MjModel, geometry: SceneGeometry, qadr: np.ndarray, dadr: np.ndarray, hand_bodies: Iterable[int],
                 home: np.ndarray, ik: IKParams = IKParams(), params: AvoidParams = AvoidParams()) -> None:
        self.model, self.geometry, self.params, self.ik_params = model, geometry, params, ik
        self.qadr, self.dadr, self.home = np.asarray(qadr), np.asarray(dadr), np.asarray(home, float)
        self.site = model.site(PREFIX + "tcp").id
        collidable = [g for g in range(model.ngeom) if model.geom_contype[g] or model.geom_conaffinity[g]]
        robot = geometry.robot_bodies
        hand = set(hand_bodies)
        self.hand_geoms = [g for g in collidable if model.geom_bodyid[g] in hand]
        self.link_geoms = [g for g in collidable if model.geom_bodyid[g] in robot and model.geom_bodyid[g] not in hand]
        far = {model.body(PREFIX + f"link{i}").id for i in range(params.world_links_from, 8)
               if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, PREFIX + f"link{i}") >= 0}
        self.far_geoms = [g for g in self.link_geoms if model.geom_bodyid[g] in far]
        self.owner_geoms: dict[str, list[int]] = {}
        for g in collidable:
            b = int(model.geom_bodyid[g])
            if b not in robot:
                self.owner_geoms.setdefault(geometry.owner(b), []).append(g)
        self.configuration = mink.Configuration(model)
        self.frame_task = mink.FrameTask(PREFIX + "tcp", "site", position_cost=1.0, orientation_cost=1.0, lm_damping=ik.lm_damping)
        cost = np.zeros(model.nv)
        cost[self.dadr] = params.posture_cost
        self.posture_task = mink.PostureTask(model, cost=cost)
        frozen = sorted(set(range(model.nv)) - set(int(d) for d in self.dadr))
        self.freeze = [mink.DofFreezingTask(model, dof_indices=frozen)] if frozen else []
        names = [model.joint(int(j)).name for j in range(model.njnt) if model.jnt_dofadr[j] in set(int(d) for d in self.dadr)]
        self.base_limits: list[mink.Limit] = [mink.ConfigurationLimit(model),
                                              mink.VelocityLimit(model, {n: ik.max_joint_speed for n in names})]
        self._avoid: dict[Key, mink.CollisionAvoidanceLimit | None] = {}

    def _limit(self, ignore: frozenset[str], hand_may_touch: frozenset[str]) -> mink.CollisionAvoidanceLimit | None:
        """The avoidance limit for one choice of ignored and hand-touchable objects (cached)."""
        key = (ignore, hand_may_touch)
        if key not in self._avoid:
            objects = [g for o, gs in self.owner_geoms.items() if o != WORLD and o not in ignore for g in gs]
            hand_objects = [g for o, gs in self.owner_geoms.items() if o != WORLD and o not in ignore | hand_may_touch for g in gs]
            pairs = [(self.link_geoms, objects), (self.hand_geoms, hand_objects), (self.far_geoms, self.owner_geoms.get(WORLD, []))]
            pairs = [(a, b) for a, b in pairs if a and b]
            p = self.params
            self._avoid[key] = mink.CollisionAvoidanceLimit(self.model, pairs, gain=p.gain, minimum_distance_from_collisions=p.clearance,
                                                            collision_detection_distance=p.detect) if pairs else None
        return self._avoid[key]

    def solve(self, qpos: np.ndarray, pos: np.ndarray, rot: np.ndarray, q_init: np.ndarray,
              ignore: Iterable[str] = (), hand_may_touch: Iterable[str] = ()) -> IKResult:
        """Arm joints putting the tcp at ``pos`` with rotation ``rot`` (world), starting from the arm
        at ``q_init`` with the rest of the scene at ``qpos`` (a full state: objects where they are
        or will be), moving no link into an obstacle on the way."""
        p, tol = self.params, self.ik_params
        pos = np.asarray(pos, float)
        self.frame_task.set_target(mink.SE3.from_rotation_and_translation(mink.SO3.from_matrix(rot), pos))
        q = np.asarray(qpos, float).copy()
        q[self.qadr] = q_init
        self.configuration.update(q)
        target = q.copy()
        target[self.qadr] = self.home
        self.posture_task.set_target(target)
        avoid = self._limit(frozenset(ignore), frozenset(hand_may_touch))
        limits = self.base_limits + ([avoid] if avoid is not None else [])
        tasks: list[mink.Task] = [self.frame_task, self.posture_task]
        it, pe, re, before = 0, np.inf, np.inf, np.inf
        try:
            for it in range(1, p.max_iters + 1):
                vel = mink.solve_ik(self.configuration, tasks, p.dt, tol.solver, damping=1e-6, limits=limits, constraints=self.freeze)
                self.configuration.integrate_inplace(vel, p.dt)
                pe, re = self._errors(pos, rot)
                if pe <= tol.pos_tol and re <= tol.rot_tol:
                    break
                if it % p.stall_window == 0:  # held against an obstacle: the error stops falling
                    err = pe + p.rot_weight * re
                    if err > before - p.stall_progress:
                        break
                    before = err
        except mink.NoSolutionFound:
            pass
        pe, re = self._errors(pos, rot)
        ok = pe <= tol.pos_tol and re <= tol.rot_tol
        reason = "" if ok else f"collision-free IK did not converge: residual {pe * 1000:.1f} mm / {np.degrees(re):.1f} deg"
        return IKResult(self.configuration.q[self.qadr].copy(), ok, pe, re, it, "mink-avoid", 0.0, reason)

    def _errors(self, pos: np.ndarray, rot: np.ndarray) -> tuple[float, float]:
        d = self.configuration.data
        return (float(np.linalg.norm(d.site_xpos[self.site] - pos)),
                rotation_angle(d.site_xmat[self.site].reshape(3, 3), rot))
