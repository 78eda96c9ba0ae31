"""Voices said plainly: mock-archaic English, pirate talk, regional English and young people's slang.

"Prithee, good arm, set thou yon mug upon the plate" is "please, set the mug on the plate";
"Arr matey, haul the can o' soup to port o' the bowl an' be quick" is "haul the can of soup to
port of the bowl". Only word forms are changed (pronouns, old verb endings, clipped words,
interjections and forms of address); what is asked is read by the rest of the planner.
"""

from __future__ import annotations

import re

# whole words and fixed phrases, longest first when applied
_WORDS: dict[str, str] = {
    # old pronouns and forms
    "thou": "you", "thee": "you", "thy": "your", "thine": "your", "thyself": "yourself", "ye": "you", "yer": "your",
    "yourselves": "yourself", "yon": "that", "yonder": "that", "unto": "to", "upon": "on", "betwixt": "between", "twixt": "between",
    "'twixt": "between", "o'er": "over", "ere": "before", "hither": "here", "thither": "there", "whence": "from where",
    "doth": "does", "dost": "do", "hath": "has", "hast": "have", "art": "are", "shalt": "will", "wilt": "will", "canst": "can",
    "couldst": "could", "wouldst": "would", "shouldst": "should", "mayest": "may", "mine": "my", "forth": "forward",
    # phrases, read after the words above are plain
    "my own": "my", "your own self": "yourself", "your self": "yourself", "back and forward": "back and forth",
    "an it please you": "please", "if it please you": "please", "prithee": "please", "pray you": "please", "i pray you": "please",
    "i beseech you": "please", "beseech you": "please", "i bid you": "please", "i command you to": "", "i charge you to": "",
    # regional English and young people's slang
    "och": "", "gie": "give", "tae": "to", "aboot": "about", "oot": "out", "cannae": "cannot", "canna": "cannot",
    "dinnae": "do not", "didnae": "did not", "wouldnae": "would not", "ya": "you", "y'all": "you", "yall": "you", "youse": "you",
    "ain't": "is not", "fixin to": "going to", "fixing to": "going to", "out the road": "out of the way", "out of the road": "out of the way",
    "no cap": "", "lowkey": "", "highkey": "", "fr fr": "", "deadass": "", "on god": "", "istg": "", "ngl": "", "yeet": "toss",
    "chillin": "sitting", "chilling": "sitting", "vibing": "sitting", "vibin": "sitting", "plumb": "",
    # pirate talk
    "o'": "of", "an'": "and", "me hearty": "", "me hearties": "", "matey": "", "mateys": "", "swab": "", "ye scallywag": "",
    "scallywag": "", "landlubber": "", "me bucko": "", "bucko": "",
}
# interjections that open or close a sentence and say nothing
_INTERJECTIONS = (r"arr+|yarr+|ahoy|avast|yo ho(?: ho)?|shiver me timbers|blimey|aye(?: aye)?|har+|verily|forsooth|lo|hark|hearken|alas"
                  r"|by my troth|good morrow|well met|huzzah|gadzooks|zounds|egad|sirrah|good (?:sir|arm|robot|machine)|noble (?:arm|robot|machine|sir)")
_OPENER = re.compile(rf"(?:^|(?<=[.;:!?]))\s*(?:(?:{_INTERJECTIONS})\b[,!.;:]?\s*)+")
_CLOSER = re.compile(rf",?\s*(?:{_INTERJECTIONS})\s*(?=[.!?]*\s*$|[.!?])")
# old verb endings: "the can standeth", "it moveth" (a verb ending in -eth of more than five letters)
_ETH = re.compile(r"\b([a-z]{3,})eth\b")
_NOT_ETH = {"beneath", "seventh", "eleventh", "twentieth", "thirtieth", "fortieth", "fiftieth", "hundredth", "something", "teeth"}



def _alternation(words: list[str]) -> str:
    return "|".join(re.escape(w) for w in sorted(words, key=len, reverse=True))


_FORMS = tuple(re.compile(rf"(?<![\w'])(?:{_alternation([w for w in _WORDS if (' ' in w) == phrase])})(?![\w'])") for phrase in (False, True))
# a text in one of these voices: any word of theirs, an old verb ending or an interjection
_MARKED = re.compile(rf"(?<![\w'])(?:{_alternation(list(_WORDS))}|wee|\w+eth|{_INTERJECTIONS})(?![\w'])")

def _eth(m: re.Match[str]) -> str:
    word, stem = m.group(0), m.group(1)
    if word in _NOT_ETH:
        return word
    return stem + ("es" if stem[-1] in "svxzhcgu" else "s")


def plain(text: str) -> str:
    """``text`` (lower case) with archaic, pirate, regional and slang word forms said plainly."""
    if not _MARKED.search(text):
        return text
    text = _OPENER.sub(" ", text)
    text = _CLOSER.sub("", text)
    for forms in _FORMS:  # words, then phrases (written in the words' plain forms)
        text = forms.sub(lambda m: _WORDS[m.group(0)], text)
    text = _ETH.sub(_eth, text)
    text = re.sub(r"\bwee\b(?! bit)", "small", text)  # "yon wee cube"; "a wee bit" is an amount
    text = re.sub(r"\b(on|at|to) (?:the|your|my) (left|right) hand\b(?! side)", r"\1 the \2", text)  # "upon the right hand"
    text = re.sub(r"\bgive ((?:it|them|(?:the|that|this) [a-z ]+?)) an? (?:(?:little|small|gentle|good|wee) )?(?:shove|push|nudge|poke|bump|tap)\b", r"push \1", text)  # "gie yon wee cube a shove"
    text = re.sub(r"\b(set|place|put|lift|raise|move|push|slide|carry|take|bring|remove|grab|haul|fetch) you\b(?! (?:the )?(?:left|right))", r"\1", text)  # "set thou the mug"
    text = re.sub(r"\byou (?:will|must|shall) (?=(?:set|place|put|lift|raise|move|push|slide|carry|take|bring|remove|grab|swap|haul)\b)", "", text)
    return re.sub(r"\s{2,}", " ", text).strip()
