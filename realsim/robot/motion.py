"""Motion: IK waypoints along straight lines, transits that lift before they traverse, and the
kinematic collision checks every planned path passes before it runs."""

from __future__ import annotations

from collections.abc import Callable

import mujoco
import numpy as np

from realsim.robot.grasps import rotate_about
from realsim.robot.ik import IKResult, mat_to_quat
from realsim.robot.queries import WorldQueries
from realsim.robot.result import PlanFailure

__all__ = ["Motion"]


class Motion(WorldQueries):
    """Planning and following tcp paths; every plan raises :class:`PlanFailure` when it cannot be made."""

    def _ik(self, pos: np.ndarray, rot: np.ndarray, q_init: np.ndarray) -> IKResult:
        """IK for the tcp at (``pos``, rotation ``rot``) starting from ``q_init``."""
        return self.ik.solve(pos, mat_to_quat(rot), q_init=q_init)

    def _line(self, start: np.ndarray, end: np.ndarray, rot_start: np.ndarray, rot_end: np.ndarray, q_init: np.ndarray) -> list[np.ndarray]:
        """IK waypoints along a straight tcp line (orientation interpolated); raises PlanFailure."""
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
            res = self._ik(start + f * (end - start), r, q)
            if not res.converged:
                raise PlanFailure(f"target {np.round(start + f * (end - start), 3).tolist()} unreachable ({res.reason})")
            if np.abs(res.q - q).max() > self.params.motion.max_joint_jump:
                raise PlanFailure("the straight-line path needs a joint flip")
            path.append(res.q)
            q = res.q
        return path

    def _straight(self, end: np.ndarray, rot_end: np.ndarray | None = None) -> None:
        """Move the tcp in a straight line to ``end`` (``rot_end``: None keeps the orientation)."""
        _, rot = self.tcp_pose()
        rot_end = rot if rot_end is None else rot_end
        q = self.data.ctrl[self.act].copy()
        cmd_pos, cmd_rot = self.ik.fk(q)  # plan from the commanded pose, not the sagging one
        self._follow(self._line(cmd_pos, end, cmd_rot, rot_end, q))

    def _transit(self, end: np.ndarray, rot_end: np.ndarray, skip: str | None = None, below_tcp: float = 0.0, turn_late: bool = False) -> None:
        """Lift to a safe height, traverse, descend to ``end`` (straight lines, IK-checked).

        With ``turn_late`` (a sideways hand for a handle, out of reach up high) the hand may keep
        its orientation across and turn while descending, or swing across in joint space at height.
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

        plans: list[Callable[[float], list[np.ndarray]]] = [lambda z: across(z, rot_end)]
        if turn_late:
            plans += [lambda z: across(z, cmd_rot), swing]
        last: PlanFailure | None = None
        for plan in plans:
            for z in heights:
                try:
                    path = plan(z)
                    self._check_clear(path, ignore={skip} if skip else set())
                except PlanFailure as exc:
                    last = exc
                    continue
                self._follow(path)
                return
        raise last or PlanFailure("no safe path")

    def _check_clear(self, path: list[np.ndarray], ignore: set[str] | frozenset[str] = frozenset(), hand_may_touch: set[str] | frozenset[str] = frozenset(),
                     start: np.ndarray | None = None) -> None:
        """Raise PlanFailure when the arm would touch an object along ``path`` from ``start`` (default:
        the commanded joints), at waypoints and midpoints; the held object is carried, not hit."""
        rel = None
        held = self.held
        if held:  # the held object moves with the hand: checked against the others like a link
            b = self._body(held)
            tcp, rot = self.tcp_pose()
            rel = (rot.T @ (self.data.xpos[b] - tcp), rot.T @ self.data.xmat[b].reshape(3, 3))
        q_prev = self.data.ctrl[self.act].copy() if start is None else np.asarray(start, float)
        for q in path:
            for f in (0.5, 1.0):
                qf = q_prev + f * (q - q_prev)
                carried = None
                if held and rel is not None:
                    p_w, r_w = self.ik.fk(qf)
                    carried = {held: (r_w @ rel[0] + p_w, mat_to_quat(r_w @ rel[1]))}
                hits = self.geometry.robot_hits(self.qadr, qf, ignore, hand_may_touch, self.hand_bodies, carried=carried)
                if hits:
                    raise PlanFailure(f"the arm would touch {', '.join(sorted(hits))}")
            q_prev = q
