"""Goal predicates checked in the simulation after a command ran, with their measured values.

Each goal is a small dataclass: :meth:`Goal.prepare` records what it needs before the program
runs (start poses), :meth:`Goal.evaluate` measures afterwards through a :class:`WorldView`.
Extents from ``object_size`` are treated as axis-aligned (a tilted object is approximated).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Protocol

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


@dataclass
class Inside(Goal):
    """``obj``'s centre lies over ``container``'s footprint and its bottom below the rim."""

    obj: str
    container: str

    def describe(self) -> str:
        return f"{self.obj} inside {self.container}"

    def evaluate(self, world: WorldView) -> GoalResult:
        (px, py, pz), (cx, cy, cz) = _pos(world, self.obj), _pos(world, self.container)
        so, sc = _size(world, self.obj), _size(world, self.container)
        dx, dy = abs(px - cx), abs(py - cy)
        bottom, rim, floor = pz - so[2] / 2, cz + sc[2] / 2, cz - sc[2] / 2
        ok = dx <= sc[0] / 2 and dy <= sc[1] / 2 and bottom < rim - 0.005 and bottom > floor - 0.02
        measured = (
            f"xy offset ({dx:.3f}, {dy:.3f}) m within ({sc[0] / 2:.3f}, {sc[1] / 2:.3f}); "
            f"object bottom {bottom - floor:+.3f} m above the container bottom, rim at {rim - floor:.3f} m"
        )
        return GoalResult(self.describe(), ok, measured)


@dataclass
class On(Goal):
    """``obj`` rests on top of ``support``: centre over its footprint, bottom at its top."""

    obj: str
    support: str
    tolerance: float = 0.03  # m between the object's bottom and the support's top

    def describe(self) -> str:
        return f"{self.obj} on {self.support}"

    def evaluate(self, world: WorldView) -> GoalResult:
        (px, py, pz), (cx, cy, cz) = _pos(world, self.obj), _pos(world, self.support)
        so, sc = _size(world, self.obj), _size(world, self.support)
        dx, dy = abs(px - cx), abs(py - cy)
        gap = (pz - so[2] / 2) - (cz + sc[2] / 2)
        ok = dx <= sc[0] / 2 and dy <= sc[1] / 2 and abs(gap) <= self.tolerance
        measured = (
            f"xy offset ({dx:.3f}, {dy:.3f}) m within ({sc[0] / 2:.3f}, {sc[1] / 2:.3f}); "
            f"gap bottom-to-top {gap:+.3f} m (|gap| <= {self.tolerance:.3f})"
        )
        return GoalResult(self.describe(), ok, measured)


@dataclass
class NextTo(Goal):
    """``obj`` stands beside ``ref``: horizontal gap at most ``max_gap``, not on top of it."""

    obj: str
    ref: str
    max_gap: float = 0.10

    def describe(self) -> str:
        return f"{self.obj} next to {self.ref}"

    def evaluate(self, world: WorldView) -> GoalResult:
        (px, py, pz), (rx, ry, rz) = _pos(world, self.obj), _pos(world, self.ref)
        so, sr = _size(world, self.obj), _size(world, self.ref)
        dist = math.hypot(px - rx, py - ry)
        gap = dist - max(so[0], so[1]) / 2 - max(sr[0], sr[1]) / 2
        dz = (pz - so[2] / 2) - (rz - sr[2] / 2)
        ok = gap <= self.max_gap and dist > 0.5 * max(sr[0], sr[1]) and abs(dz) < 0.05
        measured = f"centres {dist:.3f} m apart, gap ~{gap:.3f} m (<= {self.max_gap:.2f}), bottoms differ {dz:+.3f} m"
        return GoalResult(self.describe(), ok, measured)


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
        p = _pos(world, self.obj)
        ux, uy = direction_in_world(self.direction, world.robot_yaw())
        dx, dy = p[0] - self.start[0], p[1] - self.start[1]
        along, across = dx * ux + dy * uy, abs(-dx * uy + dy * ux)
        tol = max(0.02, 0.4 * self.distance)
        ok = abs(along - self.distance) <= tol and across <= max(0.03, 0.5 * self.distance)
        measured = f"moved {along:.3f} m along (target {self.distance:.3f} +- {tol:.3f}), {across:.3f} m sideways"
        return GoalResult(self.describe(), ok, measured)


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
