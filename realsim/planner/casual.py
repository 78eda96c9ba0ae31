"""Casual speech, before it is read as a command: a light verb and its noun ("give the cube a
wee shove" -> "shove the cube a bit"), a particle after its object ("pick the mug up"), and terse
verbless commands ("cereal box forward 10cm", "all cans by bowl"), and a thing named by its look or
its use ("the tin-looking thing": the tin; "the thing you drink out of": the cup)."""

from __future__ import annotations

import re

__all__ = ["causative", "described", "light_verb", "terse"]

_NP = r"(?:the|that|this|these|those|a|an|my|your|it|them|both|all)\b(?:(?!\b(?:and|then|up|down|in|into|on|onto)\b)[^,.;])*?"
_AS_PUSH = {"tap": "nudge", "poke": "nudge"}
_SMALL_STROKE = re.compile(r"\b(?:wee|little|small|gentle|slight|tiny|light|soft|short)\b")  # a small stroke: a bit
_STROKE = r"(?:(?:wee|little|small|gentle|quick|slight|tiny|light|good|firm|soft|bit of a|short)\s+)*"


def light_verb(text: str) -> str:
    """A light verb and its noun as the verb they mean ("give the cube a shove" -> "shove the
    cube"), and a particle after the object back by its verb ("pick the mug up" -> "pick up the mug")."""
    text = re.sub(rf"\bgive ({_NP}) an? ({_STROKE})(shove|nudge|push|tap|poke|bump|scoot|budge|slide)\b(?=([^,.;]*))",
                  lambda m: f"{_AS_PUSH.get(m.group(3), m.group(3))} {m.group(1)}"
                  + (" a bit" if _SMALL_STROKE.search(m.group(2)) and not re.search(r"\d|\b(?:cm|mm|centimet|millimet|inch)", m.group(4)) else ""), text)
    return re.sub(rf"\b(pick|lift|hold|raise) ({_NP}) up\b", r"\1 up \2", text)


_WAY = r"(?:left|right|forwards?|backwards?|back|ahead|away|closer|nearer)"
# with an amount, a way may name the speaker ("an inch further away from me"); alone, "the thing closer to you" says which thing
_WAY_FROM = r"(?:left|right|forwards?|backwards?|back|ahead|(?:further |farther )?away(?: from (?:me|you|the robot))?|(?:closer|nearer)(?: to (?:me|you|the robot))?)"
_HOW_FAR = r"(?:(?:by )?(?:about |around |roughly )?(?:\d+(?:\.\d+)?|a couple of|a few|an?|one|two|three|four|five|six|seven|eight|nine|ten|twenty) ?(?:cm|mm|centimet\w*|millimet\w*|inch\w*)|a bit|a little(?: bit)?|slightly)"
# a bare object, a way and how far: "cereal box forward 10cm", "the mug 5 cm left"; never "the can on the left"
_TERSE_PUSH = re.compile(rf"((?:the |a |that |this )?[a-z]+(?: [a-z]+){{0,3}}?(?<!\bthe)(?<!\bto)(?<!\bon)(?<!\bat)(?<!\bof)(?<!\bfar))"
                         rf" ({_WAY}(?: {_HOW_FAR})?|{_WAY_FROM} {_HOW_FAR}|{_HOW_FAR} (?:to the )?{_WAY_FROM})")


def terse(clause: str, has_place: bool) -> str | None:
    """The command a verbless clause means, or None: an object, a way and how far ("bowl left
    6cm" -> "move bowl left 6cm"); an object and "up" ("mug up" -> "lift mug"); an object "by" another with no other place word ("all cans by
    bowl" -> "put all cans by bowl"). ``has_place``: whether the clause already names a place."""
    m = _TERSE_PUSH.fullmatch(clause)
    if m:
        return f"move {m.group(1)} {m.group(2)}"
    m = re.fullmatch(rf"((?:{_HOW_FAR} )?(?:(?:a )?(?:little |bit |tad |touch |hair |smidge )?(?:more |further |farther )?)?{_WAY_FROM}) with ((?:the|that|this) .+)", clause)
    if m:  # "a couple of centimetres closer to me with the soup can": the thing said last
        return f"move {m.group(2)} {m.group(1)}"
    m = re.fullmatch(r"((?:the |that |this )?[a-z]+(?: [a-z]+){0,3}?) up(?: high| in the air)?", clause)
    if m and not has_place:  # "mug up", "marker, up!": lift it
        return f"lift {m.group(1)}"
    if not has_place and re.fullmatch(r"(.+?) by (?!\d|about |around |roughly |a |hand\b)(.+)", clause):
        return f"put {clause}"
    return None


