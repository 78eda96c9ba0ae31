"""Inverse kinematics of the Panda's tool-centre site.

mink differential IK (a FrameTask on the tcp site, a PostureTask toward the home posture,
ConfigurationLimit and VelocityLimit, QP solver ``daqp``) with a damped-least-squares fallback
and an optional wrist pin (joint 7 held at an angle). IK runs on a robot-only model at the world
origin; targets are mapped into the robot's base frame, so one model serves every base pose.
Given a loaded scene, that model (and the home posture) is copied out of the scene itself, so a
scene runs without the Menagerie; without one (while converting) it is the Menagerie Panda.
A solution is reported as converged only when its residual is within tolerance.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import mink
import mujoco
import numpy as np

from realsim.robot.model import ARM_JOINTS, HOME_ARM, PREFIX, describe_robot, robot_kinematics, robot_only_model


@dataclass(frozen=True)
class IKParams:
    """Tolerances and solver settings of :class:`ArmIK`."""

    pos_tol: float = 0.002  # m
    rot_tol: float = 0.02  # rad
    max_iters: int = 250
    dt: float = 0.02  # s per differential-IK step
    solver: str = "daqp"
    posture_cost: float = 1e-2
    pin_cost: float = 100.0
    pin_tol: float = 0.01  # rad
    lm_damping: float = 1e-3
    max_joint_speed: float = 3.0  # rad/s, VelocityLimit of every arm joint
    dls_damping: float = 0.03
    dls_iters: int = 300


@dataclass
class IKResult:
    """An IK answer: the arm joints and how well they reach the target."""

    q: np.ndarray  # (7,) arm joint angles
    converged: bool
    pos_error: float  # m
    rot_error: float  # rad (0 when only position was asked)
    iterations: int
    method: str  # "mink" | "dls" | "none"
    manipulability: float  # sqrt(det(J J^T)) of the 6x7 tcp Jacobian at q
    reason: str = ""


@functools.lru_cache(maxsize=1)
def _origin_model() -> mujoco.MjModel:
    return robot_only_model(np.zeros(3), np.array([1.0, 0.0, 0.0, 0.0]))


def quat_to_mat(quat: np.ndarray) -> np.ndarray:
    """The 3x3 rotation matrix of a unit quaternion (w, x, y, z)."""
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, np.asarray(quat, float))
    return mat.reshape(3, 3)


def mat_to_quat(mat: np.ndarray) -> np.ndarray:
    """The unit quaternion (w, x, y, z) of a 3x3 rotation matrix."""
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.asarray(mat, float).reshape(9))
    return quat


def rotation_angle(r_a: np.ndarray, r_b: np.ndarray) -> float:
    """Angle (rad) of the rotation between two rotation matrices."""
    c = (np.trace(r_a.T @ r_b) - 1.0) / 2.0
    return float(np.arccos(np.clip(c, -1.0, 1.0)))


class ArmIK:
    """IK of the tcp site for a Panda whose base stands at ``base_pos`` / ``base_quat`` (world);
    ``scene``: the compiled scene the robot stands in (its kinematics and home posture are used)."""

    def __init__(self, base_pos: np.ndarray, base_quat: np.ndarray, params: IKParams = IKParams(),
                 scene: mujoco.MjModel | None = None):
        self.params = params
        self.model = _origin_model() if scene is None else robot_kinematics(scene, PREFIX + "link0")
        self.data = mujoco.MjData(self.model)
        self.place(base_pos, base_quat)
        self.site_id = self.model.site(PREFIX + "tcp").id
        self.qadr = np.array([self.model.jnt_qposadr[self.model.joint(PREFIX + j).id] for j in ARM_JOINTS])
        self.dadr = np.array([self.model.jnt_dofadr[self.model.joint(PREFIX + j).id] for j in ARM_JOINTS])
        self.lower = self.model.jnt_range[[self.model.joint(PREFIX + j).id for j in ARM_JOINTS], 0]
        self.upper = self.model.jnt_range[[self.model.joint(PREFIX + j).id for j in ARM_JOINTS], 1]
        self.home = np.array(HOME_ARM if scene is None else describe_robot(scene, {"home_arm": HOME_ARM}).home_arm)
        self.configuration = mink.Configuration(self.model)
        self.frame_task = mink.FrameTask(PREFIX + "tcp", "site", position_cost=1.0, orientation_cost=1.0, lm_damping=params.lm_damping)
        self.posture_task = mink.PostureTask(self.model, cost=params.posture_cost)
        self.pin_task = mink.PostureTask(self.model, cost=np.zeros(self.model.nv))
        self.limits = [
            mink.ConfigurationLimit(self.model),
            mink.VelocityLimit(self.model, {PREFIX + j: params.max_joint_speed for j in ARM_JOINTS}),
        ]

    # --- frames -------------------------------------------------------------------------------
    def place(self, base_pos: np.ndarray, base_quat: np.ndarray) -> None:
        """Stand the base at ``base_pos`` / ``base_quat`` (world): the same solver for another base
        pose (every solve starts from its own initial configuration, nothing carries over)."""
        self.base_pos = np.asarray(base_pos, float)
        self.base_rot = quat_to_mat(base_quat)

    def to_base(self, pos: np.ndarray, rot: np.ndarray | None) -> tuple[np.ndarray, np.ndarray | None]:
        p = self.base_rot.T @ (np.asarray(pos, float) - self.base_pos)
        return p, None if rot is None else self.base_rot.T @ rot

    def full_q(self, q_arm: np.ndarray) -> np.ndarray:
        q = self.model.qpos0.copy()
        q[self.qadr] = q_arm
        q[self.model.jnt_qposadr[self.model.joint(PREFIX + "finger_joint1").id]] = 0.04
        q[self.model.jnt_qposadr[self.model.joint(PREFIX + "finger_joint2").id]] = 0.04
        return q

    def fk(self, q_arm: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """World position and rotation matrix of the tcp at arm joints ``q_arm``."""
        self.data.qpos[:] = self.full_q(q_arm)
        mujoco.mj_kinematics(self.model, self.data)
        p = self.data.site_xpos[self.site_id].copy()
        r = self.data.site_xmat[self.site_id].reshape(3, 3).copy()
        return self.base_rot @ p + self.base_pos, self.base_rot @ r

    def manipulability(self, q_arm: np.ndarray) -> float:
        self.data.qpos[:] = self.full_q(q_arm)
        mujoco.mj_kinematics(self.model, self.data)
        mujoco.mj_comPos(self.model, self.data)
        jp = np.zeros((3, self.model.nv))
        jr = np.zeros((3, self.model.nv))
        mujoco.mj_jacSite(self.model, self.data, jp, jr, self.site_id)
        jac = np.vstack([jp, jr])[:, self.dadr]
        return float(np.sqrt(max(np.linalg.det(jac @ jac.T), 0.0)))

    def _errors(self, q_arm: np.ndarray, pos: np.ndarray, rot: np.ndarray | None) -> tuple[float, float]:
        p, r = self.fk(q_arm)
        return float(np.linalg.norm(p - pos)), 0.0 if rot is None else rotation_angle(r, rot)

    def _ok(self, pe: float, re: float, q: np.ndarray | None = None, wrist_pin: float | None = None) -> bool:
        pinned = wrist_pin is None or q is None or abs(q[6] - wrist_pin) <= self.params.pin_tol
        return pe <= self.params.pos_tol and re <= self.params.rot_tol and pinned

    # --- solvers ------------------------------------------------------------------------------
    def solve(self, pos: np.ndarray, quat: np.ndarray | None = None, q_init: np.ndarray | None = None, wrist_pin: float | None = None) -> IKResult:
        """Arm joints putting the tcp at ``pos`` (world) with orientation ``quat`` (w,x,y,z; None: any).

        mink first, then damped least squares from the same start and from home; the best
        answer is returned, ``converged`` only if within ``pos_tol`` / ``rot_tol``.
        """
        pos = np.asarray(pos, float)
        rot = None if quat is None else quat_to_mat(quat)
        starts = [np.asarray(q_init, float) if q_init is not None else self.home.copy()]
        if q_init is not None:
            starts.append(self.home.copy())
        best: IKResult | None = None
        for start in starts:
            for method in (self._solve_mink, self._solve_dls):
                res = method(pos, rot, start, wrist_pin)
                if best is None or (res.converged and not best.converged) or (res.converged == best.converged and res.pos_error + 0.1 * res.rot_error < best.pos_error + 0.1 * best.rot_error):
                    best = res
                if best.converged:
                    break
            if best.converged:
                break
        assert best is not None
        best.manipulability = self.manipulability(best.q)
        if not best.converged:
            best.reason = f"IK did not converge: residual {best.pos_error * 1000:.1f} mm / {np.degrees(best.rot_error):.1f} deg (tolerance {self.params.pos_tol * 1000:.1f} mm / {np.degrees(self.params.rot_tol):.1f} deg)"
        return best

    def _solve_mink(self, pos: np.ndarray, rot: np.ndarray | None, start: np.ndarray, wrist_pin: float | None) -> IKResult:
        p = self.params
        tpos, trot = self.to_base(pos, rot)
        target = mink.SE3.from_rotation_and_translation(mink.SO3.from_matrix(trot if trot is not None else np.eye(3)), tpos)
        self.frame_task.set_orientation_cost(1.0 if rot is not None else 0.0)
        self.frame_task.set_target(target)
        start = np.clip(start, self.lower, self.upper)
        if wrist_pin is not None:
            start = start.copy()
            start[6] = np.clip(wrist_pin, self.lower[6], self.upper[6])
        self.configuration.update(self.full_q(start))
        self.posture_task.set_target(self.full_q(self.home))
        tasks: list = [self.frame_task, self.posture_task]
        if wrist_pin is not None:
            cost = np.zeros(self.model.nv)
            cost[self.dadr[6]] = p.pin_cost
            self.pin_task.set_cost(cost)
            pin_q = self.full_q(start)
            pin_q[self.qadr[6]] = wrist_pin
            self.pin_task.set_target(pin_q)
            tasks.append(self.pin_task)
        it = 0
        pe = re = np.inf
        try:
            for it in range(1, p.max_iters + 1):
                vel = mink.solve_ik(self.configuration, tasks, p.dt, p.solver, damping=1e-6, limits=self.limits)
                self.configuration.integrate_inplace(vel, p.dt)
                if it % 5 == 0:
                    pe, re = self._errors(self.configuration.q[self.qadr], pos, rot)
                    if self._ok(pe, re, self.configuration.q[self.qadr], wrist_pin):
                        break
        except mink.NoSolutionFound:
            pass
        q = self.configuration.q[self.qadr].copy()
        pe, re = self._errors(q, pos, rot)
        return IKResult(q, self._ok(pe, re, q, wrist_pin), pe, re, it, "mink", 0.0)

    def _solve_dls(self, pos: np.ndarray, rot: np.ndarray | None, start: np.ndarray, wrist_pin: float | None) -> IKResult:
        p = self.params
        q = np.clip(np.asarray(start, float).copy(), self.lower, self.upper)
        jp = np.zeros((3, self.model.nv))
        jr = np.zeros((3, self.model.nv))
        it = 0
        for it in range(1, p.dls_iters + 1):
            self.data.qpos[:] = self.full_q(q)
            mujoco.mj_kinematics(self.model, self.data)
            mujoco.mj_comPos(self.model, self.data)
            cur_p, cur_r = self.fk(q)
            err = [pos - cur_p]
            mujoco.mj_jacSite(self.model, self.data, jp, jr, self.site_id)
            jacs = [self.base_rot @ jp[:, self.dadr]]
            if rot is not None:
                err_r = rot @ cur_r.T
                quat = mat_to_quat(err_r)
                vel = np.zeros(3)
                mujoco.mju_quat2Vel(vel, quat, 1.0)
                err.append(vel)
                jacs.append(self.base_rot @ jr[:, self.dadr])
            e = np.concatenate(err)
            jac = np.vstack(jacs)
            if wrist_pin is not None:
                row = np.zeros((1, 7))
                row[0, 6] = 1.0
                jac = np.vstack([jac, row])
                e = np.append(e, wrist_pin - q[6])
            lam = p.dls_damping
            dq = jac.T @ np.linalg.solve(jac @ jac.T + lam**2 * np.eye(len(e)), e)
            step = np.linalg.norm(dq)
            if step > 0.3:
                dq *= 0.3 / step
            q = np.clip(q + dq, self.lower, self.upper)
            if np.linalg.norm(e[:3]) < p.pos_tol * 0.5 and (rot is None or np.linalg.norm(e[3:6]) < p.rot_tol * 0.5) and (wrist_pin is None or abs(e[-1]) < p.pin_tol / 2):
                break
        pe, re = self._errors(q, pos, rot)
        return IKResult(q, self._ok(pe, re, q, wrist_pin), pe, re, it, "dls", 0.0)
