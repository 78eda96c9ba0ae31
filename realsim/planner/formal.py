"""A request written as an office email: "Kindly be advised that the box needs to be relocated to
the left of the can. Regards, Martin", "Per my earlier request, please ensure the tin is relocated
to ...", "I must ask that the object be transferred into the bowl", "please arrange for the mug to
be placed behind the box", "..., after which the arm should return to its home position".

Rule: the letter's frame goes (openings that refer to earlier mail or meetings, sign-offs and the
sender's name after them, thanks for cooperation); a passive request for a thing to be moved to a
place ("X needs to be / is to be / should be relocated to ...", "ensure X is placed ...", "arrange
for X to be placed ...", "that X be transferred into ...") is the request to put it there. Nothing
that names an object, a place or an amount is dropped.
"""

from __future__ import annotations

import re

__all__ = ["formal"]

_OPENING = re.compile(
    r"(?:^|(?<=[.;!?] ))(?:(?:kindly|please) be (?:advised|informed|aware|notified)(?: that)?|(?:as )?per (?:my|our|your) (?:earlier|previous|last|recent) "
    r"(?:request|email|e-mail|message|note|conversation)|following up on [^:,.;]+|as (?:discussed|agreed|mentioned|requested|noted)(?: (?:in|at|on|during|earlier|yesterday"
    r"|previously|before)[^,.;:]*)?|with (?:reference|regard|regards|respect) to [^,.;:]+|further to [^,.;:]+|(?:i|we) am writing (?:to|about) [^,.;:]+"
    r"|(?:i|we) (?:must|would like to|wish to|need to|have to) (?:ask|request)(?: that)?|this is to (?:ask|request|confirm)(?: that)?|(?:i|we) (?:hereby )?request that"
    r"|(?:i|we) (?:kindly )?ask that|(?:i|we) (?:would|d|'d|should) be (?:most |very |so |really )?(?:grateful|obliged|delighted|happy|pleased|thankful) if"
    r"|(?:the )?(?:operator|user|undersigned|client|requester|management|lab|team)(?: hereby)? (?:requests?|asks?|requires?|directs?)(?: that)?"
    r"|it is (?:hereby |kindly )?(?:requested|asked|required|directed|instructed)(?: that)?|be (?:advised|informed|aware|notified) that"
    r"|notwithstanding [^,.;:]+|(?:pursuant|further|subject) to [^,.;:]+|for the (?:avoidance of doubt|record))(?:[,:;]\s*|\s+)")
_SIGN_OFF = re.compile(
    r"(?:^|(?<=[.;!?] )|,\s*)(?:(?:kind|best|warm|warmest|many|with) (?:regards|wishes|thanks)|regards|sincerely|yours (?:sincerely|faithfully|truly)"
    r"|thank you (?:in advance|kindly|for your (?:cooperation|help|assistance|attention|prompt attention|understanding|time))[^.;!?]*"
    r"|many thanks(?: in advance)?|thanks in advance|cheers)(?:,\s*[a-z][a-z. ]*)?\s*[.!]?\s*$")
_WHEN = re.compile(r",?\s*\b(?:at your earliest convenience|as soon as (?:possible|practicable|you can)|when(?:ever)? (?:convenient|possible|you get a chance)"
                   r"|in due course|at the earliest opportunity)\b")
_MOVED = r"(?:relocated|moved|placed|deposited|displaced|translated|conveyed|positioned|put|transferred|set|shifted|repositioned|arranged|situated|located|stored|returned|brought|put back|set down|placed down)"
_THING = r"((?:the|that|this|my|our|your) (?:(?!(?:is|be|are|gets|get|needs|should|must|has|to)\b)[a-z']+ )*?[a-z']+)"
_PLACE = r"(?:(?:directly|right|just|immediately|exactly|neatly) )?(?=(?:to the|to|in|into|inside|on|onto|on top of|next to|adjacent to|alongside|beside|behind|in front of|between|left of|right of|near|by|under|at|back)\b)"
# "ensure X is placed ...", "arrange for X to be put ...", "have X moved ...": a thing made to be somewhere
_ENSURE = re.compile(rf"(?:please |kindly )?(?:ensure|make sure|see to it|arrange for|have)(?: that)? {_THING}"
                     rf" (?:(?:is|are|gets|get|ends up|end up|to be|be|is being) )?(?:{_MOVED} )?{_PLACE}")
# "X needs to be relocated to ...", "X is to be placed ...", "(that) X be transferred into ...": moved, said in the passive
_PASSIVE = re.compile(rf"{_THING} (?:needs to be|need to be|is to be|are to be|should be|must be|has to be|have to be|shall be|will need to be|ought to be"
                      rf"|could be|would be|can be|be) {_MOVED} {_PLACE}")
