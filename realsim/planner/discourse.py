"""Talk around a command, removed before the command is read: sentences and comma pieces that
are only greetings, thanks, politeness, hedges, exhortations and chat ("Hello there, young
fellow.", "Much obliged, I'm sure.", "If not, no worries.", "Come on!", "..., if you please?"),
and the markers of a numbered step list ("1. ... 2. ...", "Steps: 1) ...", "Step one: ...").

The rule for what is dropped: a piece (a sentence, or a part of one between commas, semicolons
or colons) goes only when every word of it belongs to a discourse phrase of :data:`TALK`, a
closed list that holds no object, place, direction or distance word; so nothing that names an
object, a place or a distance is ever dropped. A conditional hedge ("if not", "otherwise") is
talk only in a sentence of talk alone: "If not, put it on the plate" keeps its condition, and
the planner refuses what it cannot read rather than doing both. A text of talk alone is left
as it is (the planner then says it found no command).
"""

from __future__ import annotations

import re

__all__ = ["TALK", "drop_talk", "steps_as_clauses"]

_MUCH = r"(?: (?:so|very|ever so|so very|very very|really|truly|awfully|most|ever)?\s?(?:much|kindly|a lot|a bunch|a million|a ton|tons|heaps|loads|indeed|in advance|again))*"
_WHO = (r"(?:(?:my |you )?(?:dear|young|old|good|kind|dear old|little|sweet)?\s?"
        r"(?:fellow|friend|sir|madam|maam|mate|buddy|pal|robot|chap|dear|love|luv|bot|fella|lad|lass|man|dude|bro|bud|champ|sweetie|darling|son|kid|machine|legend|hero|genius|boss|chief|bestie|babe|hun|honey|bud|homie))")
