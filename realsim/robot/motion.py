"""Motion: IK waypoints along straight lines, transits that lift before they traverse (or, when
those are blocked, a sampling-based plan in joint space, :mod:`realsim.robot.transit`), and the
kinematic collision checks every planned path passes before it runs. Where a plain IK posture
would touch an object, the collision-aware IK (:mod:`realsim.robot.collision_ik`) looks for one
that does not."""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterable

import mujoco
import numpy as np

from realsim.robot.clearance import ClearanceCheck, keeps, required_gaps
from realsim.robot.collision_ik import CollisionIK
from realsim.robot.grasps import rotate_about
from realsim.robot.ik import IKResult, mat_to_quat
from realsim.robot.queries import WorldQueries
from realsim.robot.result import PlanFailure
from realsim.robot.transit import TransitParams, plan_joint_path

__all__ = ["Motion", "PathBlocked", "Solve"]

Solve = Callable[[np.ndarray, np.ndarray, np.ndarray], IKResult]  # IK of a tcp (position, rotation) from arm joints


class PathBlocked(PlanFailure):
    """A planned path would touch an object (the arm could reach, but not this way)."""


class Motion(WorldQueries):
    """Planning and following tcp paths; every plan raises :class:`PlanFailure` when it cannot be made."""

    transit_params = TransitParams()

    def _ik(self, pos: np.ndarray, rot: np.ndarray, q_init: np.ndarray) -> IKResult:
        """IK for the tcp at (``pos``, rotation ``rot``) starting from ``q_init``."""
        return self.ik.solve(pos, mat_to_quat(rot), q_init=q_init)

    @functools.cached_property
    def avoid_ik(self) -> CollisionIK:
        """The collision-aware IK on this scene (built on first use)."""
        return CollisionIK(self.model, self.geometry, self.qadr, self.dadr, self.hand_bodies, self.ik.home, self.ik.params)

    def _shifted_state(self, shifted: dict[str, np.ndarray] | None) -> np.ndarray:
        """The live qpos with objects displaced by xyz offsets (where a pushed object will be)."""
        qpos: np.ndarray = self.data.qpos.copy()
        for name, offset in (shifted or {}).items():
            adr = self.model.jnt_qposadr[self.model.body_jntadr[self._body(name)]]
            qpos[adr:adr + 3] += offset
        return qpos

    def _ik_clear(self, pos: np.ndarray, rot: np.ndarray, q_init: np.ndarray, ignore: Iterable[str] = (),
                  hand_may_touch: Iterable[str] = (), shifted: dict[str, np.ndarray] | None = None) -> IKResult:
        """IK whose posture touches no object it must not: the plain answer when it is clear, else the
        collision-aware one from ``q_init``; the plain one when neither is clear."""
        res = self._ik(pos, rot, q_init)
        hits = self.geometry.robot_hits
        if res.converged and not hits(self.qadr, res.q, ignore, hand_may_touch, self.hand_bodies, shifted):
            return res
        qpos = self._shifted_state(shifted)
        alt = self.avoid_ik.solve(qpos, pos, rot, q_init, ignore, hand_may_touch)
        if alt.converged and not hits(self.qadr, alt.q, ignore, hand_may_touch, self.hand_bodies, shifted):
            alt.manipulability = self.ik.manipulability(alt.q)
            return alt
        return res

    def _line(self, start: np.ndarray, end: np.ndarray, rot_start: np.ndarray, rot_end: np.ndarray, q_init: np.ndarray,
              solve: Solve | None = None) -> list[np.ndarray]:
        """IK waypoints along a straight tcp line (orientation interpolated; ``solve``: the IK, default
        the plain one); raises PlanFailure."""
        solve = solve or self._ik
        n = max(1, int(np.ceil(np.linalg.norm(end - start) / self.params.cart_step)))
        rel = rot_start.T @ rot_end
        quat = mat_to_quat(rel)
        axis_angle = np.zeros(3)
        mujoco.mju_quat2Vel(axis_angle, quat, 1.0)
        path, q = [], q_init
        for k in range(1, n + 1):
            f = k / n
            ang = float(np.linalg.norm(axis_angle))
            r = rot_start @ (rotate_about(axis_angle, f * ang) if ang > 1e-9 else np.eye(3))
            res = solve(start + f * (end - start), r, q)
            if not res.converged:
                raise PlanFailure(f"target {np.round(start + f * (end - start), 3).tolist()} unreachable ({res.reason})")
            if np.abs(res.q - q).max() > self.params.motion.max_joint_jump:
                raise PlanFailure("the straight-line path needs a joint flip")
            path.append(res.q)
            q = res.q
        return path

    def _straight(self, end: np.ndarray, rot_end: np.ndarray | None = None, clear_but: Iterable[str] | None = None) -> None:
        """Move the tcp in a straight line to ``end`` (``rot_end``: None keeps the orientation). With
        ``clear_but`` the arm and the held object keep off every object but those named (postures
        from the collision-aware IK where needed, the path checked), or PathBlocked is raised."""
        _, rot = self.tcp_pose()
        rot_end = rot if rot_end is None else rot_end
        q = self.data.ctrl[self.act].copy()
        cmd_pos, cmd_rot = self.ik.fk(q)  # plan from the commanded pose, not the sagging one
        if clear_but is None:
            self._follow(self._line(cmd_pos, end, cmd_rot, rot_end, q))
            return
        ignore = set(clear_but)
        path = self._line(cmd_pos, end, cmd_rot, rot_end, q, solve=lambda p, r, qi: self._ik_clear(p, r, qi, ignore))
        self._check_clear(path, ignore=ignore)
        self._follow(path)

    def _checked_line(self, start: np.ndarray, end: np.ndarray, rot: np.ndarray, q_seed: np.ndarray,
                      ignore: set[str]) -> tuple[np.ndarray, list[np.ndarray]]:
        """(posture at ``start``, joint path to ``end``) of a straight tcp line at rotation ``rot`` on
        which the arm and the held object touch nothing but ``ignore``, planned and checked before
        the arm moves (``q_seed``: the IK branch to start from); raises PlanFailure."""
        at_start = self._ik_clear(start, rot, q_seed, ignore)
        if not at_start.converged:
            raise PlanFailure(f"target {np.round(start, 3).tolist()} unreachable ({at_start.reason})")
        path = self._line(start, end, rot, rot, at_start.q, solve=lambda p, r, qi: self._ik_clear(p, r, qi, ignore))
        self._check_clear(path, ignore=ignore, start=at_start.q)
        return at_start.q, path

    def _transit(self, end: np.ndarray, rot_end: np.ndarray, skip: str | None = None, below_tcp: float = 0.0, turn_late: bool = False,
                 q_goal: np.ndarray | None = None) -> None:
        """Lift to a safe height, traverse, descend to ``end`` (straight lines, IK-checked); when such
        paths are blocked, or fail on the way to a given goal posture, a sampling-based plan in joint
        space (:meth:`_plan_transit`).

        With ``turn_late`` (a sideways hand for a handle, out of reach up high) the hand may keep
        its orientation across and turn while descending, or swing across in joint space at height.
        ``q_goal``: the arm posture to end in (one already checked for what follows), unless the
        straight lines end within ``goal_posture_tol`` of it.
        """
        mp = self.params.motion
        q0 = self.data.ctrl[self.act].copy()
        cmd_pos, cmd_rot = self.ik.fk(q0)
        low = max(self._tallest(skip) + mp.transit_low + below_tcp, end[2])
        safe = max(self._tallest(skip) + self.params.clearance + below_tcp, end[2])
        heights = sorted({safe, low, *(max(safe - drop, low) for drop in mp.transit_drops)}, reverse=True)

        def rise(z: float) -> tuple[np.ndarray, list[np.ndarray]]:
            up = np.array([cmd_pos[0], cmd_pos[1], z])
            return up, self._line(cmd_pos, up, cmd_rot, cmd_rot, q0)

        def across(z: float, rot_over: np.ndarray) -> list[np.ndarray]:
            """Straight lines up, across (turning to ``rot_over``) and down (turning to ``rot_end``)."""
            up, p1 = rise(z)
            over = np.array([end[0], end[1], z])
            p2 = self._line(up, over, cmd_rot, rot_over, p1[-1] if p1 else q0)
            return p1 + p2 + self._line(over, end, rot_over, rot_end, p2[-1])

        def swing(z: float) -> list[np.ndarray]:
            """Up in a line, across in joint space at height, down along the goal's own IK branch."""
            up, p1 = rise(z)
            q_up = p1[-1] if p1 else q0
            at_end = self._ik(end, rot_end, q_up)
            if not at_end.converged:
                raise PlanFailure(f"target {np.round(end, 3).tolist()} unreachable ({at_end.reason})")
            rising = self._line(end, np.array([end[0], end[1], z]), rot_end, rot_end, at_end.q)
            across_q = [q_up + f * (rising[-1] - q_up) for f in np.linspace(1 / mp.swing_steps, 1.0, mp.swing_steps)]
            if min(float(self.ik.fk(q)[0][2]) for q in across_q) < low - mp.swing_dip:
                raise PlanFailure("the swing across dips below the safe height")
            return p1 + across_q + [*rising[::-1][1:], at_end.q]

        def slant(z: float) -> list[np.ndarray]:
            """Up and across in one straight line, then down: at the edge of the reach, where the
            hand cannot rise straight up."""
            over = np.array([end[0], end[1], z])
            p1 = self._line(cmd_pos, over, cmd_rot, rot_end, q0)
            return p1 + self._line(over, end, rot_end, rot_end, p1[-1])

        plans: list[Callable[[float], list[np.ndarray]]] = [lambda z: across(z, rot_end)]
        if turn_late:
            plans += [lambda z: across(z, cmd_rot), swing]
        plans.append(slant)
        last: PlanFailure | None = None
        blocked: PathBlocked | None = None
        ignore = {skip} if skip else set()
        for plan in plans:
            for z in heights:
                try:
                    path = plan(z)
                    if q_goal is not None and np.abs(path[-1] - q_goal).max() > mp.goal_posture_tol:
                        q_end, q_to = path[-1], np.asarray(q_goal, float)  # into the vetted posture (another IK branch): one move, checked every joint_check_step
                        n = max(1, int(np.ceil(np.abs(q_to - q_end).max() / mp.joint_check_step)))
                        self._check_clear([q_end + f * (q_to - q_end) for f in np.linspace(1 / n, 1.0, n)], ignore=ignore, start=q_end)
                        path.append(q_to)
                    self._check_clear(path, ignore=ignore)
                except PathBlocked as exc:
                    last = blocked = exc
                    continue
                except PlanFailure as exc:
                    last = exc
                    continue
                self._follow(path)
                return
        if blocked is None and q_goal is None:  # no posture to aim at, and the lines failed on reach, not on what is in the way
            raise last or PlanFailure("no safe path")
        try:
            self._plan_transit(end, rot_end, ignore, q_goal)
        except PlanFailure as exc:
            raise PlanFailure(f"{blocked or last}; {exc}") from None

    def _move_joints(self, q_goal: np.ndarray, ignore: set[str] | frozenset[str] = frozenset()) -> None:
        """Straight to arm joints ``q_goal`` in joint space when that is clear (checked every
        ``joint_check_step``), else along a planned path; raises PlanFailure when neither is."""
        q0, q_goal = self.data.ctrl[self.act].copy(), np.asarray(q_goal, float)
        n = max(1, int(np.ceil(np.abs(q_goal - q0).max() / self.params.motion.joint_check_step)))
        try:
            self._check_clear([q0 + f * (q_goal - q0) for f in np.linspace(1 / n, 1.0, n)], ignore=ignore)
        except PathBlocked:
            self._follow_corners(self._planned(q0, q_goal, ignore))
            return
        self._follow([q_goal])

    @functools.cached_property
    def gap_check(self) -> ClearanceCheck:
        """Gaps between the arm and the objects (built on first use)."""
        return ClearanceCheck(self.model, self.geometry, self.transit_params.clearance)

    def _planned(self, q0: np.ndarray, q_goal: np.ndarray, ignore: set[str] | frozenset[str]) -> list[np.ndarray]:
        """Corners of a sampling-based joint path on which no link, nor the held object, touches an
        object (``ignore`` aside), the forearm and wrist stay off the table, and the arm keeps
        ``transit_params.clearance`` from every object (less only where an end posture is nearer):
        the arm follows a path a few millimetres off, and a path that grazes an object shoves it."""
        carry, clear = self._carry(), self.transit_params.clearance

        def gaps(q: np.ndarray) -> dict[str, float]:
            return self.gap_check.gaps(self.data.qpos, self.qadr, q, ignore, self._carried(q, carry))
        need = required_gaps([gaps(q0), gaps(q_goal)], clear)
        return plan_joint_path(q0, q_goal, self.ik.lower, self.ik.upper,
                               lambda q: not self._touches(q, ignore, carry=carry, world=True) and keeps(gaps(q), need, clear),
                               seed=self.seed, params=self.transit_params)

    @functools.cached_property
    def _far_links(self) -> set[int]:
        """The arm's bodies from link 3 on: they never need to touch the table."""
        names = [self.prefix + f"link{i}" for i in range(3, 8)]
        return {self.model.body(n).id for n in names if mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, n) >= 0}

    def _plan_transit(self, end: np.ndarray, rot_end: np.ndarray, ignore: set[str], q_goal: np.ndarray | None = None) -> None:
        """Move to the tcp pose (``end``, ``rot_end``) along a planned joint path (:meth:`_planned`)
        to ``q_goal`` (default: a clear IK posture); raises PlanFailure."""
        q0 = self.data.ctrl[self.act].copy()
        if q_goal is None:
            goal = self._ik_clear(end, rot_end, q0, ignore)
            if not goal.converged:
                raise PlanFailure(f"target {np.round(end, 3).tolist()} unreachable ({goal.reason})")
            q_goal = goal.q
        self._follow_corners(self._planned(q0, q_goal, ignore))

    def _carry(self) -> tuple[np.ndarray, np.ndarray] | None:
        """The held object's pose in the tcp frame (position, rotation), None when nothing is held."""
        if not self.held:
            return None
        b = self._body(self.held)
        tcp, rot = self.tcp_pose()
        return rot.T @ (self.data.xpos[b] - tcp), rot.T @ self.data.xmat[b].reshape(3, 3)

    def _touches(self, q: np.ndarray, ignore: Iterable[str] = (), hand_may_touch: Iterable[str] = (),
                 carry: tuple[np.ndarray, np.ndarray] | None = None, world: bool = False) -> set[str]:
        """What the arm at joints ``q`` (carrying the held object at ``carry``) would touch; with
        ``world`` the forearm and wrist touching the table count too."""
        return self.geometry.robot_hits(self.qadr, q, ignore, hand_may_touch, self.hand_bodies, carried=self._carried(q, carry),
                                        world_bodies=self._far_links if world else ())

    def _carried(self, q: np.ndarray, carry: tuple[np.ndarray, np.ndarray] | None) -> dict[str, tuple[np.ndarray, np.ndarray]] | None:
        """The held object's world (position, quaternion) with the arm at joints ``q`` (``carry``: its
        pose in the tcp frame), as the collision checks take it; None when nothing is held."""
        if not self.held or carry is None:
            return None
        p_w, r_w = self.ik.fk(q)
        return {self.held: (r_w @ carry[0] + p_w, mat_to_quat(r_w @ carry[1]))}

    def _check_clear(self, path: list[np.ndarray], ignore: set[str] | frozenset[str] = frozenset(), hand_may_touch: set[str] | frozenset[str] = frozenset(),
                     start: np.ndarray | None = None) -> None:
        """Raise PlanFailure when the arm would touch an object along ``path`` from ``start`` (default:
        the commanded joints), at waypoints and midpoints; the held object is carried, not hit."""
        carry = self._carry()
        q_prev = self.data.ctrl[self.act].copy() if start is None else np.asarray(start, float)
        for q in path:
            for f in (0.5, 1.0):
                hits = self._touches(q_prev + f * (q - q_prev), ignore, hand_may_touch, carry)
                if hits:
                    raise PathBlocked(f"the arm would touch {', '.join(sorted(hits))}")
            q_prev = q
