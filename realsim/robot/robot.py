"""Motion primitives of the Panda over a loaded realsim scene.

Every primitive steps the physics (simulated time only) with the position-controlled actuators
following an interpolated joint trajectory, within a ``max_sim_time`` budget, and returns an
:class:`ActionResult` whose ``success`` is measured in the simulation (contacts, poses), never
assumed. Motions lift before they traverse: transits go up to a safe height above everything,
across, and down; approaches are straight lines along the grasp axis. Every transit is checked
against the scene's objects before it runs (a kinematic MuJoCo collision check on a scratch
state), pushes too (only the hand may touch what it pushes, which is carried along), and a push
that would shove the object into another is refused. Places try spots within the target's free
area, hand yaws and heights, keep the object's footprint and the opening fingers clear of other
objects, and judge the end state with the same relations as the goal checks
(:mod:`realsim.planner.relations`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np
from scipy.spatial import cKDTree

from realsim.physics.divergence import check_state
from realsim.planner import relations
from realsim.planner.goals import DIRECTIONS, SIDES, direction_in_world
from realsim.robot.grasps import (
    MAX_WIDTH,
    GraspCandidate,
    frame_from,
    grasp_candidates,
    narrowest_width,
    rotate_about,
    twist_check,
)
from realsim.robot.ik import ArmIK, IKParams, IKResult, mat_to_quat, quat_to_mat
from realsim.robot.model import ARM_ACTUATORS, ARM_JOINTS, FINGER_JOINTS, GRIPPER_ACTUATOR, GRIPPER_OPEN_CTRL, HOME_ARM, PREFIX
from realsim.robot.optimizer import EpsilonGreedy, GraspParams
from realsim.robot.placing import ReleaseParams, cavity_centre, footprint_radius, release_poses, spots, top_area
from realsim.robot.world import SceneGeometry


@dataclass(frozen=True)
class RobotParams:
    """Speeds, clearances and budgets of the primitives."""

    max_joint_speed: float = 1.2  # rad/s along a trajectory
    min_segment_time: float = 0.25  # s
    cart_step: float = 0.02  # m between IK waypoints on straight-line moves
    clearance: float = 0.10  # m above the tallest object when traversing
    pregrasp: float = 0.10  # m back along the approach axis
    lift: float = 0.15  # m lifted after closing
    gripper_time: float = 0.6  # s to open or close
    settle_speed: float = 0.02  # rad/s: joints at rest
    max_settle: float = 0.6  # s waiting for rest after a trajectory
    max_sim_time: float = 40.0  # s budget per primitive
    grasp_attempts: int = 4
    lifted_min: float = 0.04  # m the object must rise to count as lifted
    track_tol: float = 0.01  # m tcp error accepted at the end of a straight move
    push_tilt: float = 0.4  # rad the hand leans back when pushing (fingertips lead)
    push_nudge: float = 0.015  # m a pushed object may travel in contact with another (it nudges it that far at most)


@dataclass
class ActionResult:
    """What a primitive did: success, why, and the measured values."""

    primitive: str
    success: bool
    reason: str
    sim_time: float = 0.0
    attempts: int = 0
    values: dict[str, Any] = field(default_factory=dict)


_WORDS = {"place": "at the target", "place_on": "on the target", "place_in": "inside the target", "place_beside": "beside the target",
          "place_between": "between the targets", "place_down": "on the table"}


_SIDE_WORDS = {"left": "left of", "right": "right of", "front": "in front of", "behind": "behind"}


@dataclass(frozen=True)
class Keepout:
    """What a release must not touch: xy points of other objects, kept ``margin`` away; ``soft``:
    when no pose clears them, try the poses anyway (a crowded bowl)."""

    xy: np.ndarray
    margin: float = 0.01
    soft: bool = False


def _box_centre(pts: np.ndarray) -> np.ndarray:
    return (pts[:, :2].min(axis=0) + pts[:, :2].max(axis=0)) / 2


def _box_centre_3d(pts: np.ndarray) -> np.ndarray:
    """Centre of the points' bounding box: where goals measure an object."""
    return (pts.min(axis=0) + pts.max(axis=0)) / 2


def _on_table(touching: set[str]) -> relations.Relation:
    ok = relations.WORLD in touching and relations.ROBOT not in touching
    return relations.Relation(ok, "touching " + (", ".join(sorted(touching)) or "nothing"))


class _Budget(Exception):
    pass


class _Fail(Exception):
    pass