# Discourse phrases: none names an object, a place, a direction or a distance.
TALK: tuple[str, ...] = (
    # greetings and address
    rf"(?:hello|hi|hey|hiya|howdy|yo|oi|greetings|good (?:morning|afternoon|evening|day|night))(?: there)?(?: to you)?(?: {_WHO})?", _WHO,
    r"how are you(?: doing| today)*", r"hope (?:you re|youre|you are) (?:well|good|doing well)", r"nice to meet you",
    # thanks and praise
    rf"(?:thank you|thanks|thankyou|thank u|thx|ty|tysm|tyvm|ta|cheers|many thanks|much obliged|obliged|much appreciated|appreciated"
    rf"|(?:i )?appreciate (?:it|that)(?: a lot)?|(?:i m|im|i am) (?:so |very |most |ever so )?(?:grateful|obliged|thankful)){_MUCH}(?: {_WHO})?",
    r"(?:i|we) (?:would|d|will|ll) be (?:so |very |most |ever so |really |truly |eternally )?(?:grateful|obliged|thankful)(?: to you)?",
    r"(?:i m|im|i am) sure", r"(?:have|enjoy) a (?:nice|good|great|lovely|wonderful) (?:day|one|evening|night|weekend|morning|afternoon)",
    r"(?:that s|thats|that is|that ll be|that would be|that d be|thatd be|you re|youre|you are|you d be|youd be)(?: a)? (?:so |very |really |just )?"
    r"(?:lovely|great|perfect|brilliant|wonderful|awesome|fantastic|super|grand|fine|all|it|a star|a gem|a dear|a darling|the best|a legend|too kind|so kind)",
    r"(?:lovely|great|perfect|brilliant|wonderful|awesome|fantastic|super|splendid|marvellous|marvelous|excellent|nice|cool|sweet|good job|well done|nice one|good stuff|bless you)",
    # politeness and hedges said as a piece of their own
    r"if you please", r"if you (?:would|could|will|can|dont mind|do not mind|wouldnt mind|would not mind)", r"if (?:it|that) s? ?(?:ok|okay|alright|all right|fine|possible|easy|no trouble|not too much trouble)",
    r"(?:if|when) you (?:get|have) (?:a )?(?:chance|moment|sec|second|minute)",
    r"(?:when|whenever|if) (?:it s|its|it is|it ll be|it would be|it d be|you re|youre|you are) (?:most |more |quite |at all )?(?:convenient|handy|free|ready|able|not busy)(?: for you)?",
    r"at your (?:earliest |own )?(?:convenience|leisure)", r"in your own time", r"whenever you (?:can|like|want|are ready|re ready|get round to it|get around to it)", r"(?:(?:i m|im|i am) (?:so |very |really |terribly |awfully |truly )?|(?:so |very |really |terribly |awfully |truly ))(?:sorry|apologies)"
    r"(?: (?:to bother you|for the trouble|for bothering you|to ask|to be a pain|to be difficult))?",  # not "sorry" alone: a correction
    r"(?:sorry|apologies) (?:to bother you|for the trouble|for bothering you|to ask|to be a pain|to be difficult)",
    r"(?:but )?(?:only )?if (?:it s|its|it is|that s|thats|that is) (?:no|not any|not too much|not too much of an?|not an?) (?:trouble|bother|imposition|hassle|problem|pain)(?: at all| for you)?",
    r"(?:do |please )?(?:feel free to|you can|you may) (?:say no|decline|refuse|ignore (?:me|this|it))", r"(?:please )?(?:just )?ignore me if (?:so|not|you re busy|you cant|you can t)",
    r"(?:i|we) (?:really|truly|honestly|genuinely) (?:am|are|do)",
    # how neatly: the placing primitives already centre and square what they put down
    r"(?:nice|good|neat) and (?:square|straight|neat|tidy|snug|tight|level|even|flush|centred|centered|close)", r"(?:all )?(?:edges|sides|corners) (?:lined up|aligned|flush|square|matching)",
    r"(?:with )?no overhang(?:ing)?", r"(?:centred|centered|squared|lined|straightened)(?: up)?", r"(?:tight|flush|snug) (?:to|against) (?:it|them)", r"(?:nice and )?(?:neatly|tidily)", r"of course", r"naturally", r"obviously", r"(?:totally|entirely|completely) (?:your|up to you)(?: call| choice| decision)?(?: of course)?",
    r"(?:i|we) (?:don t|dont|do not) want to (?:be (?:difficult|a pain|a bother|rude|pushy)|bother you|impose)",
    r"(?:i )?hope (?:i m|im|i am) not (?:bothering|disturbing|troubling) you", r"no (?:rush|hurry|pressure|stress)", r"(?:take|taking) your time",
    r"(?:i )?(?:mean|guess|think|suppose|reckon)", r"you know", r"(?:please|pls|plz|plse|kindly)",
    # exhortations and chat
    r"while (?:you re|youre|you are) at it", r"(?:ok |okay |so |right )?(?:here s|heres|here is) (?:the|my|a) (?:plan|deal|idea|thing|task)", r"(?:the )?plan is", r"(?:i )?(?:love|like) (?:that|it|this)", r"(?:and )?(?:that s|thats|that is) (?:it|all)",
    r"(?:good ?)?bye(?: bye)?", r"see (?:you|ya)(?: later)?", r"later", r"to ?do(?: list)?", r"todo", r"(?:all )?done", r"finished", r"over and out", r"that s everything", r"(?:i )?(?:guess|think|suppose|reckon)(?: so)?",
    # a drill sergeant's urging: "Hustle!", "On the double!", "I said NOW!", "Don't make me repeat myself!", "Move it!"
    r"(?:very )?good", r"hustle(?: up)?", r"(?:on the )?double(?: time| quick)?", r"pick up the pace", r"i said(?: so| now| it)?", r"(?:let s|lets) move",
    r"(?:don t|dont|do not) make me (?:repeat|say) (?:myself|it|that|this)(?: again| twice)?", r"(?:soldier|private|cadet|recruit|troops|people|you there|you)",
    r"(?:i think )?(?:that|it|this|they) (?:would|will|d|might|should) (?:look|be|seem) (?:so |much |a lot |way )?(?:better|nicer|neater|tidier|good|great|best|right|lovely|perfect)(?: that way)?",
    r"(?:i m|im|i am) not (?:sure|certain) (?:if|whether) (?:this|that|it) (?:works|will work|is possible|makes sense|can be done)",
    r"come on", r"(?:look|see|watch)(?: (?:at )?(?:this|here|that))?", r"(?:go ?)+", r"go on", r"(?:now|right now|right away|straight away|at once|immediately|asap|quick|quickly|fast|hurry(?: up)?|chop chop|pronto|stat|let s go|lets go|let s do this|lets do this)",
    r"(?:ok|okay|k|alright|all right|so|well|oh|ah|aha|um+|uh+|er+|erm|hmm+|lol|lmao|rofl|haha+|hehe|xd|ez|easy|rq|fr|gg|yes|yeah|yep|yup|sure|cool|nice|wow|ugh|man|bruh|bro|dude|fam|thx|ty|pls|plz|k)",
    r"(?:much|very|so|ever so|really|truly|indeed|also|too|as well)",
)
# a conditional or alternative: talk only in a sentence of talk alone ("If not, no worries.")
_HEDGE: tuple[str, ...] = (
    r"(?:but )?only if (?:it s|its|it is|that s|thats|that is|you can|you re able|possible|easy)(?: easy| possible| not too hard| no (?:trouble|bother)(?: at all)?)?",
    r"if (?:not|you can t|you cant|you cannot|it doesn t work|it doesnt work|that doesn t work|it s not possible|its not possible|not possible|you re not able|you are not able)",
    r"(?:but )?(?:only )?if (?:it s|its|it is|that s|thats|that is|you can t|you cant|you cannot|not|it isn t|it isnt|it s not|its not)\b[a-z ]*",
    r"otherwise", r"no worries", r"no (?:problem|probs|bother|big deal|matter)", r"(?:it s|its|that s|thats) (?:fine|ok|okay|alright|no problem)(?: too| as well)?",
    r"don t worry(?: about it)?", r"dont worry(?: about it)?", r"never mind", r"nevermind", r"all good", r"either way",
)
_TALK_RE = re.compile(rf"(?:(?:{'|'.join(TALK)})(?:\s+|$))+")
_ANY_RE = re.compile(rf"(?:(?:{'|'.join((*TALK, *_HEDGE))})(?:\s+|$))+")


