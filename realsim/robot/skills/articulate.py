"""Drawers, doors and lids: grasp the handle and follow the joint (a line for slides, an arc for hinges)."""

from __future__ import annotations

import mujoco
import numpy as np

from realsim.robot.grasps import frame_from, rotate_about
from realsim.robot.model import GRIPPER_OPEN_CTRL
from realsim.robot.motion import Motion
from realsim.robot.queries import box_centre_3d
from realsim.robot.result import ActionResult, PlanFailure

__all__ = ["ArticulationSkills"]


class ArticulationSkills(Motion):
    """open_drawer, close_drawer."""

    def open_drawer(self, obj: str, amount: float | None = None, max_sim_time: float | None = None) -> ActionResult:
        """Open a drawer (slide joint) or a door/lid (hinge joint) of body ``obj`` by its handle.

        The handle is a geom of the body whose name contains "handle" (else the body's collision
        geometry); the hand grasps it approaching against the opening direction and follows the
        joint's motion (a line for slides, an arc for hinges).
        """
        return self._run("open_drawer", lambda: self._articulate("open_drawer", obj, amount, opening=True), max_sim_time)

    def close_drawer(self, obj: str, max_sim_time: float | None = None) -> ActionResult:
        """Close a drawer or door of body ``obj``: grasp its handle and follow the joint back to its
        closed end (the lower limit, or 0 when the joint is unlimited)."""
        return self._run("close_drawer", lambda: self._articulate("close_drawer", obj, None, opening=False), max_sim_time)

    def _handle(self, b: int, pull: np.ndarray | None) -> np.ndarray:
        """Where to hold body ``b`` to move it: a site or geom named "...handle", else the middle of
        its face furthest along ``pull`` (else its origin)."""
        m = self.model
        for i in range(m.nsite):
            if m.site_bodyid[i] == b and "handle" in m.site(i).name:
                return np.array(self.data.site_xpos[i])
        for g in range(m.ngeom):
            if m.geom_bodyid[g] == b and "handle" in m.geom(g).name:
                return np.array(self.data.geom_xpos[g])
        if pull is None:
            return np.array(self.data.xpos[b])
        pts = self._world_points(b)
        along = pts @ pull
        return box_centre_3d(pts[along > along.max() - self.params.articulation.handle_face])

    def _articulate(self, name: str, obj: str, amount: float | None, opening: bool) -> ActionResult:
        """Grip ``obj``'s handle, move its joint to the open (by ``amount``) or closed end, let go, judge."""
        ap = self.params.articulation
        b = self._body(obj)
        jid = self.model.body_jntadr[b]
        if jid < 0 or int(self.model.jnt_type[jid]) not in (mujoco.mjtJoint.mjJNT_SLIDE, mujoco.mjtJoint.mjJNT_HINGE):
            return ActionResult(name, False, f"{obj} has no hinge or slide joint")
        slide = self.model.jnt_type[jid] == mujoco.mjtJoint.mjJNT_SLIDE
        qa = self.model.jnt_qposadr[jid]
        q0 = float(self.data.qpos[qa])
        if self.model.jnt_limited[jid]:
            lo, hi = (float(v) for v in self.model.jnt_range[jid])
        else:
            lo, hi = (q0, q0 + (ap.slide_open if slide else ap.hinge_open)) if opening else (0.0, q0)
        if opening:
            target = min(hi, q0 + (amount if amount is not None else (hi - q0)))
        else:
            target = lo
            if q0 - lo < ap.closed_tol:
                return ActionResult(name, True, "already closed", values={"closed_by": 0.0, "target": 0.0, "position": q0})
        axis = self.data.xaxis[jid].copy()
        anchor = self.data.xanchor[jid].copy()
        hpos = self._handle(b, axis / np.linalg.norm(axis) if slide else None)
        if slide:
            pull = axis / np.linalg.norm(axis)
        else:
            arm = hpos - anchor
            pull = np.cross(axis, arm)
            pull /= np.linalg.norm(pull)
        horiz = np.array([pull[0], pull[1], 0.0])
        horiz /= max(np.linalg.norm(horiz), 1e-9)
        up = np.array([0, 0, 1.0]) if abs(horiz[2]) < 0.9 else np.array([1.0, 0, 0])
        rot = self._grip_handle(hpos, horiz, up)
        path: list[np.ndarray] = []
        q = self.data.ctrl[self.act].copy()
        for k in range(1, ap.steps + 1):
            dq = (target - q0) * k / ap.steps
            if slide:
                p, r = hpos + pull * dq, rot
            else:
                rr = rotate_about(axis, dq)
                p, r = anchor + rr @ (hpos - anchor), rr @ rot
            res = self._ik(p, r, q)
            if not res.converged:
                break
            path.append(res.q)
            q = res.q
        self._follow(path)
        self._gripper(GRIPPER_OPEN_CTRL)
        pos, r = self.tcp_pose()
        try:
            self._straight(pos - r[:, 2] * ap.retreat)
        except PlanFailure:
            pass
        now = float(self.data.qpos[qa])
        if opening:
            opened = now - q0
            ok = opened >= ap.open_fraction * (target - q0)
            return ActionResult(name, ok, "" if ok else f"opened {opened:.3f} of {target - q0:.3f}", values={"opened": opened, "target": target - q0})
        closed = q0 - now
        ok = now - lo <= max(ap.close_tol, ap.close_fraction * (q0 - lo))
        return ActionResult(name, ok, "" if ok else f"still open by {now - lo:.3f} (closed {closed:.3f} of {q0 - lo:.3f})",
                            values={"closed_by": closed, "target": q0 - lo, "position": now})

    def _grip_handle(self, hpos: np.ndarray, horiz: np.ndarray, up: np.ndarray) -> np.ndarray:
        """Open, approach the handle at ``hpos`` against the pull ``horiz``, close; the hand's rotation."""
        self._gripper(GRIPPER_OPEN_CTRL)
        for k, closing in enumerate((up, -up)):  # the hand is symmetric: either wrist roll may be the reachable one
            rot = frame_from(-horiz, closing)
            try:
                self._transit(hpos + horiz * self.params.pregrasp, rot, turn_late=True)
                self._straight(hpos, rot)
                break
            except PlanFailure:
                if k == 1:
                    raise
        self._gripper(0.0)
        return rot
