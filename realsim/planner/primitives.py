"""The one list of robot primitives a command program may call.

Each :class:`Primitive` holds its name, signature, the planner prompt's description of it, the
method of :class:`realsim.runtime.primitives.ProgramAPI` it is bound to and the
:class:`realsim.robot.Robot` method behind it. From this registry come the sandbox allowlist
(:data:`NAMES`), the runtime bindings (:func:`bind`) and the planner prompt's signature block
(:func:`prompt_block`, substituted for ``{primitives}`` in ``prompts/planner_system.md``), and
the typed parameters both checks use: the sandbox's static check of a program's calls and the
typed rule-planner program (:mod:`realsim.planner.program`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, TypeGuard

__all__ = ["BY_NAME", "DIRECTION_ALIASES", "DIRECTION_WORDS", "KINDS", "MAX_PUSH", "NAMES", "PLACEHOLDER", "PRIMITIVES", "SIDES", "Param", "Primitive",
           "bind", "prompt_block", "value_problem"]

PLACEHOLDER = "{primitives}"


SIDES: tuple[str, ...] = ("next", "left", "right", "front", "behind")
"""Where ``place_beside`` may put an object, as seen from the robot."""
DIRECTION_WORDS: tuple[str, ...] = ("left", "right", "forward", "back")
"""The named push directions (robot frame); ``push`` also takes a world-frame [dx, dy]."""
DIRECTION_ALIASES: dict[str, str] = {"backward": "back", "backwards": "back", "forwards": "forward"}
MAX_PUSH = 1.0  # m: the longest push a program may ask for

KINDS = ("object", "point", "quat", "side", "direction", "distance")
"""What a parameter takes: an object name, [x, y, z] m, (w, x, y, z) or None, a side word, a
direction word or [dx, dy], a distance in m (0 < d <= :data:`MAX_PUSH`)."""


@dataclass(frozen=True)
class Param:
    """One parameter of a primitive: its name, the :data:`KINDS` value it takes, and whether it
    may be left out (``default`` is then shown in the signature)."""

    name: str
    kind: str
    default: str | None = None

    def text(self) -> str:
        return self.name if self.default is None else f"{self.name}={self.default}"


@dataclass(frozen=True)
class Primitive:
    """One primitive: ``doc`` is its prompt text ("\\n" where the prompt wraps); entries sharing a
    ``group`` are documented on one line; ``binding``/``robot`` default to ``name``; ``query``
    primitives read the scene and return a value instead of acting; ``carries`` ones hold their
    first object in the hand."""

    name: str
    params: tuple[Param, ...]
    doc: str
    group: str = ""
    binding: str = ""
    robot: str = ""
    query: bool = False
    carries: bool = False

    @property
    def signature(self) -> str:
        """``(obj, pos)``: the parameters as the prompt shows them."""
        return "(" + ", ".join(p.text() for p in self.params) + ")"

    @property
    def api_method(self) -> str:
        """The :class:`ProgramAPI` method that implements it."""
        return self.binding or self.name

    @property
    def robot_method(self) -> str:
        """The :class:`Robot` method it ends in."""
        return self.robot or self.name

    def call(self) -> str:
        """The signature as the prompt shows it: ```name(args)```."""
        return f"`{self.name}{self.signature}`"

    def arity_problem(self, n_args: int, keywords: Sequence[str] = ()) -> str | None:
        """What is wrong with calling it with ``n_args`` positional arguments and ``keywords``, or None."""
        names = [p.name for p in self.params]
        if n_args > len(names):
            return f"{self.name}{self.signature} takes {len(names)} argument(s), got {n_args + len(keywords)}"
        for k in keywords:
            if k not in names:
                return f"{self.name}{self.signature} has no parameter {k!r}"
            if names.index(k) < n_args:
                return f"{self.name}{self.signature} got {k!r} twice"
        given = set(names[:n_args]) | set(keywords)
        missing = [p.name for p in self.params if p.default is None and p.name not in given]
        if missing:
            return f"{self.name}{self.signature} is missing {', '.join(missing)}"
        return None


def value_problem(kind: str, value: object) -> str | None:
    """What is wrong with ``value`` for a parameter of ``kind`` (None when it is fine)."""
    if kind == "object":
        return None if isinstance(value, str) and value else f"an object is named by a string, got {value!r}"
    if kind == "point":
        return None if _numbers(value, 3) else f"a position is [x, y, z] in m, got {value!r}"
    if kind == "quat":
        ok = value is None or (_numbers(value, 4) and any(v != 0 for v in value))
        return None if ok else f"a quaternion is (w, x, y, z) or None, got {value!r}"
    if kind == "side":
        return None if isinstance(value, str) and value.strip().lower() in SIDES else \
            f"side {value!r}: use {', '.join(repr(s) for s in SIDES)}"
    if kind == "direction":
        ok = (isinstance(value, str) and value.strip().lower() in (*DIRECTION_WORDS, *DIRECTION_ALIASES)) or (
            _numbers(value, 2) and any(v != 0 for v in value))
        return None if ok else f"direction {value!r}: use {', '.join(DIRECTION_WORDS)} or [dx, dy]"
    if kind == "distance":
        ok = isinstance(value, (int, float)) and not isinstance(value, bool) and 0.0 < value <= MAX_PUSH
        return None if ok else f"distance {value!r} m is out of range (0 to {MAX_PUSH:g} m)"
    raise ValueError(f"unknown parameter kind {kind!r}")


def _numbers(value: object, n: int) -> TypeGuard[Sequence[float]]:
    """``value`` is a list/tuple of ``n`` finite numbers."""
    return (isinstance(value, (list, tuple)) and len(value) == n
            and all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in value))


_OBJ = Param("obj", "object")
PRIMITIVES: tuple[Primitive, ...] = (
    Primitive("go_home", (), "move the arm to its home posture."),
    Primitive("move_ee_to", (Param("pos", "point"), Param("quat", "quat", "None")),
              "move the gripper's centre point (between the fingertips) to\n"
              "`pos` = [x, y, z] in m; `quat` = (w, x, y, z) orientation, or None for pointing straight down."),
    Primitive("open_gripper", (), "open fully / close the fingers.", group="gripper"),
    Primitive("close_gripper", (), "open fully / close the fingers.", group="gripper"),
    Primitive("grasp", (_OBJ,), "approach `obj` from above, close the gripper on it and lift it about 10 cm.", carries=True),
    Primitive("place", (_OBJ, Param("pos", "point")), "carry `obj` (grasping it first if needed) so its centre is over\n"
              "pos = [x, y, z] (m), lower it until it rests on whatever is below, release it, retreat.\n"
              "z only needs to be roughly right: the object is lowered until contact.", carries=True),
    Primitive("place_on", (_OBJ, Param("target", "object")), "put `obj` on top of the object `target` (stacking, a plate, a box);\n"
              "nothing moves when it already rests there.", carries=True),
    Primitive("place_in", (_OBJ, Param("container", "object")),
              "put `obj` inside the open container `container` (bowl, basket, bin);\n"
              "nothing moves when it already rests there.", carries=True),
    Primitive("place_beside", (_OBJ, Param("ref", "object"), Param("side", "side", '"next"')),
              "put `obj` on the table beside `ref`; `side` is \"next\" (any free\n"
              "side), \"left\", \"right\", \"front\" (toward the robot) or \"behind\" (away from it), as seen from the\n"
              "robot. A spot clear of other objects is chosen at run time.", carries=True),
    Primitive("place_between", (_OBJ, Param("a", "object"), Param("b", "object")), "put `obj` on the table between objects `a` and `b`.", carries=True),
    Primitive("place_down", (_OBJ,), "put `obj` down on the table at the free spot nearest the hand.", carries=True),
    Primitive("push", (_OBJ, Param("direction", "direction"), Param("distance", "distance")),
              "push `obj` along the table by `distance` m; `direction` is\n"
              "\"left\", \"right\", \"forward\", \"back\" or a unit vector [dx, dy] in the world xy plane."),
    Primitive("open_drawer", (_OBJ,), "open / close the drawer or door `obj`.", group="drawer"),
    Primitive("close_drawer", (_OBJ,), "open / close the drawer or door `obj`.", group="drawer"),
    Primitive("object_pose", (Param("name", "object"),), "-> `(pos, quat)`: the live position [x, y, z] (m) and orientation\n"
              "(w, x, y, z) of an object; use `pos[0]`, `pos[1]`, `pos[2]`.", query=True),
    Primitive("object_names", (), "-> list of the scene's object names.", query=True),
)
BY_NAME: dict[str, Primitive] = {p.name: p for p in PRIMITIVES}
NAMES: tuple[str, ...] = tuple(p.name for p in PRIMITIVES)


def prompt_block() -> str:
    """The prompt's primitive list: one ``- `name(args)`: doc`` item per primitive or group."""
    items: list[str] = []
    for k, p in enumerate(PRIMITIVES):
        if p.group and k and PRIMITIVES[k - 1].group == p.group:
            continue
        calls = [q.call() for q in PRIMITIVES if q.group == p.group] if p.group else [p.call()]
        sep = " " if p.doc.startswith("->") else ": "
        items.append(f"- {', '.join(calls)}{sep}{p.doc.replace(chr(10), chr(10) + '  ')}")
    return "\n".join(items)


def bind(api: Any) -> dict[str, Callable[..., Any]]:
    """name -> the bound method of ``api`` (a :class:`ProgramAPI`) for every primitive."""
    return {p.name: getattr(api, p.api_method) for p in PRIMITIVES}
