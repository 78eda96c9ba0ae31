"""The arm in a loaded scene: its handles, live readings, and stepping under a time budget.

:class:`Arm` is the base of every robot layer: it finds the Panda's joints, actuators and sites,
steps the physics (simulated time only, a diverged state stops with a message), tracks a joint
path with a quintic time scaling, drives the gripper, and runs a primitive within its
``max_sim_time`` budget (:meth:`Arm._run`), turning :class:`BudgetExceeded` and
:class:`PlanFailure` into a failed :class:`ActionResult`.
"""

from __future__ import annotations

from collections.abc import Callable

import mujoco
import numpy as np

from realsim.physics.divergence import check_state
from realsim.robot.ik import ArmIK, IKParams, quat_to_mat
from realsim.robot.model import ARM_ACTUATORS, ARM_JOINTS, FINGER_JOINTS, GRIPPER_ACTUATOR, GRIPPER_OPEN_CTRL, PREFIX
from realsim.robot.params import RobotParams
from realsim.robot.placing import ReleaseParams
from realsim.robot.result import ActionResult, BudgetExceeded, PlanFailure
from realsim.robot.world import SceneGeometry

__all__ = ["Arm"]

QUINTIC_PEAK = 1.875  # peak speed of the quintic time scaling, in units of the mean speed
QUINTIC_ACCEL = 5.7735  # its peak acceleration, in units of distance over duration squared