def _words(piece: str) -> str:
    return " ".join(re.sub(r"[^a-z0-9 ]+", " ", piece.replace("'", " ")).split())


def _is_talk(piece: str, in_talk_sentence: bool) -> bool:
    words = re.sub(r"^(?:and|but|so|or|yet) ", "", _words(piece))  # ", and I don't want to be difficult,"
    return bool(words) and bool((_ANY_RE if in_talk_sentence else _TALK_RE).fullmatch(words + " "))


def drop_talk(text: str) -> str:
    """``text`` (lower case, punctuation kept) without the sentences and comma pieces that are only
    talk (see the module's rule); unchanged when nothing else is left."""
    out: list[str] = []
    for sentence in re.finditer(r"(?:[^.!?]|\.(?=\d))+(?:[.!?]+|$)", text):
        body = sentence.group(0)
        end = re.search(r"[.!?]*\s*$", body)
        stop = end.group(0).strip() if end else ""
        body = body[: end.start()] if end else body
        pieces = [p for p in re.split(r"\s*[,;:]\s*", body) if p.strip()]
        if not pieces or all(_is_talk(p, True) for p in pieces):
            continue
        if not out and re.fullmatch(r"\s*right(?: then| so| ok| okay| well)?\s*", pieces[0]) and len(pieces) > 1:
            pieces = pieces[1:]  # "Right, first thing: ...": opening the talk, not a side
        kept = [p.strip() for p in pieces if not _is_talk(p, False)]
        out.append(", ".join(kept) + (stop or "."))
    return " ".join(out) if out else text


_WORD_NUMBERS = ("one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")


def steps_as_clauses(text: str) -> str:
    """A numbered step list as clauses ("1. grab X 2) put it ..." -> "grab X, then put it ..."):
    "step N" / "step one" / "first," / "second thing:" before a pause always; bare numbers "1." "2)"
    or letters "a)" "b)" only when they count up from the first in order, so a distance ("push it
    10. then ...") is never taken for a step."""
    text = re.sub(r"(?:^|(?<=[\s.,;:!?]))(?:(?:the|two|three|four|five|\d|a few|some|these|my|here are the|here are my)\s+)?steps?(?: are| is)?\s*:\s*", " ", text)
    # an enumerator said as a word before a pause: "first, lift X; second, put it ..."
    text = re.sub(r"(?:^|(?<=[.,;:!?]))\s*(?:(?:two|three|four|five|a few|a couple of|some|several) )?(?:things|tasks|jobs|steps)(?: for you| to do)?\s*:\s*", " ", text)  # "Three things: ..."
    text = re.sub(r"(?:^|(?<=[.,;:!?]))\s*(?:first|firstly|second|secondly|third|thirdly|fourth|fifth|next|then|finally|lastly|last of all)"
                  r"(?: (?:thing|step|up|off|of all))?\s*[,:;]\s*", ", then ", text)
    text = re.sub(rf"(?:^|(?<=[\s.,;:!?]))step\s+(?:\d+|{'|'.join(_WORD_NUMBERS)})\s*[.,:;)-]*\s+", ", then ", text)
    for mark, first in ((r"\d{1,2}", "1"), (r"[a-e]", "a")):  # "1. .. 2. ..", "a) .. b) .."
        marks = list(re.finditer(rf"(?:^|(?<=[\s.,;:!?]))\(?({mark})\s*[.)]\s+(?=[a-z])", text, re.IGNORECASE if first == "a" else 0))
        count = [ord(m.group(1).lower()) - ord("a") + 1 if first == "a" else int(m.group(1)) for m in marks]
        if len(marks) >= 2 and count == list(range(1, len(marks) + 1)) and (first == "1" or all(")" in m.group(0) for m in marks)):
            for m in reversed(marks):
                text = f"{text[: m.start()]}, then {text[m.end():]}"
    return re.sub(r"^\s*,\s*then\s+", "", re.sub(r"\s*(?:[.;:]\s*)?,\s*then\s+", ", then ", text)).strip()
