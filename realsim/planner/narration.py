"""What the robot does, told to an audience in the third person ("For our first demo the arm is going
to pick up that banana and drop it into the bowl", "What you'll see next is our robot taking the
marker and laying it down beside the brick", "the arm just nudges the tin ten centimetres forward",
"our little helper is about to make them trade places"): said as the request to the robot.

Rule: a clause whose subject is the robot (robot, arm, gripper, helper, machine, Franka, Panda, with
"the", "our", "this"), said with any tense or helper verb and adverbs, is the command its verb
names; its verb in the third person or as a gerund, and every verb joined to it by "and (then)" in
the same sentence, is said in the plain form. An audience's cues ("watch this", "gather round",
"what you'll see next is") are not part of the request.
"""

from __future__ import annotations

import re

from realsim.planner.lexicon import ALL_VERBS

__all__ = ["narrated"]

_VERBS = frozenset(w for v in ALL_VERBS for w in v.split()[:1]) | {"make", "let", "have", "lay", "swap", "switch", "trade", "lower", "carry", "hop", "ease"}
_SUBJECT = (r"(?:(?:the|our|this|my|your|that) )?(?:(?:little|trusty|friendly|clever|robotic|robot|big|mechanical|faithful) )*"
            r"(?:robot(?: arm)?|arm|gripper|helper|machine|assistant|franka|panda|bot)")
_AUX = (r"((?:(?:'s|'ll|'re) |(?:is|s|will|ll|are|can|could|shall|should|would|now|then|gonna|going to|about to|is going to|is about to|is gonna|"
        r"just|simply|carefully|gently|slowly|quickly|first|next|also|here) )*)")
_TENSE = re.compile(r"'s|'ll|\b(?:is|s|will|ll|are|gonna|going to|about to|shall)\b")
_AUDIENCE = re.compile(r"(?:^|(?<=[.;!?] )|(?<=, ))(?:(?:and )?(?:now )?(?:watch|look at|see) (?:this|closely|carefully|here)|(?:gather|come) (?:a)?round(?: everyone| folks| all)?"
                       r"|here (?:it|we|she|he) goes|(?:and )?there (?:it|we|you) (?:go|goes|have it)|(?:ladies and gentlemen|folks|everyone|everybody)"
                       r"|(?:now )?what you(?:'ll| will| are going to| re going to|'re going to) (?:see|watch)(?: next| now)?(?:,? (?:everyone|folks|all))?,? is"
                       r"|(?:now )?(?:watch|see) as|(?:and )?(?:for|in|to (?:close|open|end|start|finish)) (?:our|the|this|my)(?: (?:first|next|last|final|opening|closing|big))?"
                       r" (?:demo|demonstration|trick|act|number|show|bit|finale|one))(?=[\s,.;!?]|$)[,.!]?\s*")
# an auctioneer's and a bargainer's talk around the request: "Lot twelve, ..., sold!", "going, going, gone", "take it or leave it", "deal?"
_TALK = re.compile(r"(?:^|(?<=[.,;:!?-] )|(?<=[.,;:!?-]))\s*(?:and )?(?:(?:okay|ok|right|so|well),? )?(?:sold(?: to [^:,.!;?]+)?|going,? going(?:,|\.\.\.|…)?(?:\s*(?:gone|sold))?"
                   r"|(?:(?:the )?(?:first|final|last|next|opening) )?lot(?: of the (?:day|night|evening|sale|auction))?(?: (?:number )?(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|[a-z]+teen|twenty))?|do i hear [^,.;!?]+|on the block"
                   r"|bargain time|(?:it s|its|it's a) deal|(?:do we have a )?deal|(?:and )?we(?:'ll| ll| will) call it (?:even|square|quits)|call it (?:even|square|quits)"
                   r"|take it or leave it|(?:my |one |the )?(?:last|final) offer|i(?:'ll| ll| will) make it worth your while|(?:then )?i(?:'m| m| am) out of your hair"
                   r"|we(?:'re| re| are) (?:done|square|even|good)(?: here)?|one favou?r(?:,? just one)?|here(?:'s| s| is) (?:the|my) (?:deal|offer)|you get [^.,;!?]* off|(?:and )?that(?:'s| s| is) the (?:auction|sale|show|demo|game) (?:closed|over|done|finished)"
                   r"|(?:my |your |the |an? )?(?:opening|first|next|last|final|winning) move|(?:a |the )?(?:knight|bishop|rook|queen|king|pawn)(?:'s| s)? move(?= for\b))"
                   r"(?=\s*(?:$|[.,;:!?-]))")
# "keep your eyes on the mug and the box, because ...": what is watched is what the request is about
_EYES = re.compile(r"\b(?:keep|fix|have) (?:your|an|all eyes|both eyes)(?: eyes?)? on (.+?),? (?:because|as|cause|cos|since|for) ")


def _plain(verb: str) -> str | None:
    """``verb`` in its plain form when it is a command verb said in the third person or as a gerund ("nudges", "taking")."""
    for form in (verb, verb[:-1] if verb.endswith("s") else "", verb[:-2] if verb.endswith("es") else "", verb[:-3] + "y" if verb.endswith("ies") else "",
                 verb[:-3] if verb.endswith("ing") else "", verb[:-3] + "e" if verb.endswith("ing") else "", verb[:-4] if re.search(r"(.)\1ing$", verb) else ""):
        if form and form in _VERBS:
            return form
    return None


def narrated(text: str) -> str:
    """``text`` (lower case) with the robot's actions told in the third person said as requests."""
    if re.search(r"\b(?:sold|bid|bids|bidder|bidding|auction|auctioneer|going,? going)\b", text):  # at an auction "on the block" is for sale
        text = re.sub(r"\s*(?:up )?on the (?:auction )?block\b", "", text)
    text = _EYES.sub(r"\1, ", _TALK.sub("", _AUDIENCE.sub("", text)))
    out: list[str] = []
    for sentence in re.split(r"(?<=[.;!?])\s+", text):
        m = re.search(rf"(^|[,:;!?-]\s*|\band\s+|(?<=\s))(?:and )?{_SUBJECT} {_AUX}(\w+)\b", sentence)
        verb = _plain(m.group(3)) if m else None
        # the robot said as the one acting: at a clause's start, or with a tense ("... demo the arm is going to pick up"), or
        # its verb in the third person ("... the arm just nudges"); "push the can toward the robot then lift it" is no narration
        after_place = re.search(r"\b(?:to|toward|towards|from|of|at|near|by|with|behind|beside|than|into|onto|on|in|past|for)\s*$", sentence[:m.start()]) if m else None
        if m and verb and not after_place and (m.group(1).strip() or m.start() == 0 or _TENSE.search(m.group(2)) or m.group(3) != verb):
            head, tail = sentence[:m.start()] + m.group(1), sentence[m.end():]
            tail = re.sub(r"\b(and(?: then)?|then) (\w+)\b", lambda t: f"{t.group(1)} {_plain(t.group(2)) or t.group(2)}", tail)
            sentence = f"{head}{verb}{tail}"
        out.append(sentence)
    return " ".join(out)
