"""The place primitives: at a point, on, in (a body or a marked zone), beside, between, down."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from realsim.planner import relations
from realsim.planner.goals import DIRECTIONS, SIDES, direction_in_world
from realsim.robot.placing import cavity_centre, footprint_radius, footprint_ring, free_first, free_radius, narrowest, side_spots, spots, top_area
from realsim.robot.queries import box_centre
from realsim.robot.result import ActionResult
from realsim.robot.skills.release import Cavity, Keepout, Release

__all__ = ["PlaceSkills"]

_SIDE_WORDS = {"left": "left of", "right": "right of", "front": "in front of", "behind": "behind"}


def _turned(pts: np.ndarray, yaw: float) -> np.ndarray:
    """``pts`` turned by ``yaw`` about the vertical through their footprint's centre."""
    c, s_ = np.cos(yaw), np.sin(yaw)
    centre = np.array([*box_centre(pts), 0.0])
    turned: np.ndarray = (pts - centre) @ np.array([[c, s_, 0.0], [-s_, c, 0.0], [0.0, 0.0, 1.0]]) + centre
    return turned


def _on_table(touching: set[str]) -> relations.Relation:
    ok = relations.WORLD in touching and relations.ROBOT not in touching
    return relations.Relation(ok, "touching " + (", ".join(sorted(touching)) or "nothing"))