_THING = r"(?:thing|one|object|item)"
# what people do with a kind of thing -> the kind (its synonyms and kinds in vocab do the rest)
_FOOD = r"(?:(?:my|your|the|some|our|their|his|her) )?(?:(?:morning|evening|hot|cold) )?(?:[a-z]+ )?"  # "my morning coffee", "your cereal"
_USES = ((rf"(?:drink|sip) {_FOOD}(?:out of|from|in)", "cup"),
         (rf"eat {_FOOD}(?:out of|from|off|in)", "dish"),
         (r"write with|draw with", "marker"), (r"(?:drink|sip)", "drink"))
_HEADS = r"(?:thing|one|object|item|dish|container|box|bowl|cup|vessel)"


def described(text: str) -> str:
    """A thing named by its look ("the tall white tin-looking thing" -> "the tall white tin") or by
    its use ("the thing with the handle you drink out of" -> "the cup")."""
    text = re.sub(rf"\b([a-z]+)(?:[- ](?:looking|shaped)|-like) {_THING}\b", r"\1", text)
    for use, kind in _USES:
        text = re.sub(rf"\b{_HEADS}(?: with (?:a|the) handle)? (?:that |which )?(?:you|we|i|people|one)(?: ?'?d| would| can| could| usually| normally)? (?:{use})\b", kind, text)
    # "the box the breakfast flakes come in", "the box your breakfast comes out of": the cereal box
    return re.sub(r"\bbox (?:that |which )?(?:(?:my|your|the|our) )?(?:breakfast|cereal|flakes|breakfast flakes|corn ?flakes)(?: flakes)? (?:comes?|came|is kept|are kept)"
                  r" (?:out of|in)\b", "cereal box", text)


_WHO = r"((?:the|that|this|those|these|both|all)(?: (?!(?:across|to|of|in|on|at|from|with|over|into|by|for|through|past)\b)[a-z-]+){1,5}?|them|it|'?em)"
_CAUSE = r"\b(?:let|make|have|get|bid|tell|help|allow)"


def causative(text: str) -> str:
    """What people have something do, as the request ("let them trade places" -> "swap them", "have
    the cube go on the plate" -> "put the cube on the plate", "allow it to settle on the plate" -> "put
    it on the plate", "let the arm return to its resting place" -> "go home")."""
    text = re.sub(rf"{_CAUSE} (?:the arm|the robot|yourself|it) (?:to )?(?:return|go|head|come)(?: back)? (?:home|to (?:its|your|the) "
                  r"(?:resting|rest|home|starting|start) (?:place|position|pose|spot))\b", "go home", text)
    text = re.sub(rf"{_CAUSE} {_WHO} (?:[a-z]+ly )?(?:to )?(?:trade|swap|switch|exchange) (?:their |its )?(?:places|spots|positions|seats|squares)\b",
                  lambda m: f"swap {m.group(1).lstrip(chr(39))}", text)
    # "let it find the table": put on it; "let it float across, ...": carried, the place said next
    text = re.sub(rf"{_CAUSE} {_WHO} (?:to )?find ((?:the|its|their) (?:table|floor|counter|ground|place|spot))\b", lambda m: f"put {m.group(1).lstrip(chr(39))} on {m.group(2)}", text)
    text = re.sub(rf"{_CAUSE} {_WHO} (?:to )?(?:float|drift|glide|sail|fly) (?:across|over|along|up|through the air)(?=\s*(?:[,.;]|$| and\b| then\b))",
                  lambda m: f"lift {m.group(1).lstrip(chr(39))}", text)
    # "let it down onto the table", "help the can back down": lowered, where to said next
    text = re.sub(rf"\b(?:let|help|ease) {_WHO} (?:gently |slowly |softly )?(?:back )?down\b", lambda m: f"put {m.group(1).lstrip(chr(39))} down", text)
    # "let the mug drift back towards you three inches": how it moves
    text = re.sub(rf"{_CAUSE} {_WHO} (?:to )?(?:drift|float|glide|slide|ease|roll|travel|wander|go|move|come)(?= (?:back|forward|forwards|backwards|left|right|to the left|to the right|away|closer|toward|towards)\b)",
                  lambda m: f"move {m.group(1).lstrip(chr(39))}", text)
    return re.sub(rf"{_CAUSE} {_WHO} (?:to )?(?:go|move|sit|stand|end up|rest|come to rest|come to a rest|settle|settle down|land|drop|drift|float|glide|slide|hide|stay|come down)"
                  r"(?: (?:gently|softly|slowly|down|back|over|across|right))* (?=(?:in|into|inside|on|onto|next to|beside|behind|in front of|"
                  r"to the left of|to the right of|left of|right of|between|on top of|down on)\b)", lambda m: f"put {m.group(1).lstrip(chr(39))} ", text)

