"""The one list of robot primitives a command program may call.

Each :class:`Primitive` holds its name, signature, the planner prompt's description of it, the
method of :class:`realsim.runtime.primitives.ProgramAPI` it is bound to and the
:class:`realsim.robot.Robot` method behind it. From this registry come the sandbox allowlist
(:data:`NAMES`), the runtime bindings (:func:`bind`) and the planner prompt's signature block
(:func:`prompt_block`, substituted for ``{primitives}`` in ``prompts/planner_system.md``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

__all__ = ["NAMES", "PLACEHOLDER", "PRIMITIVES", "Primitive", "bind", "prompt_block"]

PLACEHOLDER = "{primitives}"


@dataclass(frozen=True)
class Primitive:
    """One primitive: ``doc`` is its prompt text ("\\n" where the prompt wraps); entries sharing a
    ``group`` are documented on one line; ``binding``/``robot`` default to ``name``."""

    name: str
    signature: str
    doc: str
    group: str = ""
    binding: str = ""
    robot: str = ""

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


PRIMITIVES: tuple[Primitive, ...] = (
    Primitive("go_home", "()", "move the arm to its home posture."),
    Primitive("move_ee_to", "(pos, quat=None)", "move the gripper's centre point (between the fingertips) to\n"
              "`pos` = [x, y, z] in m; `quat` = (w, x, y, z) orientation, or None for pointing straight down."),
    Primitive("open_gripper", "()", "open fully / close the fingers.", group="gripper"),
    Primitive("close_gripper", "()", "open fully / close the fingers.", group="gripper"),
    Primitive("grasp", "(obj)", "approach `obj` from above, close the gripper on it and lift it about 10 cm."),
    Primitive("place", "(obj, pos)", "carry `obj` (grasping it first if needed) so its centre is over\n"
              "pos = [x, y, z] (m), lower it until it rests on whatever is below, release it, retreat.\n"
              "z only needs to be roughly right: the object is lowered until contact."),
    Primitive("place_on", "(obj, target)", "put `obj` on top of the object `target` (stacking, a plate, a box)."),
    Primitive("place_in", "(obj, container)", "put `obj` inside the open container `container` (bowl, basket, bin)."),
    Primitive("place_beside", "(obj, ref, side)", "put `obj` on the table beside `ref`; `side` is \"next\" (any free\n"
              "side), \"left\", \"right\", \"front\" (toward the robot) or \"behind\" (away from it), as seen from the\n"
              "robot. A spot clear of other objects is chosen at run time."),
    Primitive("place_between", "(obj, a, b)", "put `obj` on the table between objects `a` and `b`."),
    Primitive("place_down", "(obj)", "put `obj` down on the table at the free spot nearest the hand."),
    Primitive("push", "(obj, direction, distance)", "push `obj` along the table by `distance` m; `direction` is\n"
              "\"left\", \"right\", \"forward\", \"back\" or a unit vector [dx, dy] in the world xy plane."),
    Primitive("open_drawer", "(obj)", "open / close the drawer or door `obj`.", group="drawer"),
    Primitive("close_drawer", "(obj)", "open / close the drawer or door `obj`.", group="drawer"),
    Primitive("object_pose", "(name)", "-> `(pos, quat)`: the live position [x, y, z] (m) and orientation\n"
              "(w, x, y, z) of an object; use `pos[0]`, `pos[1]`, `pos[2]`."),
    Primitive("object_names", "()", "-> list of the scene's object names."),
)
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