class PlaceSkills(Release):
    """place, place_on, place_in, place_beside, place_between, place_down."""

    def place(self, obj: str, pos: ArrayLike, tolerance: float | None = None, max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` down with its centre at ``pos`` (xy; z is found below it) and release
        (``tolerance``: how far from ``pos`` counts, default ``params.place.tolerance``)."""
        tol = self.params.place.tolerance if tolerance is None else tolerance

        def body() -> ActionResult:
            target = np.asarray(pos, float)
            r = footprint_radius(self.object_points(obj))
            near = spots(target[:2], min(tol, r), self.base_pos[:2], self.release.ring)
            return self._place(obj, near, target[2], "place", lambda: self._near(obj, target[:2], tol),
                               Keepout(self._others(obj), soft=True))
        return self._run("place", body, max_sim_time)

    def place_on(self, obj: str, target: str, max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` on top of body ``target`` (spots within its top face that keep the
        object's centre well inside it, its footprint and the fingers clear of what already lies
        there and of neighbours rising above that face, else its footprint alone: released over
        one, it lands on it and slides off, shoving both; no such spot, and nothing moves)."""
        pl = self.params.place

        def body() -> ActionResult:
            tp = self.object_points(target)
            centre, r_in = top_area(tp)
            near = spots(centre, max(r_in - footprint_radius(self.object_points(obj)) * pl.support_fraction, 0.0), self.base_pos[:2], self.release.ring)
            return self._place(obj, near, np.nan, "place_on", lambda: relations.on(
                self.object_points(obj), self.object_points(target), self.geometry.touching(obj), target),
                Keepout(self._others(obj, {target}, above=float(tp[:, 2].max()) - self.params.place.on_top_margin), fingers_soft=True))
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
            others = self._others(obj, {container}, above=float(cp[:, 2].min()) + self.params.place.in_bottom_margin)
            inside = others[np.linalg.norm(others - centre, axis=1) < r_in]  # what already lies in it: its free part first
            full = self.crowded(obj, container)
            if full is not None:
                return ActionResult("place_in", False, full)
            near = free_first(spots(centre, max(0.0, r_in - r), self.base_pos[:2], self.release.ring), inside)
            return self._place(obj, near, np.nan, "place_in", lambda: relations.inside(
                self.object_points(obj), self.object_points(container), self.geometry.touching(obj), container),
                Keepout(others, soft=True),
                cavity=Cavity(container, centre, r_in, float(cp[:, 2].max())))
        return self._run("place_in", body, max_sim_time)

    def crowded(self, obj: str, container: str) -> str | None:
        """Why ``obj`` cannot go into body ``container``, or None: what already lies in it rises to
        the rim and the largest free part of the opening is narrower than ``obj`` at its narrowest."""
        if self._zone(container) is not None:
            return None
        cp = self.object_points(container)
        centre, r_in = cavity_centre(cp)
        high = float(cp[:, 2].max()) - self.params.place.rim_margin
        blockers: dict[str, np.ndarray] = {}
        for n in self.object_names():
            p = self.object_points(n) if n not in (obj, container) else np.zeros((0, 3))
            p = p[(p[:, 2] > high) & (np.linalg.norm(p[:, :2] - centre, axis=1) < r_in), :2]
            if len(p):
                blockers[n] = p
        if not blockers:
            return None
        room, need = 2 * free_radius(centre, r_in, list(blockers.values())), narrowest(self.object_points(obj))
        if room >= need:
            return None
        held = sorted(blockers)
        return (f"{container} already holds {', '.join(held)}: the largest free part of its opening is {room * 100:.1f} cm across, "
                f"{obj} is {need * 100:.1f} cm at its narrowest")

    def place_beside(self, obj: str, ref: str, side: str = "next", gap: float | None = None,
                     max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` on the table beside ``ref``: ``side`` is "next" (any free side) or
        "left", "right", "front", "behind" as seen from the robot; the object's footprint at
        release must clear every other object (``gap``: default ``params.place.beside_gap``)."""
        pl = self.params.place
        gap_ = pl.beside_gap if gap is None else gap
        if side != "next" and side not in SIDES:
            return ActionResult("place_beside", False, f"unknown side {side!r}: use next, left, right, front or behind")

        def body() -> ActionResult:
            o, r = self.object_points(obj), self.object_points(ref)
            rc, oc = box_centre(r), box_centre(o)
            cands: list[tuple[float, float, np.ndarray, float]] = []
            if side == "next":
                for d in [np.array([np.cos(a), np.sin(a)]) for a in np.arange(8) * np.pi / 4]:
                    reach = float(((r[:, :2] - rc) @ d).max()) + float(((o[:, :2] - oc) @ -d).max()) + gap_
                    for extra in pl.beside_extra:
                        xy = rc + d * (reach + extra)
                        cands.append((extra, float(np.linalg.norm(xy - self.base_pos[:2])), xy, 0.0))
            else:
                d_side = np.asarray(direction_in_world(DIRECTIONS[SIDES[side]], self.base_yaw), float)
                for turn in pl.beside_turns:
                    cands += [(cost + pl.turn_cost * abs(turn), 0.0, xy, turn) for cost, xy in side_spots(_turned(o, turn), r, d_side, gap_, pl)]
            cands.sort(key=lambda t: (t[0], t[1]))
            level = float(r[:, 2].min())
            rings = {turn: footprint_ring(_turned(o, turn), frac=pl.support_fraction) for turn in {c[3] for c in cands}}
            near: list[tuple[np.ndarray, float]] = []
            for _, _, xy, turn in cands:
                if len(near) < self.release.max_poses and all(
                        abs(self.geometry.surface_below(xy + off, level + pl.level_probe, exclude=obj) - level) < pl.level_tol for off in rings[turn]):
                    near.append((xy, turn))
            if not near:
                return ActionResult("place_beside", False, f"no spot {'next to' if side == 'next' else _SIDE_WORDS[side]} {ref} "
                                    "on its surface (table edge)")
            side_d = None if side == "next" else direction_in_world(DIRECTIONS[SIDES[side]], self.base_yaw)

            def judge() -> relations.Relation:
                o_now, r_now, touching = self.object_points(obj), self.object_points(ref), self.geometry.touching(obj)
                return relations.next_to(o_now, r_now, touching) if side_d is None else relations.side_of(o_now, r_now, side_d, touching)
            return self._place(obj, [xy for xy, _ in near], np.nan, "place_beside", judge, Keepout(self._others(obj)),
                               turns=[turn for _, turn in near])
        return self._run("place_beside", body, max_sim_time)

    def place_between(self, obj: str, a: str, b: str, max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` on the table between objects ``a`` and ``b``."""
        pl = self.params.place

        def body() -> ActionResult:
            pa, pb = self.object_points(a), self.object_points(b)
            ca, cb = box_centre(pa), box_centre(pb)
            u = (cb - ca) / max(float(np.linalg.norm(cb - ca)), 1e-9)
            perp = np.array([-u[1], u[0]])
            t = (float(((pa[:, :2] - ca) @ u).max()) + float(((pb[:, :2] - ca) @ u).min())) / 2
            a_edge, b_edge = float(((pa[:, :2] - ca) @ u).max()), float(((pb[:, :2] - ca) @ u).min())
            along = [t] + [t + f * (b_edge - a_edge) for f in pl.between_along]
            cands = [ca + u * tt + perp * lat for lat in pl.between_lateral for tt in along]
            return self._place(obj, cands, np.nan, "place_between", lambda: relations.between(
                self.object_points(obj), pa, pb, self.geometry.touching(obj)), Keepout(self._others(obj), margin=pl.between_margin))
        return self._run("place_between", body, max_sim_time)

    def place_down(self, obj: str, max_sim_time: float | None = None) -> ActionResult:
        """Put the held ``obj`` down on the table (the static surface) at the free spot nearest
        the hand."""
        pl = self.params.place

        def body() -> ActionResult:
            o = self.object_points(obj)
            start = box_centre(o)
            cands = [start + rr * np.array([np.cos(a), np.sin(a)]) for rr in np.arange(0.0, pl.down_radius + pl.down_step / 3, pl.down_step)
                     for a in np.linspace(0, 2 * np.pi, max(1, int(round(rr / pl.down_step)) * 6), endpoint=False)]
            top = float(o[:, 2].max())
            ring = footprint_ring(o, frac=pl.support_fraction)
            near = [xy for xy in cands if all(self.geometry.surface_below(xy + off, top, exclude=obj)
                                              <= self.geometry.surface_below(xy + off, top, exclude=obj, static_only=True) + pl.table_tol for off in ring)]
            if not near:
                return ActionResult("place_down", False, f"no free table surface within {pl.down_radius * 100:.0f} cm of {obj}")
            near.sort(key=lambda xy: float(np.linalg.norm(xy - self.base_pos[:2])) > pl.down_reach)  # spots out of easy reach last
            return self._place(obj, near, np.nan, "place_down", lambda: _on_table(self.geometry.touching(obj)), Keepout(self._others(obj)))
        return self._run("place_down", body, max_sim_time)