class Robot:
    """The Panda in a loaded scene: primitives that act by stepping ``data``."""

    def __init__(self, model: mujoco.MjModel, data: mujoco.MjData, prefix: str = PREFIX, params: RobotParams = RobotParams(),
                 ik_params: IKParams = IKParams(), seed: int = 0, release: ReleaseParams = ReleaseParams()):
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
        self.step_hook: Callable[[mujoco.MjModel, mujoco.MjData], None] | None = None
        self.hook_every = 1  # physics steps between calls of ``step_hook`` (e.g. a video recorder)
        self._steps = 0
        if not np.any(data.ctrl[self.act]):  # a model reset without keyframe: hold the current posture
            data.ctrl[self.act] = data.qpos[self.qadr]
            data.ctrl[self.grip_act] = GRIPPER_OPEN_CTRL

    # --- reading the simulation ---------------------------------------------------------------
    def object_names(self) -> list[str]:
        """Names of the free bodies (the movable objects), in model order."""
        return self.geometry.object_names()

    def object_pose(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """Live (position, quaternion w,x,y,z) of a body."""
        b = self._body(name)
        return self.data.xpos[b].copy(), self.data.xquat[b].copy()

    def tcp_pose(self) -> tuple[np.ndarray, np.ndarray]:
        mujoco.mj_kinematics(self.model, self.data)
        return self.data.site_xpos[self.tcp].copy(), self.data.site_xmat[self.tcp].reshape(3, 3).copy()

    def gripper_opening(self) -> float:
        return float(self.data.qpos[self.finger_qadr].sum())

    def _body(self, name: str) -> int:
        return self.geometry.body(name)

    def _subtree(self, b: int) -> list[int]:
        return self.geometry.subtree(b)

    def _world_points(self, b: int) -> np.ndarray:
        return self.geometry.body_points(b)

    def object_points(self, name: str) -> np.ndarray:
        """World-frame surface samples of an object's collision geometry (live pose, attached parts included)."""
        return self.geometry.points(name)

    def object_normals(self, name: str) -> np.ndarray:
        """World-frame outward normals matching :meth:`object_points`."""
        return self.geometry.normals(name)

    def _grasp_candidates(self, obj: str, height_offset: float = 0.0) -> list[GraspCandidate]:
        """Pinches that fit the hand and whose lever arm the grip can hold against gravity."""
        return [c for c in self._fitting_candidates(obj, height_offset) if self._holds(obj, c)[0]]

    def _fitting_candidates(self, obj: str, height_offset: float = 0.0) -> list[GraspCandidate]:
        pts = self.object_points(obj)
        surface = self.surface_below(pts[:, :2].mean(axis=0), float(pts[:, 2].min()) + 0.01, exclude=obj)
        return grasp_candidates(pts, surface, self.base_pos[:2], self._prefer_yaw(), height_offset=height_offset,
                                normals=self.object_normals(obj))

    def _holds(self, obj: str, cand: GraspCandidate) -> tuple[bool, float, float]:
        """Statics of ``cand`` on ``obj``: its mass and centre of mass from the model (attached parts
        included), friction of its geoms, the gripper's force limit."""
        b = self._body(obj)
        mujoco.mj_comPos(self.model, self.data)
        geoms = [g for g in range(self.model.ngeom) if self.model.geom_bodyid[g] in self._subtree(b)]
        friction = float(min(self.model.geom_friction[g][0] for g in geoms)) if geoms else 0.5
        force = float(abs(self.model.actuator_forcerange[self.grip_act]).max()) or 70.0
        return twist_check(cand, self.data.subtree_com[b], float(self.model.body_subtreemass[b]), friction, force)

    def surface_below(self, xy: np.ndarray, z_from: float, exclude: str | None = None) -> float:
        """z of the first collision surface below (xy, z_from), ignoring the robot and ``exclude``."""
        return self.geometry.surface_below(xy, z_from, exclude)

    def _tallest(self, skip: str | None = None) -> float:
        return self.geometry.tallest(skip, default=float(self.base_pos[2]))

    def _contacts_with(self, name: str) -> set[int]:
        """Robot finger bodies touching object ``name`` (or a part attached to it)."""
        parts = set(self._subtree(self._body(name)))
        out = set()
        for i in range(self.data.ncon):
            c = self.data.contact[i]
            b1, b2 = self.model.geom_bodyid[c.geom1], self.model.geom_bodyid[c.geom2]
            if b1 in parts and b2 in self.finger_bodies:
                out.add(int(b2))
            elif b2 in parts and b1 in self.finger_bodies:
                out.add(int(b1))
        return out

    def holding(self, name: str) -> bool:
        return len(self._contacts_with(name)) == 2 and self.gripper_opening() > 0.002

    # --- execution ----------------------------------------------------------------------------
    def _step(self) -> None:
        if self.data.time > self._deadline:
            raise _Budget()
        mujoco.mj_step(self.model, self.data)
        self._steps += 1
        if self._steps % 50 == 0:  # a diverged simulation stops with a message, never a hang
            check_state(self.model, self.data, "robot motion")
        if self.step_hook is not None and self._steps % self.hook_every == 0:
            self.step_hook(self.model, self.data)

    def _wait(self, duration: float) -> None:
        end = self.data.time + duration
        while self.data.time < end:
            self._step()

    def _settle(self) -> None:
        end = self.data.time + self.params.max_settle
        while self.data.time < end:
            self._step()
            if np.abs(self.data.qvel[self.dadr]).max() < self.params.settle_speed:
                break

    def _follow(self, path: list[np.ndarray]) -> None:
        """Track a joint path (first point = current command) with a smooth time scaling."""
        q_cmd = self.data.ctrl[self.act].copy()
        pts = np.vstack([q_cmd] + list(path))
        seg = np.abs(np.diff(pts, axis=0)).max(axis=1)
        total = float(seg.sum())
        if total < 1e-6:
            return
        cum = np.concatenate([[0.0], np.cumsum(seg)])
        duration = max(1.875 * total / self.params.max_joint_speed, self.params.min_segment_time)  # peak speed of the quintic
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
        self._settle()

    def _ik(self, pos: np.ndarray, rot: np.ndarray, q_init: np.ndarray) -> IKResult:
        return self.ik.solve(pos, mat_to_quat(rot), q_init=q_init)

    def _line(self, start: np.ndarray, end: np.ndarray, rot_start: np.ndarray, rot_end: np.ndarray, q_init: np.ndarray) -> list[np.ndarray]:
        """IK waypoints along a straight tcp line (orientation interpolated); raises _Fail."""
        n = max(1, int(np.ceil(np.linalg.norm(end - start) / self.params.cart_step)))
        rel = rot_start.T @ rot_end
        quat = mat_to_quat(rel)
        axis_angle = np.zeros(3)
        mujoco.mju_quat2Vel(axis_angle, quat, 1.0)
        path, q = [], q_init
        for k in range(1, n + 1):
            f = k / n
            ang = np.linalg.norm(axis_angle)
            r = rot_start @ (rotate_about(axis_angle, f * ang) if ang > 1e-9 else np.eye(3))
            res = self._ik(start + f * (end - start), r, q)
            if not res.converged:
                raise _Fail(f"target {np.round(start + f * (end - start), 3).tolist()} unreachable ({res.reason})")
            if np.abs(res.q - q).max() > 0.6:
                raise _Fail("the straight-line path needs a joint flip")
            path.append(res.q)
            q = res.q
        return path

    def _straight(self, end: np.ndarray, rot_end: np.ndarray | None = None) -> None:
        pos, rot = self.tcp_pose()
        rot_end = rot if rot_end is None else rot_end
        q = self.data.ctrl[self.act].copy()
        cmd_pos, cmd_rot = self.ik.fk(q)  # plan from the commanded pose, not the sagging one
        self._follow(self._line(cmd_pos, end, cmd_rot, rot_end, q))

    def _transit(self, end: np.ndarray, rot_end: np.ndarray, skip: str | None = None, below_tcp: float = 0.0, turn_late: bool = False) -> None:
        """Lift to a safe height, traverse, descend to ``end`` (straight lines, IK-checked).

        With ``turn_late`` (a sideways hand for a handle, out of reach up high) the hand may keep
        its orientation across and turn while descending, or swing across in joint space at height.
        """
        q0 = self.data.ctrl[self.act].copy()
        cmd_pos, cmd_rot = self.ik.fk(q0)
        low = max(self._tallest(skip) + 0.03 + below_tcp, end[2])
        safe = max(self._tallest(skip) + self.params.clearance + below_tcp, end[2])
        heights = sorted({safe, max(safe - 0.04, low), max(safe - 0.08, low), low}, reverse=True)

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
                raise _Fail(f"target {np.round(end, 3).tolist()} unreachable ({at_end.reason})")
            rising = self._line(end, np.array([end[0], end[1], z]), rot_end, rot_end, at_end.q)
            across_q = [q_up + f * (rising[-1] - q_up) for f in np.linspace(0.1, 1.0, 10)]
            if min(float(self.ik.fk(q)[0][2]) for q in across_q) < low - 0.02:
                raise _Fail("the swing across dips below the safe height")
            return p1 + across_q + [*rising[::-1][1:], at_end.q]

        plans = [lambda z: across(z, rot_end)]
        if turn_late:
            plans += [lambda z: across(z, cmd_rot), swing]
        last = None
        for plan in plans:
            for z in heights:
                try:
                    path = plan(z)
                    self._check_clear(path, ignore={skip} if skip else set())
                except _Fail as exc:
                    last = exc
                    continue
                self._follow(path)
                return
        raise last or _Fail("no safe path")

    def _check_clear(self, path: list[np.ndarray], ignore: set[str] = frozenset(), hand_may_touch: set[str] = frozenset(),
                     start: np.ndarray | None = None) -> None:
        """Raise _Fail when the arm would touch an object along ``path`` from ``start`` (default:
        the commanded joints), at waypoints and midpoints; the held object is carried, not hit."""
        rel = None
        if self.held:  # the held object moves with the hand: checked against the others like a link
            b = self._body(self.held)
            tcp, rot = self.tcp_pose()
            rel = (rot.T @ (self.data.xpos[b] - tcp), rot.T @ self.data.xmat[b].reshape(3, 3))
        q_prev = self.data.ctrl[self.act].copy() if start is None else np.asarray(start, float)
        for q in path:
            for f in (0.5, 1.0):
                qf = q_prev + f * (q - q_prev)
                carried = None
                if rel is not None:
                    p_w, r_w = self.ik.fk(qf)
                    carried = {self.held: (r_w @ rel[0] + p_w, mat_to_quat(r_w @ rel[1]))}
                hits = self.geometry.robot_hits(self.qadr, qf, ignore, hand_may_touch, self.hand_bodies, carried=carried)
                if hits:
                    raise _Fail(f"the arm would touch {', '.join(sorted(hits))}")
            q_prev = q

    def _check_stroke(self, pushed: set[str], path: list[np.ndarray], contact: np.ndarray, d: np.ndarray, gap: float = 0.03) -> None:
        """Raise _Fail when a link other than the hand would touch the ``pushed`` objects (the
        object and what rides in or on it, carried along once the fingers reach it) or the arm
        any other object, along the push ``path``."""
        for q in path:
            advanced = float((self.ik.fk(q)[0] - contact) @ d)
            shift = d * max(0.0, advanced - gap)
            hits = self.geometry.robot_hits(self.qadr, q, (), pushed, self.hand_bodies, {n: shift for n in pushed})
            if hits:
                raise _Fail(f"the arm would touch {', '.join(sorted(hits))} while pushing")

    def _gripper(self, ctrl: float) -> None:
        self.data.ctrl[self.grip_act] = ctrl
        end = self.data.time + self.params.gripper_time
        while self.data.time < end:
            self._step()
            if self.data.time > end - self.params.gripper_time / 2 and np.abs(self.data.qvel[self.model.jnt_dofadr[self.model.joint(self.prefix + FINGER_JOINTS[0]).id]]) < 1e-3:
                break

    def _run(self, name: str, fn, budget: float | None = None) -> ActionResult:
        start = self.data.time
        self._deadline = start + (budget if budget is not None else self.params.max_sim_time)
        try:
            res: ActionResult = fn()
        except _Budget:
            res = ActionResult(name, False, f"simulated-time budget of {budget or self.params.max_sim_time:.0f} s exceeded")
        except _Fail as exc:
            res = ActionResult(name, False, str(exc))
        finally:
            self._deadline = np.inf
        res.sim_time = self.data.time - start
        return res

    # --- primitives ---------------------------------------------------------------------------
    def go_home(self, max_sim_time: float | None = None) -> ActionResult:
        """Back to the home posture (lifting first if the hand is low)."""
        def body() -> ActionResult:
            pos, _ = self.tcp_pose()
            home_pos, _ = self.ik.fk(np.array(HOME_ARM))
            if pos[2] < home_pos[2] - 0.05:
                try:
                    self._straight(np.array([pos[0], pos[1], home_pos[2]]))
                except _Fail:
                    pass
            self._follow([np.array(HOME_ARM)])
            err = float(np.abs(self.data.qpos[self.qadr] - np.array(HOME_ARM)).max())
            return ActionResult("go_home", err < 0.02, "" if err < 0.02 else f"joint error {err:.3f} rad", values={"joint_error": err})
        return self._run("go_home", body, max_sim_time)

    def move_ee_to(self, pos, quat=None, max_sim_time: float | None = None, direct: bool = False) -> ActionResult:
        """Move the tcp to ``pos`` (world) with ``quat`` (w,x,y,z; None keeps the current orientation)."""
        pos = np.asarray(pos, float)

        def body() -> ActionResult:
            _, rot = self.tcp_pose()
            target_rot = rot if quat is None else quat_to_mat(np.asarray(quat, float))
            res = self._ik(pos, target_rot, self.data.ctrl[self.act].copy())
            if not res.converged:
                return ActionResult("move_ee_to", False, f"target unreachable: {res.reason}", values={"ik_pos_error": res.pos_error, "ik_rot_error": res.rot_error})
            if direct:
                self._straight(pos, target_rot)
            else:
                self._transit(pos, target_rot, skip=self.held, below_tcp=self._held_below())
            now, r_now = self.tcp_pose()
            err = float(np.linalg.norm(now - pos))
            ok = err < self.params.track_tol
            return ActionResult("move_ee_to", ok, "" if ok else f"tcp ended {err * 1000:.1f} mm from the target", values={"pos_error": err, "ik_residual": res.pos_error, "manipulability": res.manipulability})
        return self._run("move_ee_to", body, max_sim_time)

    def open_gripper(self) -> ActionResult:
        def body() -> ActionResult:
            self._gripper(GRIPPER_OPEN_CTRL)
            self.held = None
            w = self.gripper_opening()
            return ActionResult("open_gripper", w > 0.07, "" if w > 0.07 else f"opened only to {w * 1000:.0f} mm", values={"opening": w})
        return self._run("open_gripper", body)

    def close_gripper(self) -> ActionResult:
        def body() -> ActionResult:
            self._gripper(0.0)
            return ActionResult("close_gripper", True, "", values={"opening": self.gripper_opening()})
        return self._run("close_gripper", body)

    def _held_below(self) -> float:
        if not self.held:
            return 0.0
        pos, _ = self.tcp_pose()
        return max(0.0, float(pos[2] - self.object_points(self.held)[:, 2].min()))

    def _prefer_yaw(self) -> float:
        _, r = self.ik.fk(np.array(HOME_ARM))
        return float(np.arctan2(r[1, 1], r[0, 1]))

    def graspability(self, obj: str) -> tuple[bool, str]:
        """Whether the hand can hold ``obj`` at all (some cross-section within the opening)."""
        if self._grasp_candidates(obj):
            return True, ""
        fitting = self._fitting_candidates(obj)
        if fitting:
            torques = [self._holds(obj, c) for c in fitting]
            _, need, can = min(torques, key=lambda t: t[1])
            return False, (f"{obj} fits the hand only where its weight twists out of the pinch: {need:.2f} N m about the "
                           f"fingers at the best of {len(fitting)} pinches, the grip holds {can:.2f} N m")
        w = narrowest_width(self.object_points(obj))
        return False, f"{obj} is {w * 1000:.0f} mm across at its narrowest and has no rim the hand can pinch (handles are not used): the Panda hand opens {MAX_WIDTH * 1000:.0f} mm usable (80 mm max)"

    def grasp(self, obj: str, max_attempts: int | None = None, max_sim_time: float | None = None) -> ActionResult:
        """Grasp and lift ``obj``; failed attempts retry with epsilon-greedy grasp parameters."""
        attempts = max_attempts or self.params.grasp_attempts
        opt = EpsilonGreedy(seed=self.seed)
        log: list[dict] = []

        def body() -> ActionResult:
            ok, why = self.graspability(obj)
            if not ok:
                return ActionResult("grasp", False, f"not graspable: {why}", values={"graspable": False})
            for attempt in range(1, attempts + 1):
                gp = opt.propose()
                z0 = float(self.object_points(obj)[:, 2].min())
                try:
                    reward, info = self._attempt(obj, gp, opt)
                except _Fail as exc:
                    reward, info = -0.1, {"error": str(exc)}
                opt.update(gp, reward)
                log.append({"attempt": attempt, "params": gp.__dict__, "reward": reward, **info})
                if reward >= 1.0:
                    self.held = obj
                    return ActionResult("grasp", True, "", attempts=attempt, values={"graspable": True, "lifted": info.get("lifted"), "kind": info.get("kind"), "log": log})
                # reset for the next attempt: open, back up, home
                self._gripper(GRIPPER_OPEN_CTRL)
                pos, _ = self.tcp_pose()
                try:
                    self._straight(pos + np.array([0, 0, 0.12]))
                except _Fail:
                    pass
                self._follow([np.array(HOME_ARM)])
                if float(self.object_points(obj)[:, 2].min()) < z0 - 0.1:
                    return ActionResult("grasp", False, f"{obj} fell off its support", attempts=attempt, values={"log": log})
            last = log[-1] if log else {}
            return ActionResult("grasp", False, f"no grasp held after {attempts} attempts (last: {last.get('error') or last.get('failure', '')})", attempts=attempts, values={"graspable": True, "log": log})
        return self._run("grasp", body, max_sim_time or self.params.max_sim_time * 2)

    def _attempt(self, obj: str, gp: GraspParams, opt: EpsilonGreedy) -> tuple[float, dict]:
        cands = self._grasp_candidates(obj, gp.height_offset)
        reachable: list[tuple[GraspCandidate, np.ndarray, IKResult]] = []
        q_home = np.array(HOME_ARM)
        for c in cands:
            rot = rotate_about(c.rot[:, 1], gp.tilt) @ c.rot
            rot = rotate_about(rot[:, 2], gp.yaw_offset) @ rot
            for flip in (False, True):  # the hand is symmetric: closing axis +y or -y
                r = rot @ np.diag([-1, -1, 1]) if flip else rot
                pre = c.pos - r[:, 2] * self.params.pregrasp
                res_pre = self._ik(pre, r, q_home)
                if not res_pre.converged:
                    continue
                res = self._ik(c.pos, r, res_pre.q)
                if not res.converged:
                    continue
                try:  # the final approach must be a straight line without a joint flip
                    self._line(pre, c.pos, r, r, res_pre.q)
                except _Fail:
                    continue
                reachable.append((GraspCandidate(c.kind, c.pos, r, c.width, c.score + 0.5 * res.manipulability), res_pre.q, res))
                break
            if len(reachable) >= 6:
                break
        if not reachable:
            raise _Fail(f"none of {len(cands)} grasp candidates is reachable")
        reachable.sort(key=lambda x: -x[0].score)
        opt.n_candidates = len(reachable)
        first = min(gp.candidate, len(reachable) - 1)
        self._gripper(GRIPPER_OPEN_CTRL)
        for k, (cand, _, _) in enumerate(reachable[first:] + reachable[:first]):
            try:  # a path that cannot be planned moves nothing: try the next candidate
                self._transit(cand.pos - cand.approach * self.params.pregrasp, cand.rot, skip=None)
                self._straight(cand.pos, cand.rot)
                break
            except _Fail:
                if k == len(reachable) - 1:
                    raise
        self._gripper(0.0)
        touching = self._contacts_with(obj)
        z_before = float(self.object_points(obj)[:, 2].min())
        pos, _ = self.tcp_pose()
        try:
            self._straight(pos + np.array([0, 0, self.params.lift]))
        except _Fail:
            self._straight(pos + np.array([0, 0, self.params.lift / 2]))
        self._wait(0.2)
        lifted = float(self.object_points(obj)[:, 2].min()) - z_before
        held = self.holding(obj)
        info = {"kind": cand.kind, "width": cand.width, "lifted": lifted, "contacts_at_close": len(touching)}
        if held and lifted >= self.params.lifted_min:
            return 1.0, info
        info["failure"] = f"fingers touching {len(self._contacts_with(obj))}/2, lifted {lifted * 1000:.0f} mm"
        return 0.3 * len(touching) / 2 + 0.4 * max(0.0, min(lifted / self.params.lift, 1.0)), info

    def place(self, obj: str, pos, tolerance: float = 0.03, max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` down with its centre at ``pos`` (xy; z is found below it) and release."""
        def body() -> ActionResult:
            target = np.asarray(pos, float)
            r = footprint_radius(self.object_points(obj))
            near = spots(target[:2], min(tolerance, r), self.base_pos[:2], self.release.ring)
            return self._place(obj, near, target[2], "place", lambda: self._near(obj, target[:2], tolerance),
                               Keepout(self._others(obj), soft=True))
        return self._run("place", body, max_sim_time)

    def place_on(self, obj: str, target: str, max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` on top of body ``target`` (spots within its top face, clear of what
        already lies there)."""
        def body() -> ActionResult:
            tp = self.object_points(target)
            centre, r_in = top_area(tp)
            near = spots(centre, r_in, self.base_pos[:2], self.release.ring)
            return self._place(obj, near, np.nan, "place_on", lambda: relations.on(
                self.object_points(obj), self.object_points(target), self.geometry.touching(obj), target),
                Keepout(self._others(obj, {target}, above=float(tp[:, 2].max()) - 0.01), soft=True))
        return self._run("place_on", body, max_sim_time)

    def place_in(self, obj: str, container: str, max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` into ``container``: a body (bin, bowl, mug: spots within its
        opening, clear of what already lies in it) or a marked zone (a geom or site)."""
        def body() -> ActionResult:
            r = footprint_radius(self.object_points(obj))
            zone = self._zone(container)
            if zone is not None:
                c, half, _ = zone
                near = spots(c, float(max(0.0, half.min() - r)), self.base_pos[:2], self.release.ring)
                return self._place(obj, near, np.nan, "place_in", lambda: self._in_zone(obj, zone), Keepout(self._others(obj), soft=True))
            cp = self.object_points(container)
            centre, r_in = cavity_centre(cp)
            near = spots(centre, max(0.0, r_in - r), self.base_pos[:2], self.release.ring)
            return self._place(obj, near, np.nan, "place_in", lambda: relations.inside(
                self.object_points(obj), self.object_points(container), self.geometry.touching(obj), container),
                Keepout(self._others(obj, {container}, above=float(cp[:, 2].min()) + 0.005), soft=True))
        return self._run("place_in", body, max_sim_time)

    def place_beside(self, obj: str, ref: str, side: str = "next", gap: float = 0.03, max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` on the table beside ``ref``: ``side`` is "next" (any free side) or
        "left", "right", "front", "behind" as seen from the robot; the object's footprint at
        release must clear every other object."""
        if side != "next" and side not in SIDES:
            return ActionResult("place_beside", False, f"unknown side {side!r}: use next, left, right, front or behind")

        def body() -> ActionResult:
            o, r = self.object_points(obj), self.object_points(ref)
            rc, oc = _box_centre(r), _box_centre(o)
            if side == "next":
                dirs = [np.array([np.cos(a), np.sin(a)]) for a in np.arange(8) * np.pi / 4]
                lats: tuple[float, ...] = (0.0,)
            else:
                dirs = [np.array(direction_in_world(DIRECTIONS[SIDES[side]], self.base_yaw))]
                lats = (0.0, 0.03, -0.03, 0.06, -0.06)
            cands: list[tuple[float, float, np.ndarray]] = []
            for d in dirs:
                perp = np.array([-d[1], d[0]])
                reach = float(((r[:, :2] - rc) @ d).max()) + float(((o[:, :2] - oc) @ -d).max()) + gap
                for extra in (0.0, 0.02, 0.05):
                    for lat in lats:
                        xy = rc + d * (reach + extra) + perp * lat
                        cands.append((extra + abs(lat), float(np.linalg.norm(xy - self.base_pos[:2])) if side == "next" else 0.0, xy))
            cands.sort(key=lambda t: (t[0], t[1]))
            level = float(r[:, 2].min())
            near = [xy for _, _, xy in cands if abs(self.geometry.surface_below(xy, level + 0.3, exclude=obj) - level) < 0.02]
            if not near:
                return ActionResult("place_beside", False, f"no spot {'next to' if side == 'next' else _SIDE_WORDS[side]} {ref} "
                                    "on its surface (table edge)")
            if side == "next":
                judge = lambda: relations.next_to(self.object_points(obj), self.object_points(ref), self.geometry.touching(obj))  # noqa: E731
            else:
                d = direction_in_world(DIRECTIONS[SIDES[side]], self.base_yaw)
                judge = lambda: relations.side_of(self.object_points(obj), self.object_points(ref), d, self.geometry.touching(obj))  # noqa: E731
            return self._place(obj, near, np.nan, "place_beside", judge, Keepout(self._others(obj)))
        return self._run("place_beside", body, max_sim_time)

    def place_between(self, obj: str, a: str, b: str, max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` on the table between objects ``a`` and ``b``."""
        def body() -> ActionResult:
            pa, pb = self.object_points(a), self.object_points(b)
            ca, cb = _box_centre(pa), _box_centre(pb)
            u = (cb - ca) / max(float(np.linalg.norm(cb - ca)), 1e-9)
            perp = np.array([-u[1], u[0]])
            t = (float(((pa[:, :2] - ca) @ u).max()) + float(((pb[:, :2] - ca) @ u).min())) / 2
            a_edge, b_edge = float(((pa[:, :2] - ca) @ u).max()), float(((pb[:, :2] - ca) @ u).min())
            along = [t] + [t + f * (b_edge - a_edge) for f in (0.15, -0.15, 0.3, -0.3)]
            cands = [ca + u * tt + perp * lat for lat in (0.0, 0.02, -0.02, 0.04, -0.04, 0.06, -0.06) for tt in along]
            return self._place(obj, cands, np.nan, "place_between", lambda: relations.between(
                self.object_points(obj), pa, pb, self.geometry.touching(obj)), Keepout(self._others(obj), margin=0.005))
        return self._run("place_between", body, max_sim_time)

    def place_down(self, obj: str, max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` down on the table (the static surface) at the free spot nearest
        the hand."""
        def body() -> ActionResult:
            o = self.object_points(obj)
            start = _box_centre(o)
            cands = [start + rr * np.array([np.cos(a), np.sin(a)]) for rr in np.arange(0.0, 0.31, 0.03)
                     for a in np.linspace(0, 2 * np.pi, max(1, int(round(rr / 0.03)) * 6), endpoint=False)]
            top = float(o[:, 2].max())
            near = [xy for xy in cands if self.geometry.surface_below(xy, top, exclude=obj)
                    <= self.geometry.surface_below(xy, top, exclude=obj, static_only=True) + 0.002]
            if not near:
                return ActionResult("place_down", False, f"no free table surface within 30 cm of {obj}")
            return self._place(obj, near, np.nan, "place_down", lambda: _on_table(self.geometry.touching(obj)), Keepout(self._others(obj)))
        return self._run("place_down", body, max_sim_time)

    def _owner_of_xy(self, obj: str, xy: np.ndarray, above: float) -> str:
        """The object (not ``obj``) with a surface point nearest ``xy``."""
        best = min(((float(np.min(np.linalg.norm(p[p[:, 2] > above, :2] - xy, axis=1))) if (p[:, 2] > above).any() else np.inf, n)
                    for n in self.object_names() if n != obj for p in [self.object_points(n)]), default=(np.inf, "another object"))
        return best[1]

    def _others(self, obj: str, skip: frozenset[str] | set[str] = frozenset(), above: float = -np.inf) -> np.ndarray:
        """xy of every other object's surface points higher than ``above`` (what a release must clear)."""
        pts = [self.object_points(n) for n in self.object_names() if n != obj and n not in skip]
        pts = [p[p[:, 2] > above, :2] for p in pts]
        return np.vstack(pts) if pts else np.zeros((0, 2))

    def _zone(self, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """(centre xy, half extents, xy rotation) of a zone geom or site named ``name``, else None."""
        m, d = self.model, self.data
        for kind in (mujoco.mjtObj.mjOBJ_GEOM, mujoco.mjtObj.mjOBJ_SITE):
            i = mujoco.mj_name2id(m, kind, name)
            if i >= 0:
                if kind == mujoco.mjtObj.mjOBJ_GEOM:
                    pos, mat, size = d.geom_xpos[i], d.geom_xmat[i].reshape(3, 3), m.geom_size[i]
                else:
                    pos, mat, size = d.site_xpos[i], d.site_xmat[i].reshape(3, 3), m.site_size[i]
                return pos[:2].copy(), np.asarray(size[:2], float).copy(), mat[:2, :2].copy()
        return None

    def _centre_xy(self, obj: str) -> np.ndarray:
        pts = self.object_points(obj)
        return (pts[:, :2].min(axis=0) + pts[:, :2].max(axis=0)) / 2

    def _in_zone(self, obj: str, zone: tuple[np.ndarray, np.ndarray, np.ndarray]) -> relations.Relation:
        c, half, r2 = zone
        local = r2.T @ (self._centre_xy(obj) - c)
        inside = bool(np.all(np.abs(local) <= half))
        return relations.Relation(inside, f"centre at ({local[0]:+.3f}, {local[1]:+.3f}) m in the zone of half size "
                                          f"({half[0]:.3f}, {half[1]:.3f})")

    def _near(self, obj: str, xy: np.ndarray, tolerance: float) -> relations.Relation:
        err = float(np.linalg.norm(self._centre_xy(obj) - xy))
        return relations.Relation(err <= tolerance, f"centre {err * 1000:.0f} mm from the target (<= {tolerance * 1000:.0f})")

    def _place(self, obj: str, candidates: list[np.ndarray], surface_hint: float, name: str,
               judge: Callable[[], relations.Relation], keepout: Keepout | None = None) -> ActionResult:
        """Carry the held ``obj`` over the first reachable release pose (spot, hand yaw, height),
        lower it there, release, retreat; ``judge`` says whether the end state is what was asked."""
        if self.held != obj or not self.holding(obj):
            return ActionResult(name, False, f"{obj} is not held (grasp it first)")
        pts = self.object_points(obj)
        tcp, rot = self.tcp_pose()
        offset = self._centre_xy(obj) - tcp[:2]  # object centre relative to the tcp, turns with the hand
        below = tcp[2] - float(pts[:, 2].min())
        poses = release_poses(candidates, self.release, limit=keepout is None or not len(keepout.xy))
        if keepout is not None and len(keepout.xy):
            # the object's footprint and the fingers as they open (4 cm each side along the closing axis)
            y, x = rot[:2, 1], rot[:2, 0]
            fingers = np.array([sy * 0.05 * y + sx * 0.012 * x for sy in (-1.0, 1.0) for sx in (-1.0, 0.0, 1.0)])
            foot = np.vstack([pts[:, :2] - tcp[:2], fingers])
            tree = cKDTree(keepout.xy)

            def turn_offset(yaw: float) -> np.ndarray:  # the object's centre relative to the tcp, turned
                c, s_ = np.cos(yaw), np.sin(yaw)
                return offset @ np.array([[c, s_], [-s_, c]])

            def fits(pose: tuple[np.ndarray, float, float]) -> bool:
                xy, yaw, _ = pose
                c, s_ = np.cos(yaw), np.sin(yaw)
                turned = foot @ np.array([[c, s_], [-s_, c]])
                at = turned - turn_offset(yaw) + xy
                return bool(tree.query(at[:: max(1, len(at) // 400)])[0].min() >= keepout.margin)
            clear = [pose for pose in poses if fits(pose)]
            if not clear and not keepout.soft:
                raise _Fail(f"no release pose leaves {keepout.margin * 1000:.0f} mm to the other objects ({len(poses)} tried)")
            poses = (clear or poses)[: self.release.max_poses]
        last: _Fail | None = None
        for k, (xy, yaw, drop) in enumerate(poses):
            turn = rotate_about(np.array([0.0, 0.0, 1.0]), yaw)
            r_goal = turn @ rot
            surface = surface_hint if np.isfinite(surface_hint) else self.surface_below(xy, self._tallest(obj) + 0.05, exclude=obj)
            goal = np.array([*(xy - turn[:2, :2] @ offset), surface + below + drop])
            if not self._ik(goal, r_goal, self.data.ctrl[self.act].copy()).converged:
                last = _Fail(f"release pose {np.round(goal, 3).tolist()} unreachable")
                continue
            try:
                self._transit(goal + np.array([0, 0, 0.08]), r_goal, skip=obj, below_tcp=below)
                self._straight(goal, r_goal)
                break
            except _Fail as exc:
                last = exc
        else:
            raise _Fail(f"no release pose reachable ({len(poses)} tried: spots, hand yaws, heights; last: {last})")
        self._gripper(GRIPPER_OPEN_CTRL)
        self.held = None
        pos, _ = self.tcp_pose()
        try:
            self._straight(pos + np.array([0, 0, 0.10]))
        except _Fail:
            pass
        self._wait(0.4)
        dof = self.model.jnt_dofadr[self.model.body(obj).jntadr[0]]
        resting = float(np.abs(self.data.qvel[dof:dof + 3]).max()) < 0.05
        settle_end = self.data.time + 1.2  # a released object may rock a little before it rests
        while not resting and self.data.time < settle_end:
            self._wait(0.05)
            resting = float(np.abs(self.data.qvel[dof:dof + 3]).max()) < 0.05
        verdict = judge()
        values = {"object_xy": self._centre_xy(obj).tolist(), "target_xy": np.asarray(xy).tolist(), "release_pose": k,
                  "release_yaw": yaw, "release_drop": drop, "measured": verdict.measured, "resting": resting}
        ok = verdict.ok and resting
        reason = "" if ok else (f"not {_WORDS[name]} after release: {verdict.measured}" if not verdict.ok else "object still moving")
        return ActionResult(name, ok, reason, values=values)

    def push(self, obj: str, direction, distance: float, max_sim_time: float | None = None) -> ActionResult:
        """Push ``obj`` horizontally along ``direction`` by ``distance`` with the closed fingers."""
        d = np.array([*np.asarray(direction, float)[:2], 0.0])
        d /= np.linalg.norm(d)

        def body() -> ActionResult:
            pts = self.object_points(obj)
            start_pos = _box_centre_3d(pts)
            bottom = float(pts[:, 2].min())
            height = float(pts[:, 2].max()) - bottom
            centre = np.array([*pts[:, :2].mean(axis=0), bottom + min(0.03, height / 2) + 0.005])
            back = float(((pts - centre) @ d).min())
            contact = centre + d * (back - 0.03)
            closing = np.array([-d[1], d[0], 0.0])
            # the closed hand is symmetric: of the two yaws, try the one nearer the current first
            _, now_rot = self.tcp_pose()
            # tilted so the fingertips lead and the palm trails: tall objects are pushed low, not tipped
            tilt = rotate_about(np.array([d[1], -d[0], 0.0]), self.params.push_tilt)
            upright = [frame_from(np.array([0, 0, -1.0]), c) for c in (closing, -closing)]
            upright.sort(key=lambda r: -float(np.trace(now_rot.T @ r)))
            rots = [tilt @ r for r in upright] + upright  # upright when the tilted hand cannot reach
            # the object's footprint swept along the push must not run into another object
            foot = pts[:: max(1, len(pts) // 400), :2]
            # what rests in or on the object (touching it, centred over its footprint) rides along: not in the way
            lo, hi = pts[:, :2].min(axis=0), pts[:, :2].max(axis=0)
            riding = {n for n in self.geometry.touching(obj) - {relations.WORLD, relations.ROBOT}
                      if np.all((_box_centre(self.object_points(n)) >= lo) & (_box_centre(self.object_points(n)) <= hi))}
            others = self._others(obj, skip=riding, above=bottom + 0.005)
            if len(others):
                tree = cKDTree(others)
                for k in np.linspace(0.0, distance, max(2, int(distance / 0.01) + 1)):
                    gap, idx = tree.query(foot + k * d[:2])
                    if gap.min() < 0.002 and k < distance - self.params.push_nudge:  # a last-centimetre touch nudges, no more
                        hit = self._owner_of_xy(obj, others[idx[int(np.argmin(gap))]], bottom)
                        return ActionResult("push", False, f"pushing {obj} {distance * 100:.0f} cm would shove {hit} "
                                            f"(after {k * 100:.0f} cm)", values={"moved": 0.0})
            self._gripper(0.0)
            end = contact + d * (distance + 0.03)
            last: _Fail | None = None
            for rot in rots:
                try:  # the stroke is planned and checked first: only the hand may touch the pushed object
                    q_c = self._ik(contact, rot, np.array(self.ik.home))
                    if not q_c.converged:
                        raise _Fail(f"push contact {np.round(contact, 3).tolist()} unreachable ({q_c.reason})")
                    self._check_stroke({obj, *riding}, self._line(contact, end, rot, rot, q_c.q), contact, d)
                    self._transit(contact, rot, skip=None)
                    break
                except _Fail as exc:
                    last = exc
            else:
                raise last or _Fail("no push pose")
            self._straight(end, rot)
            pos, _ = self.tcp_pose()
            for retreat in (pos - d * 0.03 + np.array([0, 0, 0.1]), pos + np.array([0, 0, 0.1]), pos - d * 0.03):
                try:  # back off the object; the push itself is judged by how far the object moved
                    self._straight(retreat, rot)
                    break
                except _Fail:
                    continue
            self._wait(0.3)
            end_pos = _box_centre_3d(self.object_points(obj))
            moved = float((end_pos - start_pos) @ d)
            verdict = relations.moved(start_pos, end_pos, d[:2], distance)  # the same test as the goal check
            return ActionResult("push", verdict.ok, "" if verdict.ok else verdict.measured, values={"moved": moved, "measured": verdict.measured})
        return self._run("push", body, max_sim_time)

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
                return self.data.site_xpos[i].copy()
        for g in range(m.ngeom):
            if m.geom_bodyid[g] == b and "handle" in m.geom(g).name:
                return self.data.geom_xpos[g].copy()
        if pull is None:
            return self.data.xpos[b].copy()
        pts = self._world_points(b)
        along = pts @ pull
        front = pts[along > along.max() - 0.005]
        return (front.min(axis=0) + front.max(axis=0)) / 2

    def _articulate(self, name: str, obj: str, amount: float | None, opening: bool) -> ActionResult:
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
            lo, hi = (q0, q0 + (0.25 if slide else 1.2)) if opening else (0.0, q0)
        if opening:
            target = min(hi, q0 + (amount if amount is not None else (hi - q0)))
        else:
            target = lo
            if q0 - lo < 0.005:
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
        self._gripper(GRIPPER_OPEN_CTRL)
        for k, closing in enumerate((up, -up)):  # the hand is symmetric: either wrist roll may be the reachable one
            rot = frame_from(-horiz, closing)
            try:
                self._transit(hpos + horiz * self.params.pregrasp, rot, turn_late=True)
                self._straight(hpos, rot)
                break
            except _Fail:
                if k == 1:
                    raise
        self._gripper(0.0)
        steps = 10
        path, q = [], self.data.ctrl[self.act].copy()
        for k in range(1, steps + 1):
            dq = (target - q0) * k / steps
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
            self._straight(pos - r[:, 2] * 0.08)
        except _Fail:
            pass
        now = float(self.data.qpos[qa])
        if opening:
            opened = now - q0
            ok = opened >= 0.6 * (target - q0)
            return ActionResult(name, ok, "" if ok else f"opened {opened:.3f} of {target - q0:.3f}", values={"opened": opened, "target": target - q0})
        closed = q0 - now
        ok = now - lo <= max(0.01, 0.2 * (q0 - lo))
        return ActionResult(name, ok, "" if ok else f"still open by {now - lo:.3f} (closed {closed:.3f} of {q0 - lo:.3f})",
                            values={"closed_by": closed, "target": q0 - lo, "position": now})
