"""Push: the closed hand, tilted so the fingertips lead, shoves an object along the table.

The stroke is planned and checked first (only the hand may touch the pushed object, which is
carried along with what rides on it), and a push that would shove the object into another is
refused.
"""

from __future__ import annotations

import functools
from collections.abc import Iterable

import numpy as np
from numpy.typing import ArrayLike

from realsim.planner import relations
from realsim.robot.grasps import frame_from, rotate_about
from realsim.robot.ik import IKResult
from realsim.robot.motion import Motion, PathBlocked, Solve
from realsim.robot.placing import footprint_ring
from realsim.robot.pushing import StrokeParams, first_contact, strokes
from realsim.robot.queries import box_centre, box_centre_3d
from realsim.robot.reach import ReachBound
from realsim.robot.result import ActionResult, PlanFailure

__all__ = ["PushSkill"]


class PushSkill(Motion):
    """push."""

    stroke = StrokeParams()

    @functools.cached_property
    def reach(self) -> ReachBound:
        """The arm's reach by geometry: a stroke it rules out needs no IK."""
        return ReachBound.of(self.ik)

    def push(self, obj: str, direction: ArrayLike, distance: float, max_sim_time: float | None = None,
             carry: Iterable[str] = ()) -> ActionResult:
        """Push ``obj`` horizontally along ``direction`` by ``distance`` with the closed fingers.
        What rests in or on ``obj`` rides along: only the objects named in ``carry`` may (the ones the
        command itself put there); another one riding on it is refused, as it would be moved too."""
        d = np.array([*np.asarray(direction, float)[:2], 0.0])
        d /= np.linalg.norm(d)
        pp = self.params.push

        def body() -> ActionResult:
            pts = self.object_points(obj)
            start_pos = box_centre_3d(pts)
            bottom = float(pts[:, 2].min())
            height = float(pts[:, 2].max()) - bottom
            z = bottom + min(pp.contact_height, height / 2) + pp.contact_lift
            if -pp.palm_clearance < bottom + height - (z + pp.palm_height) < pp.palm_catch:  # the palm would catch the top edge and press it down
                z = max(z, min(bottom + height + pp.palm_clearance - pp.palm_height, bottom + pp.max_contact_fraction * height))
            # the object's footprint swept along the push must not run into another object
            foot = pts[:: max(1, len(pts) // pp.footprint_samples), :2]
            riding = self._riding(obj, pts)
            stray = sorted(riding - set(carry))
            if stray:
                return ActionResult("push", False, f"{', '.join(stray)} {'rests' if len(stray) == 1 else 'rest'} on {obj}: pushing {obj} "
                                    f"would carry {'it' if len(stray) == 1 else 'them'} along; take {'it' if len(stray) == 1 else 'them'} "
                                    "off first or say to push both", values={"moved": 0.0})
            others = self._others(obj, skip=riding, above=bottom + pp.ride_margin)
            # the asked stroke, else a shorter or askew one that still ends within the asked move's tolerance
            options = [(u, length) for i, (u, length) in enumerate(strokes(d[:2], distance, self.stroke))  # another stroke touches nothing at all
                       if first_contact(foot, others, u, length, pp.touch_gap, pp.sweep_step, pp.nudge if i == 0 else 0.0) is None]
            if not options:
                hit = first_contact(foot, others, d[:2], distance, pp.touch_gap, pp.sweep_step, pp.nudge)
                assert hit is not None
                return ActionResult("push", False, f"pushing {obj} {distance * 100:.0f} cm would shove "
                                    f"{self._owner_of_xy(obj, others[hit[1]], bottom)} (after {hit[0] * 100:.0f} cm), "
                                    "and no shorter or askew push within the asked move's tolerance clears it", values={"moved": 0.0})
            judged = self._stays_on(obj, pts, np.zeros(2))  # it stands level on one surface now: where the stroke leaves it can be judged
            on_support = [(u, length) for u, length in options if not judged or self._stays_on(obj, pts, u * length)]
            if not on_support:
                return ActionResult("push", False, f"pushing {obj} {distance * 100:.0f} cm would take it over the edge of what it "
                                    "stands on, and no shorter or askew push within the asked move's tolerance keeps it there",
                                    values={"moved": 0.0})
            options = on_support
            self._gripper(0.0)
            pushed = {obj, *riding}
            failures: list[PlanFailure] = []
            solved: dict[tuple[float, ...], IKResult] = {}  # contact IK per (contact, hand rotation): strokes of one direction share it
            planned: tuple[np.ndarray, np.ndarray, list[np.ndarray]] | None = None
            for zc in self._contact_heights(pts, z, d):  # higher only when no stroke at the usual height can be made
                for u, length in options:
                    try:
                        planned = (np.array([*u, 0.0]), *self._plan_stroke(pts, zc, np.array([*u, 0.0]), length, pushed, solved))
                        break
                    except PlanFailure as exc:
                        failures.append(exc)
                if planned is not None:
                    break
            if planned is None:
                raise _refusal(failures)
            ds, rot, stroke = planned
            self._follow(stroke)  # the checked stroke itself, forearm clear of the pushed object
            pos, _ = self.tcp_pose()
            up = np.array([0, 0, pp.retreat_up])
            q_now = self.data.ctrl[self.act].copy()
            cmd_pos, _ = self.ik.fk(q_now)
            for retreat in (pos - ds * pp.retreat_back + up, pos + up, pos - ds * pp.retreat_back):
                try:  # back off the object; the push itself is judged by how far the object moved
                    self._follow(self._line(cmd_pos, retreat, rot, rot, q_now, solve=lambda p, r, q: self._ik_clear(p, r, q, (), pushed)))
                    break
                except PlanFailure:
                    continue
            self._wait(pp.rest_wait)
            end_pos = box_centre_3d(self.object_points(obj))
            moved = float((end_pos - start_pos) @ d)
            verdict = relations.moved(start_pos, end_pos, d[:2], distance)  # the same test as the goal check
            return ActionResult("push", verdict.ok, "" if verdict.ok else verdict.measured, values={"moved": moved, "measured": verdict.measured})
        return self._run("push", body, max_sim_time)

    def _contact_heights(self, pts: np.ndarray, z: float, d: np.ndarray) -> list[float]:
        """The contact height ``z``, then higher ones (``reach_lifts``): a contact higher up keeps the
        wrist higher, within reach further out. Each stays below ``max_contact_fraction`` of the
        object's height and ``tip_ratio`` times its half length along the push ``d`` (pushed
        higher, friction at its foot could tip it), and clear of the palm catching its top edge."""
        pp = self.params.push
        bottom, top = float(pts[:, 2].min()), float(pts[:, 2].max())
        half = 0.5 * float(np.ptp(pts[:, :2] @ d[:2]))
        cap = bottom + min(pp.max_contact_fraction * (top - bottom), pp.tip_ratio * half)
        lifted = [z + lift for lift in pp.reach_lifts if z + lift <= cap]
        return [z, *(zc for zc in lifted if not -pp.palm_clearance < top - (zc + pp.palm_height) < pp.palm_catch)]

    def _riding(self, obj: str, pts: np.ndarray) -> set[str]:
        """What rests in or on ``obj`` (points ``pts``) and rides along a push: touching it, centred
        over its footprint, its bottom not below ``obj``'s (a mug in a bowl stands about as low as
        the bowl); what ``obj`` itself rests on starts lower, under it, and does not ride."""
        lo, hi = pts[:, :2].min(axis=0), pts[:, :2].max(axis=0)
        bottom = float(pts[:, 2].min()) - self.params.push.ride_margin
        out = set()
        for n in self.geometry.touching(obj) - {relations.WORLD, relations.ROBOT}:
            p = self.object_points(n)
            c = box_centre(p)
            if np.all((c >= lo) & (c <= hi)) and float(p[:, 2].min()) > bottom:
                out.add(n)
        return out

    def _stays_on(self, obj: str, pts: np.ndarray, shift: np.ndarray) -> bool:
        """Whether ``obj`` (points ``pts``) moved by the xy ``shift`` still stands on the surface it
        stands on now under its footprint's inner ring (its centre of mass well over its support)."""
        sp = self.stroke
        bottom = float(pts[:, 2].min())
        ring = footprint_ring(pts, frac=sp.support_fraction) + box_centre(pts) + shift
        floors = self.geometry.surfaces_below(ring, bottom + sp.level_probe, exclude=obj)
        return bool(np.all(np.abs(floors - bottom) < sp.level_tol))

    def _plan_stroke(self, pts: np.ndarray, z: float, d: np.ndarray, distance: float, pushed: set[str],
                     solved: dict[tuple[float, ...], IKResult]) -> tuple[np.ndarray, list[np.ndarray]]:
        """(hand rotation, checked joint path) of a stroke pushing ``pts`` by ``distance`` along
        ``d`` with the fingers at height ``z``, the arm moved to its start; raises PlanFailure.
        ``solved`` keeps the contact IK of earlier strokes (keyed by contact and rotation)."""
        pp = self.params.push
        centre = np.array([*pts[:, :2].mean(axis=0), z])
        contact = centre + d * (float(((pts - centre) @ d).min()) - pp.standoff)
        closing = np.array([-d[1], d[0], 0.0])
        # the closed hand is symmetric: of the two yaws, try the one nearer the current first
        _, now_rot = self.tcp_pose()
        # tilted so the fingertips lead and the palm trails: tall objects are pushed low, not tipped
        upright = [frame_from(np.array([0, 0, -1.0]), c) for c in (closing, -closing)]
        upright.sort(key=lambda r: -float(np.trace(now_rot.T @ r)))
        leaning = [[rotate_about(np.array([d[1], -d[0], 0.0]), t) @ r for r in upright] for t in (pp.tilt, 0.0, *pp.steep_tilts)]
        end = contact + d * (distance + pp.standoff)
        failures: list[PlanFailure] = []
        for rot in [r for group in leaning for r in group]:  # upright when the tilted hand cannot reach, steeper past a tall face
            try:  # the stroke is planned and checked first: only the hand may touch the pushed object
                past = max(self.reach.excess(contact, rot), self.reach.excess(end, rot))
                if past > 0:  # by geometry, before any IK: the wrist cannot stretch that far
                    raise PlanFailure(f"push end {np.round(end, 3).tolist()} out of reach (the wrist would be "
                                      f"{past * 100:.0f} cm past the arm's longest stretch)")
                key = tuple(np.round(np.concatenate([contact, rot.ravel()]), 5))
                if key not in solved:
                    solved[key] = self._ik_clear(contact, rot, np.array(self.ik.home), hand_may_touch=pushed)
                q_c = solved[key]
                if not q_c.converged:
                    raise PlanFailure(f"push contact {np.round(contact, 3).tolist()} unreachable ({q_c.reason})")
                if not self._ik(end, rot, q_c.q).converged:  # one solve rules out a stroke the arm cannot finish
                    raise PlanFailure(f"push end {np.round(end, 3).tolist()} out of reach")
                stroke = self._line(contact, end, rot, rot, q_c.q, solve=self._stroke_solve(pushed, contact, d))
                self._check_stroke(pushed, stroke, contact, d)
                self._transit(contact, rot, skip=None, q_goal=q_c.q)
                return rot, stroke
            except PlanFailure as exc:
                failures.append(exc)
        # the reason to give: a hand pose that reaches but whose arm would touch something says more than one out of reach
        raise next((f for f in failures if isinstance(f, PathBlocked)), failures[0] if failures else PlanFailure("no push pose"))

    def _pushed_by(self, pushed: set[str], tcp: np.ndarray, contact: np.ndarray, d: np.ndarray) -> dict[str, np.ndarray]:
        """Where the ``pushed`` objects are (xyz offsets) once the tcp, from ``contact``, is at ``tcp``."""
        shift = d * max(0.0, float((tcp - contact) @ d) - self.params.push.standoff)
        return {n: shift for n in pushed}

    def _stroke_solve(self, pushed: set[str], contact: np.ndarray, d: np.ndarray) -> Solve:
        """IK along a push stroke: no link but the hand touches the pushed objects where they will be."""
        return lambda pos, rot, q: self._ik_clear(pos, rot, q, (), pushed, self._pushed_by(pushed, pos, contact, d))

    def _check_stroke(self, pushed: set[str], path: list[np.ndarray], contact: np.ndarray, d: np.ndarray) -> None:
        """Raise PlanFailure when a link other than the hand would touch the ``pushed`` objects (the
        object and what rides in or on it, carried along once the fingers reach it) or the arm
        any other object, along the push ``path``."""
        for q in path:
            hits = self.geometry.robot_hits(self.qadr, q, (), pushed, self.hand_bodies, self._pushed_by(pushed, self.ik.fk(q)[0], contact, d))
            if hits:
                raise PathBlocked(f"the arm would touch {', '.join(sorted(hits))} while pushing")


def _refusal(failures: list[PlanFailure]) -> PlanFailure:
    """Why no stroke can be made: the first stroke's reason (the one asked, or the nearest to
    it), and when only another stroke reached the object, what stopped that one."""
    if not failures:
        return PlanFailure("no push pose")
    first = failures[0]
    blocked = next((f for f in failures[1:] if isinstance(f, PathBlocked)), None)
    if isinstance(first, PathBlocked) or blocked is None:
        return first
    return PlanFailure(f"{first}; a shorter or askew stroke: {blocked}")
