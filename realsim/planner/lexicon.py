"""The planner's closed word lists: command verbs and their particles, relation (place) words,
surfaces, and the patterns that find a verb or a place in a text; shared by the modules that
read a command so they never disagree on what a verb or a place is."""

from __future__ import annotations

import re

__all__ = ["AGAIN", "ALL_VERBS", "AVOID", "PARTICLES", "PUSH", "PUT", "RELATIONS", "RELATION_AT", "STATEMENT_VERB", "SURFACES", "TAKE", "VERB_ANYWHERE", "VERB_START",
           "has_relation", "relation_start"]

TAKE = ("pick up", "pick", "grab", "grasp", "take", "lift up", "lift", "raise", "get", "fetch", "hold up", "hold", "snag", "remove",
        "collect", "hand me", "give me", "pass me", "bring me", "show me", "retrieve", "gather up", "gather")
PUT = ("put back", "put down", "put", "place", "set down", "set", "drop", "stack", "insert", "transfer", "bring", "carry",
       "lay down", "lay", "position", "stick", "pop", "toss", "throw", "dump", "store", "stash", "leave", "relocate", "return",
       "move", "shift", "slide", "drag", "stand", "rest", "translate", "park", "plonk", "tuck", "haul", "lug", "sink", "butt", "line up", "line", "dock")
PUSH = ("push", "slide", "shove", "nudge", "move", "drag", "shift", "scoot", "bump", "roll", "pull", "budge", "translate", "kick", "tap", "retract")
ALL_VERBS = tuple(sorted(set(TAKE + PUT + PUSH + ("give", "hand", "pass") + ("open", "close", "shut", "go", "return", "reset", "release", "let go", "home",
                                                  "come", "head", "pull open", "pull out", "push in"))))
# a length said with its unit: "4 cm", "2.5 inches", "30mm" (inches as "in" only where nothing else can follow)
UNIT_WORDS = r"(?:cm|mm|inch\w*|centimet\w*|millimet\w*)"
MEASURE = rf"\d+(?:\.\d+)? ?{UNIT_WORDS}"
PARTICLES = r"(?:\s+(?:back|down|up|over|away|off|out|round|around|carefully|gently|again|too))*"

# "do that again", "repeat it", "once more": the last step again (a clause of its own)
AGAIN = re.compile(r"(?:do (?:that|it|this|so|the same)(?: thing)? (?:again|once more|one more time)|repeat(?: that| it| this)?(?: again)?"
                   r"|(?:and )?(?:once more|one more time|again))")

RELATIONS: tuple[tuple[str, str], ...] = (
    ("at the side of", "next"), ("by the side of", "next"), ("on either side of", "sides"), ("on both sides of", "sides"), ("on each side of", "sides"), ("to either side of", "sides"),
    ("either side of", "sides"), ("on opposite sides of", "sides"),
    ("at the left of", "left"), ("at the right of", "right"), ("on the far side of", "behind"), ("to the far side of", "behind"), ("on the near side of", "front"), ("to the near side of", "front"),
    ("on this side of", "front"), ("on the other side of", "other"), ("to the other side of", "other"), ("on the opposite side of", "other"),
    ("in front of", "front"), ("in back of", "behind"), ("at the back of", "behind"), ("to the back of", "behind"),
    ("upstage of", "behind"), ("downstage of", "front"),  # a stage seen from the robot: its audience
    ("to the front of", "front"), ("at the front of", "front"), ("to the left hand side of", "left"), ("to the left side of", "left"), ("on the left hand side of", "left"),
    ("to the right hand side of", "right"), ("to the right side of", "right"), ("on the right hand side of", "right"),
    ("closer to", "next"), ("nearer to", "next"), ("to the left of", "left"), ("on the left side of", "left"), ("on the left of", "left"), ("left of", "left"),
    ("to the right of", "right"), ("on the right side of", "right"), ("on the right of", "right"), ("right of", "right"),
    ("behind", "behind"), ("in between", "between"), ("between", "between"),
    ("right next to", "next"), ("next to", "next"), ("beside", "next"), ("besides", "next"), ("alongside", "next"),
    ("close to", "next"), ("nearby", "next"), ("near", "next"), ("by", "next"), ("against", "next"),
    ("on top of", "on"), ("onto", "on"), ("on to", "on"), ("on", "on"), ("atop", "on"), ("upon", "on"), ("over", "on"), ("above", "on"),
    ("inside of", "in"), ("inside", "in"), ("into", "in"), ("in", "in"), ("within", "in"),
    ("toward", "next"), ("towards", "next"), ("to", "to"),  # toward a thing is a way, not into it
)
SURFACES = r"(?:the )?(?:table|counter|countertop|desk|surface|tabletop|table top|worktop|work surface|bench|benchtop|floor|deck)(?: top)?"


def has_relation(text: str) -> bool:
    """Whether a relation word opens ``text`` or any of its word tails ("mug in the bowl")."""
    words = text.split()
    return any(relation_start(" ".join(words[i:])) for i in range(len(words)))


def relation_start(text: str) -> bool:
    """Whether ``text`` opens with a relation word ("in the bowl", "to the left of the box")."""
    words = sorted((w for w, _ in RELATIONS if w not in ("by", "over")), key=len, reverse=True)
    return bool(re.match(rf"(?:{'|'.join(re.escape(w) for w in words)})\b", text))


VERB_START = re.compile(rf"(?:{'|'.join(re.escape(v) for v in sorted(ALL_VERBS, key=len, reverse=True))})\b")
VERB_ANYWHERE = re.compile(rf"(?<![a-z]){VERB_START.pattern}")
RELATION_AT = re.compile(rf"(?<![a-z])(?:{'|'.join(re.escape(w) for w, _ in sorted(RELATIONS, key=lambda r: -len(r[0])) if w not in ('by', 'over'))})\b")

# a thing not to touch: "don't touch the mug", "... without hitting the bowl"
AVOID = re.compile(r"(?:^|\s+(?:but |and |while )?)(?:dont|don t|do not|never|try not to|avoid|(?:be )?careful not to|without)"
                    r" (?:touch|knock|hit|bump|disturb|move|topple|tip|upset)(?:ing)?(?: over| down| into)? (.+)$")

# the verb of a statement about a thing ("the blue box exceeds the gripper aperture", "the mug is dirty")
STATEMENT_VERB = (r"(?:is|are|s|looks?|seems?|was|were|keeps|sits|has been|has|have|got|needs?|exceeds|fits|weighs|measures|blocks|contains|holds"
                  r"|belongs|stands|lies|rests|leans|touches|overlaps|won t|wont|can t|cant|cannot|doesn t|doesnt|isn t|isnt|aren t|arent)")

# what people ask of things that no primitive does ("pour the soup into the bowl"): refused, never
# read as the nearest verb the planner knows
BEYOND_VERBS = ("pour", "fill", "cut", "slice", "chop", "wash", "rinse", "wipe", "eat", "drink", "cook", "heat", "microwave", "boil", "fry", "bake",
                "peel", "squeeze", "crush", "smash", "tear", "rip", "fold", "unfold", "tie", "untie", "screw", "unscrew", "plug", "unplug", "spray",
                "paint", "solve", "juggle", "stir", "blend", "unwrap", "unpack", "uncap", "sharpen", "melt", "freeze")
BEYOND = re.compile(rf"(?:{'|'.join(BEYOND_VERBS)})\b")

