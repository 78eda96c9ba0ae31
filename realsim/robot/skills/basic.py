"""The basic primitives: home posture, end-effector moves, opening and closing the gripper."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from realsim.robot.ik import quat_to_mat
from realsim.robot.model import GRIPPER_OPEN_CTRL, HOME_ARM
from realsim.robot.motion import Motion
from realsim.robot.result import ActionResult, PlanFailure

__all__ = ["BasicSkills"]


class BasicSkills(Motion):
    """go_home, move_ee_to, open_gripper, close_gripper."""

    def go_home(self, max_sim_time: float | None = None) -> ActionResult:
        """Back to the home posture (lifting first if the hand is low, around what is in the way)."""
        def body() -> ActionResult:
            pos, _ = self.tcp_pose()
            home_pos, _ = self.ik.fk(np.array(HOME_ARM))
            if pos[2] < home_pos[2] - self.params.arm.home_lift_margin:
                try:
                    self._straight(np.array([pos[0], pos[1], home_pos[2]]))
                except PlanFailure:
                    pass
            ignore = {self.held} if self.held else set()
            try:  # around what is in the way
                self._move_joints(np.array(HOME_ARM), ignore=ignore)
            except PlanFailure as exc:  # never a blind move: it would shove what is in the way
                pos, rot = self.tcp_pose()
                above = np.array([pos[0], pos[1], max(pos[2], self._tallest(self.held) + self.params.clearance)])
                again: PlanFailure | None = None
                for rot_up in (rot, self.ik.fk(np.array(HOME_ARM))[1]):  # from above everything (a checked straight rise), turning home if need be
                    try:
                        self._straight(above, rot_up, clear_but=ignore)
                        self._move_joints(np.array(HOME_ARM), ignore=ignore)
                        break
                    except PlanFailure as failure:
                        again = failure
                else:
                    return ActionResult("go_home", False, f"no clear way home ({exc}; from above: {again})")
            err = float(np.abs(self.data.qpos[self.qadr] - np.array(HOME_ARM)).max())
            ok = err < self.params.arm.home_tol
            return ActionResult("go_home", ok, "" if ok else f"joint error {err:.3f} rad", values={"joint_error": err})
        return self._run("go_home", body, max_sim_time)

    def move_ee_to(self, pos: ArrayLike, quat: ArrayLike | None = None, max_sim_time: float | None = None,
                   direct: bool = False) -> ActionResult:
        """Move the tcp to ``pos`` (world) with ``quat`` (w,x,y,z; None keeps the current orientation)."""
        goal = np.asarray(pos, float)

        def body() -> ActionResult:
            _, rot = self.tcp_pose()
            target_rot = rot if quat is None else quat_to_mat(np.asarray(quat, float))
            res = self._ik(goal, target_rot, self.data.ctrl[self.act].copy())
            if not res.converged:
                return ActionResult("move_ee_to", False, f"target unreachable: {res.reason}", values={"ik_pos_error": res.pos_error, "ik_rot_error": res.rot_error})
            if direct:
                self._straight(goal, target_rot)
            else:
                self._transit(goal, target_rot, skip=self.held, below_tcp=self._held_below())
            now, _ = self.tcp_pose()
            err = float(np.linalg.norm(now - goal))
            ok = err < self.params.track_tol
            return ActionResult("move_ee_to", ok, "" if ok else f"tcp ended {err * 1000:.1f} mm from the target", values={"pos_error": err, "ik_residual": res.pos_error, "manipulability": res.manipulability})
        return self._run("move_ee_to", body, max_sim_time)

    def open_gripper(self) -> ActionResult:
        """Open the gripper fully (whatever it held is let go)."""
        def body() -> ActionResult:
            self._gripper(GRIPPER_OPEN_CTRL)
            self.held = None
            w = self.gripper_opening()
            ok = w > self.params.arm.open_min
            return ActionResult("open_gripper", ok, "" if ok else f"opened only to {w * 1000:.0f} mm", values={"opening": w})
        return self._run("open_gripper", body)

    def close_gripper(self) -> ActionResult:
        """Close the fingers."""
        def body() -> ActionResult:
            self._gripper(0.0)
            return ActionResult("close_gripper", True, "", values={"opening": self.gripper_opening()})
        return self._run("close_gripper", body)