# "X is to be displaced 8 cm forward": a move by an amount, said in the passive
_PASSIVE_BY = re.compile(rf"{_THING} (?:needs to be|is to be|are to be|should be|must be|has to be|shall be|be) {_MOVED} (?:by )?(?=(?:about |roughly )?\d|(?:one|two|three|four|five|six|seven|eight|nine|ten|fifteen|twenty)\b)")
_SAID_AGAIN = re.compile(r",\s*(?:that is|i\.?e\.?|in other words|meaning),?\s*[^.;!?]*|,\s*'?[a-z]+'? being (?:understood|taken|read|defined) as [^.;!?]*")
# the words of a form: "upon receipt of this instruction", "effect the transfer of X to", "a position (immediately) adjacent to"
_FORM = ((r",?\s*(?:up)?on receipt of (?:this|these|the|my|our) (?:instructions?|requests?|messages?|orders?|notes?),?", ""),
         (r"\b(?:effect|carry out|perform|execute|undertake) (?:the|a) (?:transfer|relocation|movement|repositioning|move|displacement) of\b", "move"),
         (r"\b(?:to|into|at|in) (?:a|the) (?:position|location|spot|place|point)(?: (?:that is|which is))? (?=(?:immediately |directly |just |right )?"
          r"(?:adjacent|next|beside|behind|in front|to the (?:left|right)|left of|right of|on top|between)\b)", ""),
         (r"\b(?:is|are) to be (?:removed|taken|lifted) (?:from|off)(?: of)? (?:atop |on top of )?(?:the|that|this) [a-z ]+? and (?=(?:deposited|placed|put|set|moved|relocated)\b)", "is to be "),
         (r"\b(?:by )?a distance of (?=\w)", ""), (r"\bin the (forward|backward|left|right|rightward|leftward) direction\b", r"\1"))

# office jargon around a request: "low-hanging fruit first:", "going forward", "can we get that actioned?", "circle back to your home position"
_JARGON = ((r"(?:^|(?<=[.;!?:,] ))(?:(?:the |some )?low[- ]hanging fruit(?: first)?|first things first|quick win(?: first)?|(?:as )?(?:an |one )?action item|top priority|"
            r"priority (?:one|number one)|(?:going|moving) forward|at the end of the day|bottom line|big picture|(?:just )?to level set|to close the loop|"
            r"(?:just )?(?:a )?quick (?:one|ask|sync|ping)|(?:when|if) you (?:have|get) (?:the )?(?:bandwidth|cycles|a sec)|no blockers?(?: here)?)\s*[,:;.\-]*\s*", ""),
           (r"[,.;]?\s*(?:(?:can|could) (?:we|you|i) (?:get|have) (?:that|this|it|these) (?:actioned|done|sorted|sorted out|taken care of|over the line|across the line)"
            r"|(?:please )?action (?:that|this|it)|let(?: s| us)? (?:action|actio) (?:that|this|it)|(?:that s|that is) the (?:deliverable|ask|action item)"
            r"|(?:if you have|with your) (?:the )?bandwidth|ping me (?:when|once) (?:it s |that s |you re )?(?:done|finished)|(?:asap|eod|by eod|by end of day|by cob))(?=\s*(?:$|[.;!?,]))", ""),
           (r"\bcircle back (?=to\b)", "go back "), (r"\bcircle back(?=\s*(?:$|[.;!?,]))", "go home"))


_THE_ARM = re.compile(r"(?:,\s*)?\bafter which\b\s*(?:the (?:arm|robot|manipulator)|it) (?:should|must|can|will|is to|needs to|ought to|shall) ")


def formal(text: str) -> str:
    """``text`` (lower case, punctuation kept) without its letter frame, its passive requests made plain."""
    text = _SIGN_OFF.sub("", _WHEN.sub("", text.strip()))
    for pattern, word in _JARGON:
        text = re.sub(pattern, word, text)
    for _ in range(3):  # "further to my message, I must ask that ...": one opening after another
        text = _OPENING.sub("", text)
    for pattern, word in _FORM:
        text = re.sub(pattern, word, text)
    text = _SAID_AGAIN.sub("", _THE_ARM.sub(", then ", text))
    text = _PASSIVE_BY.sub(lambda m: f"move {m.group(1)} ", text)
    text = _ENSURE.sub(lambda m: f"put {m.group(1)} ", text)
    return _PASSIVE.sub(lambda m: f"put {m.group(1)} ", text).strip()
