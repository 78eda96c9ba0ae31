"""Clock-face directions, as pilots and sailors give them: 12 o'clock is straight ahead of the
robot, 3 o'clock its right, 6 o'clock toward it, 9 o'clock its left; and a ship's port,
starboard, fore and aft (:func:`nautical`).

"the soup can at your ten o'clock" names the thing whose bearing from the robot's base is nearest
ten o'clock; "slide it two inches toward your nine" is a push to the left; "the bowl's six o'clock
side" and "the nine o'clock side of the plate" are the sides in front of the bowl and left of the
plate. Hours between the four quarters go to the nearest quarter for a way or a side.
"""

from __future__ import annotations

import math
import re

__all__ = ["AT_CLOCK", "bearing_gap", "clock", "nautical"]

_HOURS = {w: i + 1 for i, w in enumerate("one two three four five six seven eight nine ten eleven twelve".split())}
_HOUR = r"(one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|1[0-2]|[1-9])"
_OCLOCK = r"(?:\s*o\s*'?\s*clock)"
_ISH = r"(?:\s*-?\s*ish)?"
_WAY = {12: "forward", 3: "to the right", 6: "back", 9: "to the left"}
_SIDE = {12: "behind", 3: "to the right of", 6: "in front of", 9: "to the left of"}
# a way to go follows what moves and how far: "slide it two inches toward your nine"
_MOVING = re.compile(r"\b(?:it|them|that|cm|mm|centimet\w*|millimet\w*|inch\w*|\d+|slide|push|shove|nudge|move|scoot|bring|shift|roll|drag)\W*$")
AT_CLOCK = re.compile(r"(.+?),? at clock (\d+)")


def _hour(word: str) -> int:
    return _HOURS.get(word) or int(word)


def _quarter(hour: int) -> int:
    """The nearest of 12, 3, 6 and 9 (1 and 11 are ahead, 2 and 4 right, ...)."""
    return {0: 12, 1: 3, 2: 6, 3: 9}[round((hour % 12) / 3) % 4]


def clock(text: str) -> str:
    """``text`` (lower case) with clock-face sides, ways and places in the planner's words."""
    # "on the mug's six, so just behind it": the pilots' "on your six" (behind, by the thing's own facing) is read by the
    # side the speaker spells out after it, never by the robot's clock face
    text = re.sub(r"\bon (?:the )?([a-z]+(?: [a-z]+)?)'?s (?:six|6)(?: o'?clock)?,? (?:(?:so|that is|i\.?e\.?|i mean|meaning|as in),? )?(?:just |right |directly )?"
                  r"(behind|in front of|to the left of|to the right of|left of|right of) (?:it|them)\b", r"\2 the \1", text)
    text = re.sub(rf"\b(?:on |to |at )?(?:the )?([a-z]+(?: [a-z]+)?)'?s {_HOUR}{_OCLOCK}?{_ISH} side\b",
                  lambda m: f"{_SIDE[_quarter(_hour(m.group(2)))]} the {m.group(1)}", text)
    text = re.sub(rf"\b(?:on |to |at )?the {_HOUR}{_OCLOCK}?{_ISH} side of\b", lambda m: _SIDE[_quarter(_hour(m.group(1)))], text)

    def way_or_place(m: re.Match[str]) -> str:
        said = m.group(0)
        if not (m.group(2) or m.group(4) or "toward" in said):
            return said  # "move it to two": no clock
        if _MOVING.search(text[: m.start()]):
            return f" {_WAY[_quarter(_hour(m.group(3)))]}"
        return f" at clock {_hour(m.group(3))}"

    text = re.sub(rf"\s+(toward|towards|to|round to|around to|up to|over to|in the direction of)\s+(your |my )?{_HOUR}({_OCLOCK}{_ISH})?\b",
                  way_or_place, text)
    text = re.sub(rf"(?:^|\s+)(?:(?:that is|which is|sitting|over|out|off|past|around|round|about|roughly|at|on|near)\s+)*(?:your |my )?{_HOUR}{_OCLOCK}{_ISH}",
                  lambda m: f" at clock {_hour(m.group(1))}", text)
    return re.sub(rf"\s+(?:(?:over|out|off|around|round|about|roughly|at|on)\s+)+your {_HOUR}\b", lambda m: f" at clock {_hour(m.group(1))}", text)


_SHIP = {"port": "left", "larboard": "left", "starboard": "right"}


def nautical(text: str) -> str:
    """A sailor's sides and ways in the robot's frame: port is its left, starboard its right, fore
    ahead (away from it), aft and astern back toward it ("to port o' the bowl", "drag it fore")."""
    text = re.sub(r"\b(?:to |toward |towards |over to )?(?:the )?(port|larboard|starboard)(?: side)?(?: (?:o'?|of) (?=the |th' |yon |that ))?",
                  lambda m: f"to the {_SHIP[m.group(1)]}" + (" of " if re.search(r"(?:o'?|of) $", m.group(0)) else ""), text)
    text = re.sub(r"\b(?:to )?(?:the )?(?:fore|forrard)\b", "forward", text)
    return re.sub(r"\b(?:to )?(?:the )?(?:aft|astern)\b", "back", text)


def bearing_gap(forward: float, left: float, hour: int) -> float:
    """How far (radians) a point at ``forward``/``left`` of the robot lies from ``hour`` o'clock."""
    bearing = math.atan2(-left, forward)  # clockwise from straight ahead
    gap = bearing - math.radians(30 * (hour % 12))
    return abs(math.atan2(math.sin(gap), math.cos(gap)))