class Arm:
    """The Panda's handles in ``model``/``data``, its live pose, and stepping within a budget."""

    def __init__(self, model: mujoco.MjModel, data: mujoco.MjData, prefix: str = PREFIX, params: RobotParams = RobotParams(),
                 ik_params: IKParams = IKParams(), seed: int = 0, release: ReleaseParams = ReleaseParams()) -> None:
        self.model, self.data, self.prefix, self.params, self.seed = model, data, prefix, params, seed
        self.release = release
        try:
            self.base_id = model.body(prefix + "link0").id
        except KeyError as exc:
            raise ValueError(f"no robot with prefix '{prefix}' in the model (attach it with realsim.robot.attach_robot)") from exc
        self.jnt = [model.joint(prefix + j).id for j in ARM_JOINTS]
        self.qadr = np.array([model.jnt_qposadr[j] for j in self.jnt])
        self.dadr = np.array([model.jnt_dofadr[j] for j in self.jnt])
        self.finger_qadr = np.array([model.jnt_qposadr[model.joint(prefix + j).id] for j in FINGER_JOINTS])
        self.act = np.array([model.actuator(prefix + a).id for a in ARM_ACTUATORS])
        self.grip_act = model.actuator(prefix + GRIPPER_ACTUATOR).id
        self.tcp = model.site(prefix + "tcp").id
        self.finger_bodies = {model.body(prefix + "left_finger").id, model.body(prefix + "right_finger").id}
        self.hand_bodies = self.finger_bodies | {model.body(prefix + "hand").id}
        self.robot_bodies = {b for b in range(model.nbody) if model.body(b).name.startswith(prefix)}
        mujoco.mj_kinematics(model, data)
        self.base_pos = data.xpos[self.base_id].copy()
        self.base_quat = data.xquat[self.base_id].copy()
        base_rot = quat_to_mat(self.base_quat)
        self.base_yaw = float(np.arctan2(base_rot[1, 0], base_rot[0, 0]))  # direction words are relative to it
        self.ik = ArmIK(self.base_pos, self.base_quat, ik_params, scene=model)
        self.geometry = SceneGeometry(model, data, self.robot_bodies)
        self._deadline = np.inf
        self.held: str | None = None
        self.pinch: tuple[str, float] = ("", 0.0)  # kind and width of the pinch holding ``held``
        self.stood: dict[str, np.ndarray] = {}  # each grasped object's up axis (world) as it stood before the grasp
        self.step_hook: Callable[[mujoco.MjModel, mujoco.MjData], None] | None = None
        self.hook_every = 1  # physics steps between calls of ``step_hook`` (e.g. a video recorder)
        self._steps = 0
        self._scene_noslip = int(model.opt.noslip_iterations)  # the scene's own setting, restored when nothing is held
        if not np.any(data.ctrl[self.act]):  # a model reset without keyframe: hold the current posture
            data.ctrl[self.act] = data.qpos[self.qadr]
            data.ctrl[self.grip_act] = GRIPPER_OPEN_CTRL

    def tcp_pose(self) -> tuple[np.ndarray, np.ndarray]:
        """Live (position, rotation matrix) of the tool centre point."""
        mujoco.mj_kinematics(self.model, self.data)
        return self.data.site_xpos[self.tcp].copy(), self.data.site_xmat[self.tcp].reshape(3, 3).copy()

    def gripper_opening(self) -> float:
        """Distance between the fingers (m)."""
        return float(self.data.qpos[self.finger_qadr].sum())

    def _step(self) -> None:
        """One physics step; raises :class:`BudgetExceeded` past the deadline. While an object is
        held, MuJoCo's noslip post-processor keeps the pads' friction within its cone without the
        soft contacts' creep: a pinch below its friction limit holds still, as static friction does
        (without it a 178 g pitcher held by its handle turned 8 deg in 2 s at a third of its limit)."""
        if self.data.time > self._deadline:
            raise BudgetExceeded()
        self.model.opt.noslip_iterations = max(self.params.arm.hold_noslip, self._scene_noslip) if self.held else self._scene_noslip
        mujoco.mj_step(self.model, self.data)
        self._steps += 1
        if self._steps % self.params.arm.check_every == 0:  # a diverged simulation stops with a message, never a hang
            check_state(self.model, self.data, "robot motion")
        if self.step_hook is not None and self._steps % self.hook_every == 0:
            self.step_hook(self.model, self.data)

    def _wait(self, duration: float) -> None:
        """Step for ``duration`` s of simulated time."""
        end = self.data.time + duration
        while self.data.time < end:
            self._step()

    def _settle(self) -> None:
        """Step until the arm's joints rest (at most ``max_settle`` s)."""
        end = self.data.time + self.params.max_settle
        while self.data.time < end:
            self._step()
            if np.abs(self.data.qvel[self.dadr]).max() < self.params.settle_speed:
                break

    def _follow(self, path: list[np.ndarray], settle: bool = True) -> None:
        """Track a joint path (first point = current command) with a smooth time scaling."""
        q_cmd = self.data.ctrl[self.act].copy()
        pts = np.vstack([q_cmd] + list(path))
        seg = np.abs(np.diff(pts, axis=0)).max(axis=1)
        total = float(seg.sum())
        if total < 1e-6:
            return
        cum = np.concatenate([[0.0], np.cumsum(seg)])
        duration = max(QUINTIC_PEAK * total / self.params.max_joint_speed, self.params.min_segment_time, self._carry_time(pts))
        start = self.data.time
        while True:
            t = min((self.data.time - start) / duration, 1.0)
            s = (10 * t**3 - 15 * t**4 + 6 * t**5) * total
            i = min(int(np.searchsorted(cum, s, side="right") - 1), len(seg) - 1)
            f = 0.0 if seg[i] == 0 else (s - cum[i]) / seg[i]
            self.data.ctrl[self.act] = pts[i] + f * (pts[i + 1] - pts[i])
            if t >= 1.0:
                break
            self._step()
        if settle:
            self._settle()

    def _carry_time(self, pts: np.ndarray) -> float:
        """The shortest duration (s) of a trajectory through joint points ``pts`` that what the hand
        holds allows (0 here: nothing limits it; the grasp skill bounds the carry's acceleration)."""
        return 0.0

    def _follow_corners(self, corners: list[np.ndarray]) -> None:
        """Track a joint polyline through its ``corners`` (a planned transit): a quintic time scaling
        per segment, at rest at every corner, so the arm stays on the checked straight segments."""
        for q in corners:
            self._follow([q], settle=False)
        self._settle()

    def _gripper(self, ctrl: float) -> None:
        """Command the gripper to ``ctrl`` and step until the fingers stop (at most ``gripper_time``)."""
        self.data.ctrl[self.grip_act] = ctrl
        end = self.data.time + self.params.gripper_time
        finger_dof = self.model.jnt_dofadr[self.model.joint(self.prefix + FINGER_JOINTS[0]).id]
        while self.data.time < end:
            self._step()
            if self.data.time > end - self.params.gripper_time / 2 and np.abs(self.data.qvel[finger_dof]) < self.params.arm.finger_rest_speed:
                break

    def _run(self, name: str, fn: Callable[[], ActionResult], budget: float | None = None) -> ActionResult:
        """Run a primitive's body within ``budget`` s of simulated time (default ``max_sim_time``)."""
        start = self.data.time
        self._deadline = start + (budget if budget is not None else self.params.max_sim_time)
        try:
            res: ActionResult = fn()
        except BudgetExceeded:
            res = ActionResult(name, False, f"simulated-time budget of {budget or self.params.max_sim_time:.0f} s exceeded")
        except PlanFailure as exc:
            res = ActionResult(name, False, str(exc))
        finally:
            self._deadline = np.inf
        res.sim_time = self.data.time - start
        return res
