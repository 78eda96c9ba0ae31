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
from realsim.robot.placing import release_poses
from realsim.robot.result import ActionResult, PlanFailure

__all__ = ["Keepout", "Release"]

_WORDS = {"place": "at the target", "place_on": "on the target", "place_in": "inside the target", "place_beside": "beside the target",
          "place_between": "between the targets", "place_down": "on the table"}


@dataclass(frozen=True)
class Keepout:
    """What a release must not touch: xy points of other objects, kept ``margin`` away; ``soft``:
    when no pose clears them, try the poses anyway (a crowded bowl)."""

    xy: np.ndarray
    margin: float = 0.01
    soft: bool = False


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
               judge: Callable[[], relations.Relation], keepout: Keepout | None = None) -> ActionResult:
        """Carry the held ``obj`` over the first reachable release pose (spot, hand yaw, height),
        lower it there, release, retreat; ``judge`` says whether the end state is what was asked."""
        if self.held != obj or not self.holding(obj):
            return ActionResult(name, False, f"{obj} is not held (grasp it first)")
        pl = self.params.place
        pts = self.object_points(obj)
        tcp, rot = self.tcp_pose()
        offset = self._centre_xy(obj) - tcp[:2]  # object centre relative to the tcp, turns with the hand
        below = tcp[2] - float(pts[:, 2].min())
        poses = release_poses(candidates, self.release, limit=keepout is None or not len(keepout.xy))
        if keepout is not None and len(keepout.xy):
            poses = self._clear_poses(poses, keepout, pts, tcp, rot, offset)
        last: PlanFailure | None = None
        for k, (xy, yaw, drop) in enumerate(poses):
            turn = rotate_about(np.array([0.0, 0.0, 1.0]), yaw)
            r_goal = turn @ rot
            surface = surface_hint if np.isfinite(surface_hint) else self.surface_below(xy, self._tallest(obj) + pl.surface_probe, exclude=obj)
            goal = np.array([*(xy - turn[:2, :2] @ offset), surface + below + drop])
            if not self._ik(goal, r_goal, self.data.ctrl[self.act].copy()).converged:
                last = PlanFailure(f"release pose {np.round(goal, 3).tolist()} unreachable")
                continue
            try:
                self._transit(goal + np.array([0, 0, pl.approach_height]), r_goal, skip=obj, below_tcp=below)
                self._straight(goal, r_goal, clear_but={obj})  # the arm and the held object shove nothing on the way down
                break
            except PlanFailure as exc:
                last = exc
        else:
            raise PlanFailure(f"no release pose reachable ({len(poses)} tried: spots, hand yaws, heights; last: {last})")
        if self._slipped(obj):
            self.held = None
            return ActionResult(name, False, f"{obj} slipped out of the hand on the way", values={"release_pose": k})
        self._gripper(GRIPPER_OPEN_CTRL)
        self.held = None
        pos, _ = self.tcp_pose()
        try:
            self._straight(pos + np.array([0, 0, pl.retreat]))
        except PlanFailure:
            pass
        self._wait(pl.release_wait)
        dof = self.model.jnt_dofadr[self.model.body(obj).jntadr[0]]
        resting = float(np.abs(self.data.qvel[dof:dof + 3]).max()) < pl.rest_speed
        settle_end = self.data.time + pl.max_rock  # a released object may rock a little before it rests
        while not resting and self.data.time < settle_end:
            self._wait(pl.rock_step)
            resting = float(np.abs(self.data.qvel[dof:dof + 3]).max()) < pl.rest_speed
        verdict = judge()
        values = {"object_xy": self._centre_xy(obj).tolist(), "target_xy": np.asarray(xy).tolist(), "release_pose": k,
                  "release_yaw": yaw, "release_drop": drop, "measured": verdict.measured, "resting": resting}
        ok = verdict.ok and resting
        reason = "" if ok else (f"not {_WORDS[name]} after release: {verdict.measured}" if not verdict.ok else "object still moving")
        return ActionResult(name, ok, reason, values=values)

    def _slipped(self, obj: str) -> bool:
        """Whether no finger touches ``obj`` any more: it fell or swung out of the hand on the way."""
        return not self._contacts_with(obj)

    def _clear_poses(self, poses: list[tuple[np.ndarray, float, float]], keepout: Keepout, pts: np.ndarray, tcp: np.ndarray,
                     rot: np.ndarray, offset: np.ndarray) -> list[tuple[np.ndarray, float, float]]:
        """The release poses whose footprint (the object's, and the fingers' as they open) keeps
        ``keepout.margin`` to the other objects; all of them when none does and the keep-out is soft."""
        pl = self.params.place
        y, x = rot[:2, 1], rot[:2, 0]
        fingers = np.array([sy * pl.finger_reach * y + sx * pl.finger_half_width * x for sy in (-1.0, 1.0) for sx in (-1.0, 0.0, 1.0)])
        foot = np.vstack([pts[:, :2] - tcp[:2], fingers])
        tree = cKDTree(keepout.xy)

        def turn_offset(yaw: float) -> np.ndarray:  # the object's centre relative to the tcp, turned
            c, s_ = np.cos(yaw), np.sin(yaw)
            turned: np.ndarray = offset @ np.array([[c, s_], [-s_, c]])
            return turned

        def fits(pose: tuple[np.ndarray, float, float]) -> bool:
            xy, yaw, _ = pose
            c, s_ = np.cos(yaw), np.sin(yaw)
            turned = foot @ np.array([[c, s_], [-s_, c]])
            at = turned - turn_offset(yaw) + xy
            return bool(tree.query(at[:: max(1, len(at) // pl.footprint_samples)])[0].min() >= keepout.margin)
        clear = [pose for pose in poses if fits(pose)]
        if not clear and not keepout.soft:
            raise PlanFailure(f"no release pose leaves {keepout.margin * 1000:.0f} mm to the other objects ({len(poses)} tried)")
        kept: list[tuple[np.ndarray, float, float]] = (clear or poses)[: self.release.max_poses]
        return kept
