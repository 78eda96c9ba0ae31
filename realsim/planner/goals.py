"""Goal predicates checked in the simulation after a command ran, with their measured values.

Each goal is a small dataclass: :meth:`Goal.prepare` records what it needs before the program
runs (start poses), :meth:`Goal.evaluate` measures afterwards through a :class:`WorldView`.
Relations between objects (in, on, next to, a side of, between) are decided by
:mod:`realsim.planner.relations` on the objects' surface points and contacts when the world
provides them (a :class:`Sim`), else on their axis-aligned boxes.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from realsim.planner import relations

DIRECTIONS: dict[str, tuple[float, float]] = {
    "forward": (1.0, 0.0),
    "back": (-1.0, 0.0),
    "left": (0.0, 1.0),
    "right": (0.0, -1.0),
}
"""Named push directions in the robot's frame: forward is away from the robot's base, left is
the robot's left. :func:`direction_in_world` turns them into world xy vectors."""


def direction_in_world(direction: Sequence[float], robot_yaw: float) -> tuple[float, float]:
    """A robot-frame xy direction rotated by the robot base's yaw into the world frame."""
    c, s = math.cos(robot_yaw), math.sin(robot_yaw)
    return (c * direction[0] - s * direction[1], s * direction[0] + c * direction[1])


class GeometryView(Protocol):
    """Surfaces and contacts of the objects (a :class:`realsim.robot.world.SceneGeometry`)."""

    def points(self, name: str) -> np.ndarray: ...  # world-frame surface samples (N x 3)

    def touching(self, name: str) -> set[str]: ...  # "world", "robot" or object names in contact


class WorldView(Protocol):
    """What goals read from the simulation (world frame, metres)."""

    def object_pose(self, name: str) -> tuple[Sequence[float], Sequence[float]]: ...  # pos, quat wxyz

    def object_size(self, name: str) -> Sequence[float]: ...  # extents x, y, z

    def ee_pos(self) -> Sequence[float]: ...

    def at_home(self) -> bool: ...

    def joint_position(self, name: str) -> float: ...  # drawer opening (m) or door angle (rad)

    def robot_yaw(self) -> float: ...  # yaw of the robot's base in the world (rad)


@dataclass(frozen=True)
class GoalResult:
    """Whether a goal holds, and the numbers that decided it."""

    goal: str
    ok: bool
    measured: str

    def __str__(self) -> str:
        return f"[{'met' if self.ok else 'NOT met'}] {self.goal}: {self.measured}"


def _pos(world: WorldView, name: str) -> tuple[float, float, float]:
    p = world.object_pose(name)[0]
    return float(p[0]), float(p[1]), float(p[2])


def _size(world: WorldView, name: str) -> tuple[float, float, float]:
    s = world.object_size(name)
    return float(s[0]), float(s[1]), float(s[2])


@dataclass
class Goal:
    """Base class: a predicate over the world after the program ran."""

    def prepare(self, world: WorldView) -> None:
        """Record the state the goal compares against (called before the program runs)."""

    def describe(self) -> str:
        raise NotImplementedError

    def evaluate(self, world: WorldView) -> GoalResult:
        raise NotImplementedError


def _geometry(world: WorldView) -> GeometryView | None:
    """The simulation's surface/contact view when the world has one (a :class:`Sim` through its
    robot), else None: goals then judge on the bounding boxes alone."""
    geo = getattr(world, "geometry", None)
    if geo is None:
        geo = getattr(getattr(world, "robot", None), "geometry", None)
    return geo


def _shape(world: WorldView, name: str) -> tuple[np.ndarray, set[str] | None]:
    """Surface points of ``name`` and what it touches (None without contact information)."""
    geo = _geometry(world)
    if geo is not None:
        return geo.points(name), set(geo.touching(name))
    return relations.box_points(_pos(world, name), _size(world, name)), None


def _result(goal: Goal, rel: relations.Relation) -> GoalResult:
    return GoalResult(goal.describe(), rel.ok, rel.measured)


@dataclass
class Inside(Goal):
    """``obj`` rests in ``container`` (see :func:`realsim.planner.relations.inside`)."""

    obj: str
    container: str

    def describe(self) -> str:
        return f"{self.obj} inside {self.container}"

    def evaluate(self, world: WorldView) -> GoalResult:
        pts, touching = _shape(world, self.obj)
        return _result(self, relations.inside(pts, _shape(world, self.container)[0], touching, self.container))


@dataclass
class On(Goal):
    """``obj`` rests on top of ``support`` (see :func:`realsim.planner.relations.on`)."""

    obj: str
    support: str
    tolerance: float = 0.03  # m between the object's bottom and the support's top

    def describe(self) -> str:
        return f"{self.obj} on {self.support}"

    def evaluate(self, world: WorldView) -> GoalResult:
        pts, touching = _shape(world, self.obj)
        return _result(self, relations.on(pts, _shape(world, self.support)[0], touching, self.support, self.tolerance))


