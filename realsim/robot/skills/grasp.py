"""Grasp and pick: pinch candidates that fit the hand and hold against gravity, reachable
approaches, and attempts retried with epsilon-greedy grasp parameters."""

from __future__ import annotations

import functools
from dataclasses import replace
from typing import Any

import mujoco
import numpy as np

from realsim.robot.arm import QUINTIC_ACCEL
from realsim.robot.grasps import MAX_WIDTH, GraspCandidate, grasp_candidates, narrowest_width, rotate_about, twist_check
from realsim.robot.hand_hulls import HandHulls
from realsim.robot.handles import handle_candidates
from realsim.robot.ik import IKResult
from realsim.robot.model import FINGER_JOINTS, GRIPPER_OPEN_CTRL, HOME_ARM
from realsim.robot.motion import Motion
from realsim.robot.optimizer import EpsilonGreedy, GraspParams
from realsim.robot.result import ActionResult, PlanFailure
from realsim.robot.squeeze import close_ctrl, needed_pad, pad_force, servo_pad

SUCCESS = 1.0  # reward of an attempt that holds the object lifted

__all__ = ["GraspSkill"]


class GraspSkill(Motion):
    """graspability and grasp (pick and lift)."""

    def _grasp_candidates(self, obj: str, height_offset: float = 0.0) -> list[GraspCandidate]:
        """Pinches that fit the hand and whose lever arm the grip can hold against gravity (a handle
        pinch with ``squeeze_safety`` to spare); a pinch ranks lower the nearer its torque comes to
        what the grip holds (a screwdriver by its grip, not by its shaft far from its weight)."""
        out = []
        for c in self._fitting_candidates(obj, height_offset):
            ok, need, can = self._holds(obj, c)
            if ok:
                if c.kind == "handle" and need * self.params.pick.squeeze_safety > can:
                    continue  # a lever held only just: carrying it swings it out of the pinch
                out.append(replace(c, score=c.score - self.params.pick.statics_weight * need / can))
        out.sort(key=lambda c: -c.score)
        return out

    def _fitting_candidates(self, obj: str, height_offset: float = 0.0) -> list[GraspCandidate]:
        """Pinches of ``obj`` that fit the hand, from its surface points above its support; its
        handles too when it has handle sites or when no pinch of its body holds."""
        pts = self.object_points(obj)
        surface = self.surface_below(pts[:, :2].mean(axis=0), float(pts[:, 2].min()) + self.params.pick.support_probe, exclude=obj)
        normals = self.object_normals(obj)
        cands = grasp_candidates(pts, surface, self.base_pos[:2], self._prefer_yaw(), height_offset=height_offset, normals=normals)
        sites = self._handle_sites(obj)
        if sites or not any(self._holds(obj, c)[0] for c in cands):
            cands += self._handles(obj, pts, normals, surface, sites)
            cands.sort(key=lambda c: -c.score)
        return cands

    def _handle_sites(self, obj: str) -> list[np.ndarray]:
        """World positions of the handle sites (``<obj>_handle``, ``<obj>_handle_2``) on the object's own body."""
        b, m = self._body(obj), self.model
        return [self.data.site_xpos[i].copy() for i in range(m.nsite)
                if m.site_bodyid[i] == b and m.site(i).name.removeprefix(f"{obj}_").startswith("handle")]

    def _handles(self, obj: str, pts: np.ndarray, normals: np.ndarray, surface: float, sites: list[np.ndarray]) -> list[GraspCandidate]:
        """Handle pinches of ``obj`` (:func:`handle_candidates`), computed once per object pose."""
        pos, quat = self.object_pose(obj)
        key = (obj, *np.round(np.concatenate([pos, quat]), 4).tolist())
        cache: dict[tuple[object, ...], list[GraspCandidate]] = self.__dict__.setdefault("_handle_cache", {})
        if key not in cache:
            cache[key] = handle_candidates(pts, normals, surface, self.base_pos[:2], sites or None)
        return list(cache[key])

    def _holds(self, obj: str, cand: GraspCandidate) -> tuple[bool, float, float]:
        """Statics of ``cand`` on ``obj``: its mass and centre of mass from the model (attached parts
        included), friction of its geoms, the gripper's squeeze at the pinch's width."""
        b = self._body(obj)
        mujoco.mj_comPos(self.model, self.data)
        return twist_check(cand, self.data.subtree_com[b], float(self.model.body_subtreemass[b]), self._friction(b), pad_force(self.model, self.grip_act, cand.width))

    def _friction(self, b: int) -> float:
        """The lowest sliding friction of body ``b``'s geoms and the bodies attached to it."""
        geoms = [g for g in range(self.model.ngeom) if self.model.geom_bodyid[g] in self._subtree(b)]
        return float(min(self.model.geom_friction[g][0] for g in geoms)) if geoms else self.params.arm.default_friction

    def _close_ctrl(self, obj: str, cand: GraspCandidate) -> float:
        """The gripper command for ``cand``: the plain servo's squeeze at that width
        (:func:`servo_pad`: a body pinch, whose small lever the soft contacts hold better than the
        statics say, and a thin wall squeezed harder is driven through), harder for a handle,
        as its lever needs, up to the most the gripper can."""
        m, a = self.model, self.grip_act
        if cand.kind != "handle":
            return close_ctrl(m, a, cand.width, servo_pad(m, a, cand.width))
        _, need, can = self._holds(obj, cand)
        b = self._body(obj)
        pad = needed_pad(need, can, pad_force(m, a, cand.width), float(m.body_subtreemass[b]), self._friction(b), self.params.pick.squeeze_safety)
        return close_ctrl(m, a, cand.width, min(max(pad, servo_pad(m, a, cand.width)), pad_force(m, a, cand.width)))

    def _prefer_yaw(self) -> float:
        """Yaw of the hand's closing axis at home: pinches near it are preferred."""
        _, r = self.ik.fk(np.array(HOME_ARM))
        return float(np.arctan2(r[1, 1], r[0, 1]))

    def graspability(self, obj: str) -> tuple[bool, str]:
        """Whether the hand can hold ``obj`` at all (some cross-section, rim or handle within the opening
        whose lever arm the grip holds), and why not."""
        if self._grasp_candidates(obj):
            return True, ""
        fitting = self._fitting_candidates(obj)
        if fitting:
            safety = self.params.pick.squeeze_safety
            torques = [(c.kind, *self._holds(obj, c)[1:]) for c in fitting]
            kind, need, can = min(torques, key=lambda t: t[1] / t[2] * (safety if t[0] == "handle" else 1.0))
            held = f"the grip holds {can:.2f} N m" + (f" (a handle must hold {safety:g} times its torque to be carried without swinging out)"
                                                       if kind == "handle" else "")
            return False, (f"{obj} fits the hand only where its weight twists out of the pinch: {need:.2f} N m about the "
                           f"fingers at the best of {len(fitting)} pinches ({'a handle' if kind == 'handle' else 'of its body'}), {held}")
        w = narrowest_width(self.object_points(obj))
        return False, f"{obj} is {w * 1000:.0f} mm across at its narrowest and has no rim or handle the hand can pinch: the Panda hand opens {MAX_WIDTH * 1000:.0f} mm usable (80 mm max)"

    def grasp(self, obj: str, max_attempts: int | None = None, max_sim_time: float | None = None) -> ActionResult:
        """Grasp and lift ``obj``; failed attempts retry with epsilon-greedy grasp parameters."""
        attempts = max_attempts or self.params.grasp_attempts
        opt = EpsilonGreedy(seed=self.seed)
        log: list[dict[str, Any]] = []
        pk = self.params.pick

        def body() -> ActionResult:
            ok, why = self.graspability(obj)
            if not ok:
                return ActionResult("grasp", False, f"not graspable: {why}", values={"graspable": False})
            self.stood[obj] = self._up(obj)
            for attempt in range(1, attempts + 1):
                gp = opt.propose()
                z0 = float(self.object_points(obj)[:, 2].min())
                q_cmd = self.data.ctrl[self.act].copy()
                try:
                    reward, info = self._attempt(obj, gp, opt)
                except PlanFailure as exc:
                    reward, info = pk.error_reward, {"error": str(exc)}
                opt.update(gp, reward)
                log.append({"attempt": attempt, "params": gp.__dict__, "reward": reward, **info})
                if reward >= SUCCESS:
                    self.held, self.pinch = obj, (str(info.get("kind", "")), float(info.get("width", 0.0)))
                    return ActionResult("grasp", True, "", attempts=attempt, values={"graspable": True, "lifted": info.get("lifted"), "kind": info.get("kind"), "log": log})
                self.held, self.pinch = None, ("", 0.0)
                if np.array_equal(self.data.ctrl[self.act], q_cmd):
                    continue  # the arm never moved (no plan): nothing to undo
                # reset for the next attempt: open, back up, home
                self._gripper(GRIPPER_OPEN_CTRL)
                pos, _ = self.tcp_pose()
                try:
                    self._straight(pos + np.array([0, 0, pk.retry_lift]))
                except PlanFailure:
                    pass
                self._follow([np.array(HOME_ARM)])
                if float(self.object_points(obj)[:, 2].min()) < z0 - pk.fell_drop:
                    return ActionResult("grasp", False, f"{obj} fell off its support", attempts=attempt, values={"log": log})
            last = log[-1] if log else {}
            return ActionResult("grasp", False, f"no grasp held after {attempts} attempts (last: {last.get('error') or last.get('failure', '')})", attempts=attempts, values={"graspable": True, "log": log})
        res = self._run("grasp", body, max_sim_time or self.params.max_sim_time * pk.budget_factor)
        if not res.success:
            self.held, self.pinch = None, ("", 0.0)
        return res

    def _carry_time(self, pts: np.ndarray) -> float:
        """A held object is carried no faster than its pinch holds it: the tcp's peak acceleration
        (quintic time scaling over the tcp's path through joint points ``pts``) stays where the
        inertial torque, mass x acceleration x the lever from the pinch to the centre of mass, fits
        in what the pinch resists beyond the weight's own torque (:func:`twist_check` at the
        gripper's present squeeze), within ``carry_accel``."""
        obj, (kind, width) = self.held, self.pinch
        if obj is None or not kind:
            return 0.0
        b, (lo, hi) = self._body(obj), self.params.pick.carry_accel
        tcp, rot = self.tcp_pose()
        mujoco.mj_comPos(self.model, self.data)
        com, mass = self.data.subtree_com[b].copy(), float(self.model.body_subtreemass[b])
        force = pad_force(self.model, self.grip_act, width, float(self.data.ctrl[self.grip_act]))
        _, need, can = twist_check(GraspCandidate(kind, tcp, rot, width, 0.0), com, mass, self._friction(b), force)
        accel = float(np.clip((can - need) / (mass * max(float(np.linalg.norm(com - tcp)), 1e-3)), lo, hi))
        path = np.array([self.ik.fk(q)[0] for q in pts])
        return float(np.sqrt(QUINTIC_ACCEL * np.linalg.norm(np.diff(path, axis=0), axis=1).sum() / accel))

    @functools.cached_property
    def _tcp_bodies(self) -> set[int]:
        """The robot bodies rigid with the tcp (the hand, its fingers, the last link)."""
        return self.hand_bodies | {self.model.body(self.prefix + "link7").id}

    @functools.cached_property
    def _hand_hulls(self) -> HandHulls:
        """The hulls rigid with the tcp, fingers open, swept over the pre-grasp approach."""
        qpos = self.data.qpos.copy()
        qpos[self.finger_qadr] = self.model.jnt_range[[self.model.joint(self.prefix + j).id for j in FINGER_JOINTS], 1]
        return HandHulls(self.model, qpos, self.tcp, self._tcp_bodies, self.params.pregrasp)

    def _neighbour_clouds(self, obj: str) -> dict[str, np.ndarray]:
        """Surface samples of every other object within the hand's reach of ``obj``, by name."""
        pts = self.object_points(obj)
        lo, hi = pts.min(axis=0) - self._hand_hulls.reach, pts.max(axis=0) + self._hand_hulls.reach
        clouds = {n: self.object_points(n) for n in self.object_names() if n != obj}
        return {n: p[np.all((p > lo) & (p < hi), axis=1)] for n, p in clouds.items()}

    def _clear_posture(self, pos: np.ndarray, rot: np.ndarray, q_init: np.ndarray, ignore: set[str], blockers: set[str]) -> IKResult | None:
        """A posture putting the tcp at (``pos``, ``rot``) that touches nothing but ``ignore``: the
        plain IK's, else the collision-aware IK's when only links the arm can move aside are in the
        way (what the hand itself would touch at that pose, no posture avoids); None when there is
        none, what was touched added to ``blockers``."""
        res = self._ik(pos, rot, q_init)
        if not res.converged:
            return None
        hits = self._touches(res.q, ignore)
        if not hits:
            return res
        # only the bodies rigid with the tcp count: every object is one the other links "may touch"
        hand_hits = self.geometry.robot_hits(self.qadr, res.q, ignore, self.object_names(), self.robot_bodies - self._tcp_bodies)
        if not hand_hits:
            alt = self._ik_clear(pos, rot, q_init, ignore)
            if alt.converged and not self._touches(alt.q, ignore):
                return alt
        blockers |= hand_hits or hits
        return None

    def _reachable(self, obj: str, cands: list[GraspCandidate], tilt: float, yaw: float,
                   blockers: set[str], others: dict[str, np.ndarray] | None = None) -> list[tuple[GraspCandidate, np.ndarray, IKResult]]:
        """The candidates the hand reaches, turned by ``tilt`` about their closing axis and ``yaw``
        about their approach, with a straight final approach, at pre-grasp and grasp postures that
        touch no other object (at most ``max_reachable``): (candidate, pre-grasp joints, grasp IK);
        the objects in the way are added to ``blockers``. A pose whose hand or open fingers reach
        into ``others`` (:meth:`_neighbour_clouds`) is dropped before any IK."""
        pk = self.params.pick
        others = self._neighbour_clouds(obj) if others is None else others
        out: list[tuple[GraspCandidate, np.ndarray, IKResult]] = []
        q_home = np.array(HOME_ARM)
        for c in cands:
            rot = rotate_about(c.rot[:, 1], tilt) @ c.rot
            rot = rotate_about(rot[:, 2], yaw) @ rot
            for flip in (False, True):  # the hand is symmetric: closing axis +y or -y
                r = rot @ np.diag([-1, -1, 1]) if flip else rot
                in_way = self._hand_hulls.touched(c.pos, r, others)
                if in_way:
                    blockers |= in_way
                    continue
                pre = c.pos - r[:, 2] * self.params.pregrasp
                res_pre = self._clear_posture(pre, r, q_home, set(), blockers)
                if res_pre is None:
                    continue
                res = self._clear_posture(c.pos, r, res_pre.q, {obj}, blockers)
                if res is None:
                    continue
                try:  # the final approach must be a straight line without a joint flip
                    self._line(pre, c.pos, r, r, res_pre.q)
                except PlanFailure:
                    continue
                out.append((GraspCandidate(c.kind, c.pos, r, c.width, c.score + pk.manipulability_weight * res.manipulability), res_pre.q, res))
                break
            if len(out) >= pk.max_reachable:
                break
        return out

    def _attempt(self, obj: str, gp: GraspParams, opt: EpsilonGreedy) -> tuple[float, dict[str, Any]]:
        """One grasp: the reachable candidates ranked, approach, close, lift; (reward, what happened)."""
        pk = self.params.pick
        cands = self._grasp_candidates(obj, gp.height_offset)
        reachable: list[tuple[GraspCandidate, np.ndarray, IKResult]] = []
        blockers: set[str] = set()
        others = self._neighbour_clouds(obj)
        for lean in pk.reach_tilts:  # none reachable clear as planned (the far edge of the reach, a tall neighbour): the hand leans about the closing axis
            reachable = self._reachable(obj, cands, gp.tilt + lean, gp.yaw_offset, blockers, others)
            if reachable:
                break
        if not reachable:
            why = f" without touching {', '.join(sorted(blockers))}" if blockers else ""
            raise PlanFailure(f"none of {len(cands)} grasp candidates is reachable{why}, upright or leaning up to {max(map(abs, pk.reach_tilts)):.1f} rad")
        reachable.sort(key=lambda x: -x[0].score)
        opt.n_candidates = len(reachable)
        first = min(gp.candidate, len(reachable) - 1)
        self._gripper(GRIPPER_OPEN_CTRL)
        ranked = reachable[first:] + reachable[:first]
        # each candidate's transit by its straight lines first; then planned into its pre-grasp posture found clear
        tries = [(c, None) for c, _, _ in ranked] + [(c, q_pre) for c, q_pre, _ in ranked]
        for k, (cand, q_goal) in enumerate(tries):
            try:  # a path that cannot be planned moves nothing: try the next
                self._transit(cand.pos - cand.approach * self.params.pregrasp, cand.rot, skip=None, q_goal=q_goal)
                self._straight(cand.pos, cand.rot, clear_but={obj})  # the open fingers come down clear of the neighbours
                break
            except PlanFailure:
                if k == len(tries) - 1:
                    raise
        self._gripper(self._close_ctrl(obj, cand))
        self.held, self.pinch = obj, (cand.kind, cand.width)  # the lift moves as this pinch allows (:meth:`_carry_time`)
        touching = self._contacts_with(obj)
        z_before = float(self.object_points(obj)[:, 2].min())
        pos, _ = self.tcp_pose()
        try:
            self._straight(pos + np.array([0, 0, self.params.lift]))
        except PlanFailure:
            self._straight(pos + np.array([0, 0, self.params.lift / 2]))
        self._wait(pk.lift_wait)
        lifted = float(self.object_points(obj)[:, 2].min()) - z_before
        held = self.holding(obj)
        info: dict[str, Any] = {"kind": cand.kind, "width": cand.width, "lifted": lifted, "contacts_at_close": len(touching)}
        if held and lifted >= self.params.lifted_min:
            return SUCCESS, info
        info["failure"] = f"fingers touching {len(self._contacts_with(obj))}/2, lifted {lifted * 1000:.0f} mm"
        return pk.contact_reward * len(touching) / 2 + pk.lift_reward * max(0.0, min(lifted / self.params.lift, 1.0)), info
