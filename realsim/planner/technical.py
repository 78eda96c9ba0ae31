"""An engineer's phrasing, put in the words the planner reads: "displace" / "reposition" for
move, "approx." / "~" / "ca." for about, tolerances ("+/- 1 cm", "within 5 mm"), frames and
orientation ("in the robot frame", "no rotation"), a spacing after a place ("behind it, ~100 mm
centre to centre": the primitive keeps its own clearance), an amount restated in brackets ("4 in
(about 10 cm)": the first one said), "the robot base" for the robot and "the midpoint between".

Rule: only words that say how precisely, in which frame or how far apart a place is are dropped;
an object, a relation or the first amount of a move is never dropped.
"""

from __future__ import annotations

import re

__all__ = ["technical"]

_UNIT = r"(?:cm|mm|m|in|inch|inches|centimet(?:er|re)s?|millimet(?:er|re)s?|met(?:er|re)s?)"
_AMOUNT = rf"(?:about |around |roughly |approximately )?\d+(?:\.\d+)?\s*{_UNIT}"
_CENTRES = r"(?:cent(?:re|er)s?[\s-]*(?:to|-)[\s-]*cent(?:re|er)s?|apart|between cent(?:re|er)s|gap|clearance|spacing|separation|of (?:gap|clearance|spacing))"
_REWRITES: tuple[tuple[str, str], ...] = (
    # "2 in toward ...": inches when no object follows the "in" (never "2 in the bowl")
    (r"(?<=\d) ?in\.?(?=\s*(?:$|[,.;(]|(?:to|toward|towards|forward|forwards|back|backward|backwards|left|right|away|closer|nearer|further|farther|along|in the)\b))", " inch"),
    (r"\b(?:displace|reposition|re-position|re position)\b", "move"),
    (r"(?:(?<=\s)|^)(?:~|≈|approx\.?|ca\.|circa)\s*(?=\d)", "about "),
    (r"\b(?:approx\.?|approximately)(?=\s)", "about"),
    # a tolerance: "+/- 1 cm", "± 5 mm", "plus or minus 1 cm", "to within 1 cm", "give or take a cm"
    (rf",?\s*(?:\+\s*/\s*-|±|\+-|plus or minus|give or take|(?:to )?within|tolerance(?: of)?)\s*(?:about |a )?(?:\d+(?:\.\d+)?\s*)?{_UNIT}\b(?: or so)?", " "),
    # a spacing after a place: "behind it, ~100 mm centre to centre", "next to it with a 2 cm gap"
    (rf",?\s*(?:with )?(?:an? )?(?:{_AMOUNT})\s*{_CENTRES}\b", " "),
    # frames and orientation: the robot's frame is how every direction is read anyway
    (r",?;?\s*\b(?:in|w\.?r\.?t\.?|relative to|with respect to) (?:the )?(?:robot(?: s| base)?|base|world|table) (?:frame|coordinates?|coordinate frame|axes)\b", " "),
    (r"[,;]?\s*\b(?:no rotation|without (?:any )?rotation|(?:and )?(?:do not|dont|don t|without) (?:rotate|rotating|turn|turning)(?: it| them)?"
     r"|(?:and )?keep (?:its|the|their) (?:orientation|heading|yaw)(?: (?:fixed|the same|unchanged))?|orientation (?:unchanged|fixed|preserved))\b", " "),
    (r"\b(?:the )?robot(?: s|'s)? base\b", "the robot"),
    (r"\b(?:its|the|your) (?:home|rest|ready|start) (?:configuration|config|pose)\b", "home position"),
    # the arm as the object of a move home: "return the arm to its home position" is going home
    (r"\b(?:return|move|bring|send|take) (?:the (?:arm|robot|gripper|hand|manipulator)|yourself|your arm)(?: back)?(?: to)? (?:the |your |its )?"
     r"(?=(?:home|start|starting|rest|resting|ready|initial|original|default|neutral)\b)", "go back to the "),
    (r"\b(?:at|to) (?:the )?(?:midpoint|mid point|mid-point|halfway point|centre point|center point)(?: (?:of|between))?\b", "between"),
    (r"\b(?:midway|halfway|centred|centered) between\b", "between"),
)
# an amount restated in brackets: "4 in (about 10 cm)", "50 mm (5 cm)"
_RESTATED = re.compile(rf"(\d+(?:\.\d+)?\s*{_UNIT})\s*\(\s*(?:i\.?e\.?,?\s*|so |or |that is,?\s*|=\s*)?{_AMOUNT}\s*\)")


def technical(text: str) -> str:
    """``text`` (lower case) with an engineer's phrasing in the planner's words (see the module)."""
    text = _RESTATED.sub(r"\1", text)
    for pattern, word in _REWRITES:
        text = re.sub(pattern, word, text)
    return re.sub(r"\s+([,.;])", r"\1", re.sub(r"[ \t]+", " ", text)).strip()