@dataclass
class NextTo(Goal):
    """``obj`` stands beside ``ref`` on the same surface, at most ``max_gap`` away."""

    obj: str
    ref: str
    max_gap: float = 0.10

    def describe(self) -> str:
        return f"{self.obj} next to {self.ref}"

    def evaluate(self, world: WorldView) -> GoalResult:
        pts, touching = _shape(world, self.obj)
        return _result(self, relations.next_to(pts, _shape(world, self.ref)[0], touching, self.max_gap))


SIDES: dict[str, str] = {"left": "left", "right": "right", "front": "back", "behind": "forward"}
"""Side words to robot-frame directions: "in front of" an object is toward the robot (the
robot faces the table, as the person giving the command is assumed to)."""


@dataclass
class SideOf(Goal):
    """``obj`` lies on one ``side`` ("left", "right", "front", "behind", as seen from the robot)
    of ``ref``, within ``max_gap`` of it."""

    obj: str
    ref: str
    side: str
    max_gap: float = 0.15

    def describe(self) -> str:
        words = {"left": "left of", "right": "right of", "front": "in front of", "behind": "behind"}
        return f"{self.obj} {words.get(self.side, self.side)} {self.ref}"

    def evaluate(self, world: WorldView) -> GoalResult:
        d = direction_in_world(DIRECTIONS[SIDES[self.side]], world.robot_yaw())
        pts, touching = _shape(world, self.obj)
        return _result(self, relations.side_of(pts, _shape(world, self.ref)[0], d, touching, self.max_gap))


@dataclass
class Between(Goal):
    """``obj`` lies between ``a`` and ``b``."""

    obj: str
    a: str
    b: str

    def describe(self) -> str:
        return f"{self.obj} between {self.a} and {self.b}"

    def evaluate(self, world: WorldView) -> GoalResult:
        pts, touching = _shape(world, self.obj)
        return _result(self, relations.between(pts, _shape(world, self.a)[0], _shape(world, self.b)[0], touching))


@dataclass
class OnTable(Goal):
    """``obj`` rests on the static surface (table, counter), out of the hand."""

    obj: str

    def describe(self) -> str:
        return f"{self.obj} on the table"

    def evaluate(self, world: WorldView) -> GoalResult:
        geo = _geometry(world)
        if geo is None:
            return GoalResult(self.describe(), False, "needs contact information (no simulation)")
        touching = set(geo.touching(self.obj))
        ok = relations.WORLD in touching and relations.ROBOT not in touching
        return GoalResult(self.describe(), ok, "touching " + (", ".join(sorted(touching)) or "nothing"))


@dataclass
class Placed(Goal):
    """``obj`` rests with its centre within ``tolerance`` of ``xy`` (world, m), out of the hand."""

    obj: str
    xy: tuple[float, float]
    tolerance: float = 0.04

    def describe(self) -> str:
        return f"{self.obj} put down at ({self.xy[0]:.3f}, {self.xy[1]:.3f})"

    def evaluate(self, world: WorldView) -> GoalResult:
        pts, touching = _shape(world, self.obj)
        c = (pts[:, :2].min(axis=0) + pts[:, :2].max(axis=0)) / 2
        err = float(np.hypot(c[0] - self.xy[0], c[1] - self.xy[1]))
        ok = err <= self.tolerance and (touching is None or (relations.ROBOT not in touching and bool(touching)))
        return GoalResult(self.describe(), ok, f"centre {err * 1000:.0f} mm from it (<= {self.tolerance * 1000:.0f})"
                          + ("" if touching is None else "; touching " + (", ".join(sorted(touching)) or "nothing")))


def _box_gap(a: tuple[np.ndarray, np.ndarray], b: tuple[np.ndarray, np.ndarray]) -> float:
    """Horizontal distance (m) between two xy boxes (lo, hi); 0 when they overlap."""
    d = np.maximum(0.0, np.maximum(b[0] - a[1], a[0] - b[1]))
    return float(np.hypot(d[0], d[1]))


def _xy_box(world: WorldView, name: str) -> tuple[np.ndarray, np.ndarray]:
    c, s = np.asarray(_pos(world, name)[:2]), np.asarray(_size(world, name)[:2])
    return c - s / 2, c + s / 2


