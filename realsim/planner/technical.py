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
from typing import Any

__all__ = ["technical"]

_UNIT = r"(?:cm|mm|m|in|inch|inches|centimet(?:er|re)s?|millimet(?:er|re)s?|met(?:er|re)s?)"
_AMOUNT = rf"(?:about |around |roughly |approximately )?\d+(?:\.\d+)?\s*{_UNIT}"
_CENTRES = r"(?:cent(?:re|er)s?[\s-]*(?:to|-)[\s-]*cent(?:re|er)s?|apart|between cent(?:re|er)s|gap|clearance|spacing|separation|of (?:gap|clearance|spacing))"
_OFFSET = {"+x": "behind", "-x": "in front of", "+y": "to the left of", "-y": "to the right of"}
_SMALLER = ("smaller", "smallest", "lower", "lowest", "least", "minimum", "min")
_EXTREME = {(True, "y"): "on the right", (False, "y"): "on the left", (True, "x"): "nearest you", (False, "x"): "farthest from you"}
_REWRITES: tuple[tuple[str, Any], ...] = (
    # "2 in toward ...": inches when no object follows the "in" (never "2 in the bowl")
    (r"(?<=\d) ?in\.?(?=\s*(?:$|[,.;(]|(?:to|toward|towards|forward|forwards|back|backward|backwards|left|right|away|closer|nearer|further|farther|along|in the)\b))", " inch"),
    (r"\b(?:displace|reposition|re-position|re position|relocate)\b", "move"),
    (r"\b(?:elevate|hoist)\b", "lift"), (r"\b(?:transpose|interchange|exchange) (?:the )?(?:positions|places|locations) of\b", "swap"),
    (r"\b(?:to )?(?:a |the )?(?:position|location|place|point) (posterior|anterior) to\b", r"\1 to"),
    (r"\bposterior to\b", "behind"), (r"\banterior to\b", "in front of"), (r"\s+(?:laterally|longitudinally|linearly)\b", ""),
    (r",?\s*(?:and )?(?:maintain|keep|hold|retain) (?:the |its |a )?(?:grasp|grip|hold)(?: on it)?\b", ""),
    # "apply a planar displacement of +4 cm along the y axis to the can": move the can
    (r"\bapply (?:an? )?(?:planar |lateral |linear |small )?(?:displacement|translation|offset|shift|move) of (.+?) to ((?:the|that|this) [a-z ]+?)(?=$|[.,;])", r"move \2 \1"),
    # an axis said in words: "along the base frame's negative x axis", "in the robot's negative y direction"
    (r"\b(?:(?:along|in|toward|towards|on) )?(?:the )?(?:(?:base|robot|world)(?: frame)?(?: s|'s)? )?(positive|negative|\+|-) ?([xy])(?:[- ](?:axis|direction))\b",
     lambda m: f"{'+' if m.group(1) in ('positive', '+') else '-'}{m.group(2)}"),
    (rf"([+-])\s?(\d+(?:\.\d+)?\s*{_UNIT}) (?:along|in) (?:the )?([xy])(?:[- ](?:axis|direction))?\b", r"\2 \1\3"),
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
    # the primitives as an engineer names them: "execute a pick on X", "grasp target is X", "place pose inside Y"
    (r"\b(?:execute|perform|run|carry out|do|trigger|command) an? (?:(?:top[- ]down|overhead|vertical|side) )?(?:pick|grasp)(?: (?:on|of|for|at))?\b", "pick up"),
    (r"\b(?:execute|perform|run|carry out|do|trigger|command) an? (?:push|slide)(?: (?:on|of|for|at))?\b", "push"),
    (r"\b(?:the )?(?:grasp|pick|manipulation|grip) (?:target|object)(?: is|:| =)\s*", "pick up "),
    (r"\bput (?:the )?(?:place|placement|release|drop|goal|target) (?:pose|position|point|location)\b", "put it"),
    (r"(?:^|(?<=[.,;:] ))(?:the )?(?:place|placement|release|drop|goal) (?:pose|position|point|location)(?: (?:is|should be|=))?:?\s+", "put it "),
    (r",?\s*(?:clear of|away from|without touching|not touching|off) (?:the|its) (?:rim|edge|edges|lip|wall|walls)\b", " "),
    (r",?\s*\bso no (?:grasp|grasping|pick|picking|lift|lifting|lift-off)\b|\bno (?:grasp|grasping|pick|lift|lifting)\b\s*(?=[:,;])", ""),  # the push says how
    (r"\b(pick up|grab|lift|grasp) and (?=(?:place|put|set|drop|move|lay) (it|them)\b)", r"\1 \2 and "),  # "execute a pick and place it ..."
    (r"\b(?:the )?(table|counter|desk|bench)(?: ?(?:surface|top|plane))(?: surface)?\b", r"the \1"),
    (r",?\s*(?:wherever|where) there(?: s|'s| is)? (?:enough )?(?:clearance|room|space|free space|a free spot)\b", ""),
    # an offset along an axis from an object: "at a -x offset from the banana", "8 cm in +x from the cube"
    (rf"\b(?:at )?(?:an? )?(?:{_AMOUNT}\s+)?(?:(?:in|along|toward|towards|on the)\s+)?([+-])\s?([xy])(?:\s+(?:offset|direction|side|axis))?\s+(?:from|of|relative to|with respect to)\b",
     lambda m: _OFFSET[m.group(1) + m.group(2)]),
    # the end of a coordinate: "the one with the smaller y coordinate" is the rightmost
    (r"\b(?:with|having|at) (?:the )?(smaller|smallest|lower|lowest|least|minimum|min|larger|largest|bigger|biggest|higher|highest|greater|greatest|maximum|max)"
     r" ([xy])(?: (?:coordinate|value|position|coord))?\b", lambda m: _EXTREME[(m.group(1) in _SMALLER, m.group(2))]),
    # a placing said again as where it lands: "..., so it lands directly in front of it"
    (r",?\s*so (?:that )?(?:it|they) (?:lands?|ends? up|sits?|is|are|rests?|goes|go)\b[^.;,]*?\b(?:it|them)(?=$|[.;,])", ""),
    (r"\b(?:return|go|move|revert|reset)(?: back)? to (?:the )?nominal(?: (?:pose|position|config|configuration|state))?\b", "go home"),
    (r"\bhome (?:the (?:arm|robot|manipulator|gripper|end effector)|yourself)\b", "go home"),
    (r"\bstand ?by (?:at|in) (?:the |your )?home(?: (?:position|pose|config|configuration))?\b", "go home"),
    (r"\b(?:the )?robot(?: s|'s)? base\b", "the robot"),
    (r"\b(?:(?:its|the|your) )?(?:home|rest|ready|start) (?:configuration|config|pose|position)\b", "home position"),
    # "at the bowl's initial pose": where the bowl was
    (r"\b(?:at|to|in|into|on|onto) (?:the )?((?!(?:its|their|his|her|my|your)\b)[a-z]+(?: [a-z]+){0,2}?)(?:'s| s|s') (?:initial|original|starting|start|previous|old|former|prior)"
     r" (?:pose|position|location|spot|place|coordinates|xy)\b", r"where the \1 was"),
    # "a +0.04 m x-offset to the can": a move of the can along that axis
    (rf"\b(?:apply|give|impose|add) (?:an? )?([+-]?)\s?(\d+(?:\.\d+)?\s*{_UNIT}) ([xy])[- ]?(?:axis )?(?:offset|displacement|translation|shift|move) (?:to|on) ((?:the|that|this) [a-z ]+?)(?=$|[.,;]| via\b| by\b| with\b)",
     lambda m: f"move {m.group(4)} {m.group(2)} {m.group(1) or '+'}{m.group(3)}"),
    (r"\s+(?:via|by|using|with) (?:an? )?(?:planar |simple |lateral |gentle |non-prehensile |nonprehensile )?(?:push|pushing|slide|sliding)\b", " by pushing"),
    (r",?\s*(?:no|without) (?:grasp|grasping|pick|picking|lift|lifting|grip|gripping)(?: (?:is |are )?(?:required|needed|necessary|wanted))?(?=\s*(?:$|[.,;]))", ""),
    # "inside the white bowl frame": in the bowl (an object's frame is where it is)
    (r"\b(in|inside|into|on|onto|at|to|of) ((?:the|that|this) [a-z]+(?: [a-z]+){0,2}?) (?:frame|coordinate frame|reference frame)\b", r"\1 \2"),
    # the arm as the object of a move home: "return the arm to its home position" is going home
    (r"\b(?:return|move|bring|send|take) (?:the (?:arm|robot|gripper|hand|manipulator|end effector|end-effector|eef|ee|tcp|tool)|yourself|your arm)(?: back)?(?: to)? (?:the |your |its )?"
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
