"""The functions a command program calls, bound to a :class:`Sim`'s robot.

Which functions exist comes from the registry (:mod:`realsim.planner.primitives`). They follow
the planner's contract (``prompts/planner_system.md``), which differs from the raw
:class:`Robot` methods in a few conveniences:

- ``place``/``place_on``/``place_in``/``place_beside``/``place_between``/``place_down`` grasp the
  object first when the hand does not hold it;
- ``place(obj, pos)``: ``pos`` is the target *centre*; its z is only a hint, the object is
  lowered onto whatever surface lies below ``pos``'s xy;
- ``push(obj, direction, distance)`` takes "left"/"right"/"forward"/"back" (as seen from the
  robot: rotated by its base yaw) or a world-frame xy vector;
- ``move_ee_to(pos, quat=None)``: None points the fingers straight down (keeping the yaw);
- ``object_pose`` returns plain lists: the live bounding-box centre and the quaternion (w,x,y,z).

Every robot action (including the grasp a place does first) is appended to :attr:`actions`.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from realsim.planner import primitives, relations
from realsim.planner.goals import DIRECTIONS, direction_in_world
from realsim.robot.ik import mat_to_quat
from realsim.robot.robot import ActionResult, Robot
from realsim.runtime.sim import Sim
from realsim.scene_format import jsonable


def carried(put: dict[str, str], obj: str) -> set[str]:
    """What ``put`` (object -> what it was put in or on) has in or on ``obj``, and in or on those in turn."""
    out: set[str] = set()
    todo = [obj]
    while todo:
        base = todo.pop()
        for o, t in put.items():
            if t == base and o not in out and o != obj:
                out.add(o)
                todo.append(o)
    return out


def _vec(value: Any, n: int, what: str) -> np.ndarray:
    try:
        arr = np.asarray(value, dtype=float).ravel()
    except (TypeError, ValueError):
        raise ValueError(f"{what} must be {n} numbers, got {value!r}") from None
    if arr.size != n or not np.all(np.isfinite(arr)):
        raise ValueError(f"{what} must be {n} finite numbers, got {value!r}")
    return arr


class ProgramAPI:
    """The primitives as the sandbox exposes them; ``actions`` records every robot action."""

    def __init__(self, sim: Sim):
        self.sim = sim
        self.actions: list[dict[str, Any]] = []
        self.put: dict[str, str] = {}  # object -> what this program put it in or on (a push of that may carry it along)

    @property
    def robot(self) -> Robot:  # the sim may be reset between runs: always the current robot
        return self.sim.robot

    def functions(self) -> dict[str, Callable[..., Any]]:
        """The program's functions, one per entry of the primitive registry."""
        return primitives.bind(self)

    def _record(self, res: ActionResult, call: str) -> ActionResult:
        self.actions.append({
            "call": call, "primitive": res.primitive, "success": bool(res.success), "reason": res.reason,
            "sim_time": round(float(res.sim_time), 4), "attempts": int(res.attempts),
            "values": _jsonable({k: v for k, v in res.values.items() if k != "log"}),
        })
        return res

    def _placed(self, res: ActionResult, obj: str, target: str | None) -> ActionResult:
        """Note where a place left ``obj`` (in or on ``target``, else on the table)."""
        self.put.pop(obj, None)
        if res.success and target is not None:
            self.put[obj] = target
        return res

    def _obj(self, name: Any) -> str:
        if not isinstance(name, str):
            raise ValueError(f"an object is named by a string, got {name!r}")
        names = self.sim.object_names()
        if name not in names:
            raise ValueError(f"no object named {name!r}; objects: {', '.join(names)}")
        return name

    # --- reading ------------------------------------------------------------------------------
    def object_names(self) -> list[str]:
        return list(self.sim.object_names())

    def object_pose(self, name: str) -> tuple[list[float], list[float]]:
        pos, quat = self.sim.object_pose(self._obj(name))
        return list(pos), list(quat)

    # --- actions ------------------------------------------------------------------------------
    def go_home(self) -> ActionResult:
        return self._record(self.robot.go_home(), "go_home()")

    def move_ee_to(self, pos: Sequence[float], quat: Sequence[float] | None = None) -> ActionResult:
        p = _vec(pos, 3, "pos")
        if quat is None:
            _, rot = self.robot.tcp_pose()
            yaw = float(np.arctan2(rot[1, 0], rot[0, 0]))  # keep the hand's yaw, fingers down
            down = np.array([[np.cos(yaw), np.sin(yaw), 0.0], [np.sin(yaw), -np.cos(yaw), 0.0], [0.0, 0.0, -1.0]])
            q = mat_to_quat(down)
        else:
            q = _vec(quat, 4, "quat")
            q = q / np.linalg.norm(q)
        return self._record(self.robot.move_ee_to(p, q), f"move_ee_to({np.round(p, 3).tolist()})")

    def open_gripper(self) -> ActionResult:
        return self._record(self.robot.open_gripper(), "open_gripper()")

    def close_gripper(self) -> ActionResult:
        return self._record(self.robot.close_gripper(), "close_gripper()")

    def grasp(self, obj: str) -> ActionResult:
        obj = self._obj(obj)
        if self.robot.held == obj and self.robot.holding(obj):
            return self._record(ActionResult("grasp", True, "already held", values={"lifted": None}), f"grasp({obj!r})")
        if self.robot.held and self.robot.held != obj:
            return self._record(ActionResult("grasp", False, f"the hand holds {self.robot.held}; place it first"), f"grasp({obj!r})")
        return self._placed(self._record(self.robot.grasp(obj), f"grasp({obj!r})"), obj, None)

    def _ensure_held(self, obj: str, name: str) -> ActionResult | None:
        """Grasp ``obj`` unless held; a failed grasp becomes the failure of primitive ``name``."""
        if self.robot.held == obj and self.robot.holding(obj):
            return None
        res = self.grasp(obj)
        if res.success:
            return None
        return ActionResult(name, False, f"could not grasp {obj}: {res.reason}", sim_time=res.sim_time, attempts=res.attempts)

    def _already(self, obj: str, target: str, name: str, relation: Callable[..., relations.Relation]) -> ActionResult | None:
        """A place whose end state already holds (``obj`` rests ``relation`` ``target`` and is not in
        the hand) does nothing: "put the block on the box" when it lies there moves nothing."""
        if self.robot.held == obj:
            return None
        rel = relation(self.robot.object_points(obj), self.robot.object_points(target), self.robot.geometry.touching(obj), target)
        if not rel.ok:
            return None
        res = self._record(ActionResult(name, True, f"{obj} already rests there: {rel.measured}"), f"{name}({obj!r}, {target!r})")
        return self._placed(res, obj, target)

    def place(self, obj: str, pos: Sequence[float]) -> ActionResult:
        obj = self._obj(obj)
        p = _vec(pos, 3, "pos")
        fail = self._ensure_held(obj, "place")
        if fail is not None:
            return fail
        target = np.array([p[0], p[1], np.nan])  # lowered onto whatever lies below
        return self._placed(self._record(self.robot.place(obj, target), f"place({obj!r}, {np.round(p, 3).tolist()})"), obj, None)

    def place_on(self, obj: str, target: str) -> ActionResult:
        obj, target = self._obj(obj), self._obj(target)
        if (done := self._already(obj, target, "place_on", relations.on)) is not None:
            return done
        fail = self._ensure_held(obj, "place_on")
        if fail is not None:
            return fail
        return self._placed(self._record(self.robot.place_on(obj, target), f"place_on({obj!r}, {target!r})"), obj, target)

    def place_in(self, obj: str, container: str) -> ActionResult:
        obj, container = self._obj(obj), self._obj(container)
        if (done := self._already(obj, container, "place_in", relations.inside)) is not None:
            return done
        if (full := self.robot.crowded(obj, container)) is not None:
            return self._record(ActionResult("place_in", False, full), f"place_in({obj!r}, {container!r})")  # said before grasping
        fail = self._ensure_held(obj, "place_in")
        if fail is not None:
            return fail
        return self._placed(self._record(self.robot.place_in(obj, container), f"place_in({obj!r}, {container!r})"), obj, container)

    def place_beside(self, obj: str, ref: str, side: str = "next") -> ActionResult:
        obj, ref = self._obj(obj), self._obj(ref)
        problem = primitives.value_problem("side", side)
        if problem is not None:
            raise ValueError(problem)
        fail = self._ensure_held(obj, "place_beside")
        if fail is not None:
            return fail
        side = side.strip().lower()
        return self._placed(self._record(self.robot.place_beside(obj, ref, side), f"place_beside({obj!r}, {ref!r}, {side!r})"), obj, None)

    def place_between(self, obj: str, a: str, b: str) -> ActionResult:
        obj, a, b = self._obj(obj), self._obj(a), self._obj(b)
        fail = self._ensure_held(obj, "place_between")
        if fail is not None:
            return fail
        return self._placed(self._record(self.robot.place_between(obj, a, b), f"place_between({obj!r}, {a!r}, {b!r})"), obj, None)

    def place_down(self, obj: str) -> ActionResult:
        obj = self._obj(obj)
        fail = self._ensure_held(obj, "place_down")
        if fail is not None:
            return fail
        return self._placed(self._record(self.robot.place_down(obj), f"place_down({obj!r})"), obj, None)

    def push(self, obj: str, direction: Any, distance: float) -> ActionResult:
        obj = self._obj(obj)
        if isinstance(direction, str):
            key = direction.strip().lower()
            key = primitives.DIRECTION_ALIASES.get(key, key)
            if key not in DIRECTIONS:
                raise ValueError(f"direction {direction!r}: use left, right, forward, back or [dx, dy]")
            d = np.array(direction_in_world(DIRECTIONS[key], self.sim.robot_yaw()), float)
        else:
            d = _vec(direction, 2, "direction")
            if np.linalg.norm(d) < 1e-9:
                raise ValueError("direction must not be zero")
        dist = float(distance)
        if not 0.0 < dist <= primitives.MAX_PUSH:
            raise ValueError(f"push distance {dist} m is out of range (0 to {primitives.MAX_PUSH:g} m)")
        if self.robot.held:
            return self._record(ActionResult("push", False, f"the hand holds {self.robot.held}; place it first"), f"push({obj!r})")
        return self._record(self.robot.push(obj, d, dist, carry=carried(self.put, obj)), f"push({obj!r}, {direction!r}, {dist:.3f})")

    def open_drawer(self, obj: str) -> ActionResult:
        obj = self._obj(obj)
        return self._record(self.robot.open_drawer(obj), f"open_drawer({obj!r})")

    def close_drawer(self, obj: str) -> ActionResult:
        obj = self._obj(obj)
        return self._record(self.robot.close_drawer(obj), f"close_drawer({obj!r})")


def _jsonable(value: Any) -> Any:
    """JSON-ready values for run logs (5 decimals)."""
    return jsonable(value, digits=5)