@dataclass
class Aside(Goal):
    """``obj`` was moved out of the way: it rests out of the hand, clear of the footprint it
    started on (that spot is free) and at least ``min_gap`` from each of ``others``."""

    obj: str
    others: tuple[str, ...]
    min_gap: float = 0.02
    start: tuple[np.ndarray, np.ndarray] | None = field(default=None, compare=False)

    def describe(self) -> str:
        return f"{self.obj} moved out of the way (off its spot, {self.min_gap * 100:.0f} cm clear of the others)"

    def prepare(self, world: WorldView) -> None:
        self.start = _xy_box(world, self.obj)

    def evaluate(self, world: WorldView) -> GoalResult:
        _, touching = _shape(world, self.obj)
        box = _xy_box(world, self.obj)
        resting = touching is None or (relations.ROBOT not in touching and bool(touching))
        off = self.start is None or _box_gap(box, self.start) > 0.0
        gaps = {o: _box_gap(box, _xy_box(world, o)) for o in self.others}
        near = min(gaps, key=gaps.__getitem__) if gaps else None
        ok = resting and off and (near is None or gaps[near] >= self.min_gap)
        return GoalResult(self.describe(), ok, ("resting" if resting else "not resting") + ("; off its spot" if off else "; still on its spot")
                          + (f"; {gaps[near] * 100:.1f} cm from {near}" if near else ""))


@dataclass
class Moved(Goal):
    """``obj`` moved about ``distance`` m along the xy ``direction`` (a unit vector in the
    robot's frame: forward is away from the robot)."""

    obj: str
    direction: tuple[float, float]
    distance: float
    start: tuple[float, float, float] | None = field(default=None, compare=False)

    def describe(self) -> str:
        return f"{self.obj} moved {self.distance * 100:.0f} cm toward ({self.direction[0]:+.2f}, {self.direction[1]:+.2f})"

    def prepare(self, world: WorldView) -> None:
        self.start = _pos(world, self.obj)

    def evaluate(self, world: WorldView) -> GoalResult:
        if self.start is None:
            return GoalResult(self.describe(), False, "start position not recorded (prepare() was not called)")
        d = direction_in_world(self.direction, world.robot_yaw())
        return _result(self, relations.moved(self.start, _pos(world, self.obj), d, self.distance))


@dataclass
class Lifted(Goal):
    """``obj`` is at least ``min_height`` m above where it started."""

    obj: str
    min_height: float = 0.03
    start: tuple[float, float, float] | None = field(default=None, compare=False)

    def describe(self) -> str:
        return f"{self.obj} lifted"

    def prepare(self, world: WorldView) -> None:
        self.start = _pos(world, self.obj)

    def evaluate(self, world: WorldView) -> GoalResult:
        if self.start is None:
            return GoalResult(self.describe(), False, "start position not recorded (prepare() was not called)")
        rise = _pos(world, self.obj)[2] - self.start[2]
        return GoalResult(self.describe(), rise >= self.min_height, f"raised {rise:+.3f} m (>= {self.min_height:.3f})")


@dataclass
class DrawerOpen(Goal):
    """The articulated ``obj`` (drawer in m, door in rad) is open at least ``min_opening``."""

    obj: str
    min_opening: float = 0.05

    def describe(self) -> str:
        return f"{self.obj} open"

    def evaluate(self, world: WorldView) -> GoalResult:
        q = float(world.joint_position(self.obj))
        return GoalResult(self.describe(), q >= self.min_opening, f"opening {q:.3f} (>= {self.min_opening:.3f})")


@dataclass
class DrawerClosed(Goal):
    """The articulated ``obj`` is open at most ``max_opening``."""

    obj: str
    max_opening: float = 0.01

    def describe(self) -> str:
        return f"{self.obj} closed"

    def evaluate(self, world: WorldView) -> GoalResult:
        q = float(world.joint_position(self.obj))
        return GoalResult(self.describe(), q <= self.max_opening, f"opening {q:.3f} (<= {self.max_opening:.3f})")


@dataclass
class AtHome(Goal):
    """The robot is at its home posture."""

    def describe(self) -> str:
        return "robot at home"

    def evaluate(self, world: WorldView) -> GoalResult:
        ok = bool(world.at_home())
        e = world.ee_pos()
        return GoalResult(self.describe(), ok, f"end effector at ({float(e[0]):.3f}, {float(e[1]):.3f}, {float(e[2]):.3f})")


@dataclass
class Checkpoint:
    """A goal of a step that a later step undoes ("lift the can, then put it back"): prepared once
    the program's first ``start`` calls have run and checked once its first ``after`` calls have."""

    start: int
    after: int
    goal: Goal

    def describe(self) -> str:
        return f"{self.goal.describe()} (after call {self.after})"


def prepare_all(goals: Sequence[Goal], world: WorldView) -> None:
    """Record every goal's start state; call before running the program."""
    for g in goals:
        g.prepare(world)


def evaluate_all(goals: Sequence[Goal], world: WorldView) -> list[GoalResult]:
    """Evaluate every goal; an empty list means the goal is unknown (never report success)."""
    return [g.evaluate(world) for g in goals]


def verdict(results: Sequence[GoalResult]) -> str:
    """``"met"``, ``"not met"`` or ``"goal unknown"`` (no goals)."""
    if not results:
        return "goal unknown"
    return "met" if all(r.ok for r in results) else "not met"
