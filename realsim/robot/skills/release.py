"""Release: carry the held object over a release pose clear of the others, lower, open, judge.

Places try spots within the target's free area, hand yaws and heights, keep the object's
footprint and the opening fingers clear of other objects, and judge the end state with the same
relations as the goal checks (:mod:`realsim.planner.relations`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from realsim.planner import relations
from realsim.robot.grasps import rotate_about
from realsim.robot.model import GRIPPER_OPEN_CTRL
from realsim.robot.motion import Motion
from realsim.robot.placing import footprint_radius, long_axis, release_poses, underside
from realsim.robot.queries import box_centre
from realsim.robot.result import ActionResult, PlanFailure
from realsim.robot.squeeze import close_ctrl

__all__ = ["Cavity", "Keepout", "Release"]

Pose = tuple[np.ndarray, float, float, float]  # where the object's footprint centre goes (xy), hand yaw, drop, tilt

_WORDS = {"place": "at the target", "place_on": "on the target", "place_in": "inside the target", "place_beside": "beside the target",
          "place_between": "between the targets", "place_down": "on the table"}


@dataclass(frozen=True)
class Keepout:
    """What a release must not touch: xy points of other objects, kept ``margin`` away; ``soft``:
    when no pose clears them, try the poses anyway (a crowded bowl); ``fingers_soft``: then the
    poses whose object footprint alone clears them (the opening fingers' sweep is an upper bound)."""

    xy: np.ndarray
    margin: float = 0.01
    soft: bool = False
    fingers_soft: bool = False  # when no pose clears with the fingers, poses whose object alone clears (never one that lands on a neighbour)


@dataclass(frozen=True)
class Cavity:
    """A container's opening: its centre (xy), inner radius and rim height (z)."""

    name: str
    centre: np.ndarray
    radius: float
    rim: float


class Release(Motion):
    """The release every place primitive ends in (:meth:`_place`) and its judges."""

    def _in_zone(self, obj: str, zone: tuple[np.ndarray, np.ndarray, np.ndarray]) -> relations.Relation:
        """Whether ``obj``'s centre lies within ``zone`` (centre, half extents, xy rotation)."""
        c, half, r2 = zone
        local = r2.T @ (self._centre_xy(obj) - c)
        inside = bool(np.all(np.abs(local) <= half))
        return relations.Relation(inside, f"centre at ({local[0]:+.3f}, {local[1]:+.3f}) m in the zone of half size "
                                          f"({half[0]:.3f}, {half[1]:.3f})")

    def _near(self, obj: str, xy: np.ndarray, tolerance: float) -> relations.Relation:
        """Whether ``obj``'s centre lies within ``tolerance`` of ``xy``."""
        err = float(np.linalg.norm(self._centre_xy(obj) - xy))
        return relations.Relation(err <= tolerance, f"centre {err * 1000:.0f} mm from the target (<= {tolerance * 1000:.0f})")

    def _place(self, obj: str, candidates: list[np.ndarray], surface_hint: float, name: str,
               judge: Callable[[], relations.Relation], keepout: Keepout | None = None,
               cavity: Cavity | None = None, turns: list[float] | None = None) -> ActionResult:
        """Carry the held ``obj`` over the first reachable release pose (spot, hand yaw, height),
        lower it there, release, retreat; ``judge`` says whether the end state is what was asked.

        The release height comes from the object's own underside over what lies below it at that
        pose (``surface_hint``: a given surface height instead). With a ``cavity`` (a container's
        opening), poses that would leave the object on the rim are skipped and tipped releases
        (one end first, the rest over the rim) are tried for an object longer than the opening.
        ``turns``: a hand yaw for each candidate spot that the tried yaws start from."""
        if self.held != obj or not self.holding(obj):
            return ActionResult(name, False, f"{obj} is not held (grasp it first)")
        pl = self.params.place
        tcp, rot0 = self.tcp_pose()
        rel0 = self.object_points(obj) - tcp  # the object relative to the tcp: it turns with the hand
        fix = self._upright(obj)
        frames = ([(rel0 @ fix.T, fix @ rot0)] if fix is not None else []) + [(rel0, rot0)]
        if cavity is not None:  # a container's walls hold the object as it hangs; the hand turned back comes second
            frames.reverse()
        tries: list[tuple[Pose, np.ndarray, np.ndarray, np.ndarray]] = []
        last: PlanFailure | None = None
        for rel, rot in frames:  # the hand turned so the object stands as it stood, and as it hangs
            axis = long_axis(rel)
            start = {id(xy): turn for xy, turn in zip(candidates, turns or [])}
            poses: list[Pose] = [(xy, yaw + start.get(id(xy), 0.0), drop, 0.0) for xy, yaw, drop in
                                 release_poses(candidates, self.release, limit=keepout is None or not len(keepout.xy))]
            lean = self._lean_poses(obj, rel, axis, cavity) if cavity is not None else []
            if cavity is not None and footprint_radius(rel) > cavity.radius and not lean:
                last = PlanFailure(f"{obj} is longer than {cavity.name}'s opening and, {self._mass(obj) * 1000:.0f} g leaning on the rim of "
                                   f"{self._mass(cavity.name) * 1000:.0f} g, would tip it over")
            if keepout is not None and len(keepout.xy):
                poses = self._clear_poses(poses, keepout, rel, rot, axis)
                lean = self._clear_poses(lean, keepout, rel, rot, axis) if lean else []
            tries += [(pose, rel, rot, axis) for pose in poses + lean]
        for k, ((xy, yaw, drop, tilt), rel, rot, axis) in enumerate(tries):
            turn = self._turn(yaw, tilt, axis)
            r_goal, moved = turn @ rot, rel @ turn.T
            tcp_xy = xy - box_centre(moved)
            low = underside(moved, self.release.underside_cell)
            z = surface_hint - float(low[:, 2].min()) if np.isfinite(surface_hint) else self._rest_height(obj, tcp_xy, low)
            bottom = z + float(moved[:, 2].min())
            if cavity is not None and bottom > cavity.rim - pl.rim_margin:
                last = PlanFailure(f"{obj} would rest on the rim ({(bottom - cavity.rim) * 1000:+.0f} mm)")
                continue
            goal = np.array([*tcp_xy, z + drop])
            at_goal = self._ik(goal, r_goal, self.data.ctrl[self.act].copy())
            if not at_goal.converged:
                last = PlanFailure(f"release pose {np.round(goal, 3).tolist()} unreachable")
                continue
            try:
                above = goal + np.array([0, 0, pl.approach_height])  # the way down is checked before the arm moves: a blocked one costs no time
                q_above, down = self._checked_line(above, goal, r_goal, at_goal.q, {obj})
                self._transit(above, r_goal, skip=obj, below_tcp=-float(moved[:, 2].min()), q_goal=q_above)
                self._follow(down)  # the arm and the held object shove nothing on the way down
                break
            except PlanFailure as exc:
                last = exc
        else:
            raise PlanFailure(f"no release pose reachable ({len(tries)} tried: spots, hand yaws, tilts, heights; last: {last})")
        if self._slipped(obj):
            self.held = None
            return ActionResult(name, False, f"{obj} slipped out of the hand on the way", values={"release_pose": k})
        if not tilt:
            self._stand(obj)
        self._let_go([*down[::-1], q_above])
        self._wait(pl.release_wait)
        dof = self.model.jnt_dofadr[self.model.body(obj).jntadr[0]]
        resting = float(np.abs(self.data.qvel[dof:dof + 3]).max()) < pl.rest_speed
        settle_end = self.data.time + pl.max_rock  # a released object may rock a little before it rests
        while not resting and self.data.time < settle_end:
            self._wait(pl.rock_step)
            resting = float(np.abs(self.data.qvel[dof:dof + 3]).max()) < pl.rest_speed
        verdict = judge()
        values = {"object_xy": self._centre_xy(obj).tolist(), "target_xy": np.asarray(xy).tolist(), "release_pose": k,
                  "release_yaw": yaw, "release_tilt": tilt, "release_drop": drop, "measured": verdict.measured, "resting": resting}
        ok = verdict.ok and resting
        reason = "" if ok else (f"not {_WORDS[name]} after release: {verdict.measured}" if not verdict.ok else "object still moving")
        return ActionResult(name, ok, reason, values=values)

    def _let_go(self, way_up: list[np.ndarray]) -> None:
        """Open and back off. A handle's fingers open only enough to free it and leave its loop the
        way they came in (opened wide or lifted, the finger inside the loop tips the object over);
        other pinches open fully and lift: straight up as high as the arm reaches, else back up
        ``way_up`` (the joint path the hand came down, checked on the way down)."""
        pl = self.params.place
        kind, width = self.pinch
        self.held, self.pinch = None, ("", 0.0)
        pos, rot = self.tcp_pose()
        if kind == "handle":
            self._gripper(close_ctrl(self.model, self.grip_act, width + pl.handle_free, 0.0))
            try:
                self._straight(pos - rot[:, 2] * pl.handle_back)
            except PlanFailure:
                pass
            pos, _ = self.tcp_pose()
            way_up = []  # the way down ran through the loop
        self._gripper(GRIPPER_OPEN_CTRL)
        for up in (pl.retreat, pl.approach_height / 2):
            try:
                self._straight(pos + np.array([0, 0, up]))
                return
            except PlanFailure:
                continue
        if way_up:
            self._follow(way_up)

    def _upright(self, obj: str) -> np.ndarray | None:
        """The turn of the hand (world rotation) that sets the held ``obj`` up as it stood before the
        grasp, when it hangs tilted further than ``stand_tilt`` in the hand; else None."""
        up0 = self.stood.get(obj)
        if up0 is None or self._tilt(obj) <= self.params.place.stand_tilt:
            return None
        up = self._up(obj)
        axis = np.cross(up, up0)
        return rotate_about(axis, float(np.arctan2(np.linalg.norm(axis), up @ up0)))

    def _tilt(self, obj: str) -> float:
        """How far (rad) the held ``obj`` is tilted from how it stood before it was grasped."""
        up0 = self.stood.get(obj)
        return 0.0 if up0 is None else float(np.arccos(np.clip(self._up(obj) @ up0, -1.0, 1.0)))

    def _stand(self, obj: str) -> None:
        """Lower the hand while the held ``obj`` hangs tilted in it (swung in the pinch while carried)
        until it stands on what lies below it as it stood before the grasp: released tilted, it
        topples. Stops when it no longer comes upright, or at ``stand_reach`` below the release pose."""
        pl = self.params.place
        tilt, lowered = self._tilt(obj), 0.0
        while tilt > pl.stand_tilt and lowered < pl.stand_reach:
            pos, _ = self.ik.fk(self.data.ctrl[self.act].copy())
            try:
                self._straight(pos - np.array([0.0, 0.0, pl.stand_step]), clear_but={obj})
            except PlanFailure:
                return
            lowered += pl.stand_step
            now = self._tilt(obj)
            if now > tilt - pl.stand_gain and self.geometry.touching(obj) - {relations.ROBOT}:
                return  # it rests on something and no longer rights itself: pressing further shoves it
            tilt = now

    @staticmethod
    def _turn(yaw: float, tilt: float, axis: np.ndarray) -> np.ndarray:
        """The hand's change of orientation for a release: ``yaw`` about the vertical, then the
        object's long ``axis`` (xy, turned with it) tipped by ``tilt`` (its + end down)."""
        turn = rotate_about(np.array([0.0, 0.0, 1.0]), yaw)
        if tilt:
            u = turn @ np.array([axis[0], axis[1], 0.0])
            turn = rotate_about(np.cross([0.0, 0.0, 1.0], u), tilt) @ turn
        return turn

    def _rest_height(self, obj: str, tcp_xy: np.ndarray, low: np.ndarray) -> float:
        """tcp height at which the object's underside ``low`` (points relative to the tcp) first
        meets what lies below it with the tcp over ``tcp_xy``."""
        floors = self.geometry.surfaces_below(tcp_xy + low[:, :2], self._tallest(obj) + self.params.place.surface_probe, exclude=obj)
        if not np.isfinite(floors).any():
            return self.surface_below(tcp_xy, self._tallest(obj) + self.params.place.surface_probe, exclude=obj) - float(low[:, 2].min())
        return float(np.max(floors - low[:, 2]))

    def _lean_poses(self, obj: str, rel: np.ndarray, axis: np.ndarray, cavity: Cavity) -> list[Pose]:
        """Tipped releases into a container for an object longer than its opening: the low end
        past the opening's centre, the object's mass over the opening (it slides in, leaning on
        the rim), the ones that leave its centre lowest (least fall onto the rim) first; none when
        the container is lighter than the object (it would tip over)."""
        if footprint_radius(rel) <= cavity.radius or self._mass(obj) > self._mass(cavity.name):
            return []  # it fits lying flat, or leaning on the rim it would tip a lighter container over
        scored: list[tuple[int, float, Pose]] = []
        for tilt in self.release.tilts:
            for sign in (1.0, -1.0):
                for yaw in self.release.yaws[:3]:
                    turn = self._turn(yaw, sign * tilt, axis)
                    moved = rel @ turn.T
                    low = moved[int(np.argmin(moved[:, 2]))]
                    w = sign * (turn @ np.array([axis[0], axis[1], 0.0]))[:2]
                    w /= max(float(np.linalg.norm(w)), 1e-9)
                    for f in self.release.lean_reach:
                        tcp_xy = cavity.centre + w * f * cavity.radius - low[:2]
                        off = float(np.linalg.norm(tcp_xy + moved[:, :2].mean(axis=0) - cavity.centre))
                        if off < self.release.lean_mass * cavity.radius:
                            z = self._rest_height(obj, tcp_xy, underside(moved, self.release.underside_cell))
                            scored.append((0, z + float(moved[:, 2].mean()),
                                           (tcp_xy + box_centre(moved), yaw, self.release.drops[0], sign * tilt)))
        scored.sort(key=lambda t: t[:2])
        return [pose for _, _, pose in scored]

    def _mass(self, name: str) -> float:
        """Mass of object ``name`` with its attached parts (kg)."""
        return float(self.model.body_subtreemass[self._body(name)])

    def _slipped(self, obj: str) -> bool:
        """Whether no finger touches ``obj`` any more: it fell or swung out of the hand on the way."""
        return not self._contacts_with(obj)

    def _clear_poses(self, poses: list[Pose], keepout: Keepout, rel: np.ndarray, rot: np.ndarray, axis: np.ndarray) -> list[Pose]:
        """The release poses whose footprint (the object's, and the fingers' as they open) keeps
        ``keepout.margin`` to the other objects; all of them when none does and the keep-out is soft."""
        pl = self.params.place
        y, x = rot[:, 1], rot[:, 0]
        fingers = np.array([sy * pl.finger_reach * y + sx * pl.finger_half_width * x for sy in (-1.0, 1.0) for sx in (-1.0, 0.0, 1.0)])
        body = rel[:: max(1, len(rel) // pl.footprint_samples)]
        tree = cKDTree(keepout.xy)

        def fits(pose: Pose, foot: np.ndarray) -> bool:
            xy, yaw, _, tilt = pose
            turn = self._turn(yaw, tilt, axis)
            at = (foot @ turn.T)[:, :2] - box_centre(rel @ turn.T) + xy
            return bool(tree.query(at)[0].min() >= keepout.margin)
        with_fingers = np.vstack([body, fingers])
        clear = [pose for pose in poses if fits(pose, with_fingers)]
        if not clear and keepout.fingers_soft:
            clear = [pose for pose in poses if fits(pose, body)]
        if not clear and not keepout.soft:
            raise PlanFailure(f"no release pose leaves {keepout.margin * 1000:.0f} mm to the other objects ({len(poses)} tried)")
        kept: list[Pose] = (clear or poses)[: self.release.max_poses]
        return kept
