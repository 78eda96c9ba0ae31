"""How people phrase a command, before any object is looked up: filler and polite words,
verbs and their particles, relation words, clauses, and the non-imperative forms people use
("the banana goes in the bowl", "I'd like the can next to the box", "mug in the bowl please",
"I need the box moved 5 cm left"), each rewritten into the imperative the planner reads.
"""

from __future__ import annotations

import re
import unicodedata

from realsim.planner import (
    casual,
    clarify,
    clock,
    code_calls,
    discourse,
    focus,
    formal,
    narration,
    places,
    purpose,
    radio,
    remarks,
    speech,
    technical,
    topic,
    typos,
    voices,
    wishes,
)
from realsim.planner.lexicon import (
    AGAIN,
    ALL_VERBS,
    AVOID,
    BEYOND,
    PUSH,
    PUT,
    RELATION_AT,
    RELATIONS,
    STATEMENT_VERB,
    TAKE,
    VERB_ANYWHERE,
    VERB_START,
    has_relation,
    relation_start,
)
from realsim.planner.refine import REFINE
from realsim.planner.vocab import BIG, COLOR_WORDS, NUMBERS, SHADES, SMALL, VAGUE_DISTANCES, brands

FILLERS = (
    r"(?:cheers|ta|thanks|thank you)(?: (?:ever |very |so )*much| a lot| a bunch| heaps| loads| kindly)?(?: (?:mate|love|luv|pet|darling|hun|buddy|pal))?",
    r"(?:would|could|will|can|are) you (?:be )?able to", r"(?:have|take) a (?:(?:good|quick|close|closer|proper|better) )?(?:look|squiz|gander|peek|peep|glance|squint|butchers?|dekko|shufti) at (?:it|them)",
    r"thank you (?:ever |very )?(?:so )?much", r"thank you kindly", r"excuse me", r"you see", r"now then",
    r"if it (?:is |s )?(?:no|not any) (?:trouble|bother)(?: at all)?", r"if it (?:isnt|is not) too much (?:trouble|bother)",
    r"if (?:it|that|this)(?: s| is| would be| would not be| wouldnt be| isnt| is not| wont be| will not be)? (?:not )?(?:too much )?(?:of )?(?:a |any )?(?:trouble|bother|problem|hassle)(?: for you)?(?: at all)?",
    r"if (?:that|it|this)(?: s| is| would be)? (?:doable|feasible|no problem|not a problem|ok with you|alright with you)", r"if you (?:could|can|would) manage(?: it| that)?",
    r"if you (?:would|could|will) be so (?:very )?kind", r"(?:would|do) you mind (?:terribly|awfully|very much|at all)", r"yay", r"woo+", r"yippee", r"hooray",
    r"neatly", r"nicely", r"tidily", r"(?:young|little|good|dear|my|nice) (?:robot|machine|bot|friend|dear)",
    r"(?:would|could|will) you be so good as to", r"be so good as to", r"for us", r"lol", r"lmao", r"possibly", r"perhaps", r"by any chance", r"haha", r"rq", r"fr", r"ez", r"yo", r"oh", r"maybe", r"i (?:guess|think|suppose|reckon|fear|suspect|believe|bet|trust|expect|imagine|swear|admit|confess|must say|have to say|gotta say)(?: so)?", r"i(?: m| am) afraid",
    r"or (?:whatever|something|so)", r"(?:would|will|could|can) (?:ya|you)(?= *$| *[,.;])", r"(?:that s|thats|that is) (?:it|all)", r"listen(?: up)?", r"basically", r"while you(?: re| are)? at it",
    r"if (?:that|it|this)(?: s| is)? (?:ok|okay|alright|all right|fine|possible)", r"bro", r"dude", r"mate", r"lets go{2,}", r"let s go{2,}", r"let go{2,}",
    r"(?:would|could|will) you (?:be so (?:very )?kind as|be kind enough) to", r"be so (?:very )?kind as to", r"would you kindly",
    r"(?:is|would) it be (?:at all )?possible to", r"is it (?:at all )?possible to",
    r"would it be (?:terribly |too |very |awfully |at all )?(?:inconvenient|much (?:trouble|bother)|a (?:problem|bother|pain)) (?:for you )?to", r"is it ok(?:ay)? (?:if you|to)", r"do you think you could",
    r"i (?:was |am |m )?wonder(?:ing)? if you (?:could|would|might|can|will)", r"(?:might|may|could|can) i (?:trouble|bother|ask|get) you to", r"would you mind", r"do you mind", r"could you please", r"can you please", r"could you", r"can you", r"would you",
    r"will you", r"you may", r"i(?: would|d) like you to", r"i want you to", r"i need you to", r"i(?: would|d) like to", r"i want to",
    r"you should", r"you can", r"you could", r"go ahead and", r"try to", r"try and", r"be sure to", r"make sure to",
    r"(?:do you |would you )?fancy(?= \w+ing\b)", r"please", r"pls", r"kindly", r"just", r"carefully", r"gently", r"slowly", r"quickly", r"for me", r"thanks",
    r"thank you", r"hey robot", r"hey", r"ok(?:ay)?", r"alright", r"all right", r"real quick", r"if you can", r"if possible",
    r"for now", r"now", r"well", r"um+", r"uh+", r"so", r"quick", r"fast", r"asap", r"right now", r"right away", r"straight away", r"let s", r"lets", r"do me a favou?r(?: and)?", r"if you (?:would|could|dont mind)",
    r"when you (?:get|have) a (?:chance|moment|sec|second|minute)", r"(?:are|would|will) you (?:be )?able to",
    r"if that works", r"many thanks", r"thanks a lot", r"there(?: s)? a good (?:lad|boy|girl|chap|fellow|one|robot|bot|machine)",
    r"good (?:lad|boy|girl|robot)", r"be a (?:love|dear|darling|sweetheart|pal|mate|star|doll|champ) and", r"for a (?:sec|second|moment|minute|bit)",
    r"(?:(?:that s|thats|that is|it s|its|it is) )?(?:(?:totally|completely|perfectly|absolutely) )?(?:fine|ok|okay|no worries|no problem|all good|no bother) if (?:not|you can ?t|you cannot)",
    r"only if it (?:s|is) no (?:trouble|bother)(?: at all)?",
    # please, thanks and fillers in the languages people mix in: "por favor", "bitte", "s'il te plait", "jaldi se"
    r"por ?favou?r", r"porfa", r"gracias", r"muchas gracias", r"bitte(?: schon| sehr)?", r"danke(?: schon| sehr)?", r"merci(?: beaucoup| bien)?",
    r"s ?il (?:te|vous) plait", r"alors", r"allez", r"vale", r"bueno", r"oye", r"arre", r"jaldi(?: se| jaldi)?", r"yaani", r"per favore", r"grazie",
    r"prego", r"obrigad[oa]", r"kudasai", r"onegai(?: ?shimasu)?", r"shukriya", r"dhanyavaa?d", r"bas", r"accha|acha", r"ja", r"genau",
        r"(?:okay,? |ok,? )?carry on", r"abracadabra", r"hey presto", r"presto", r"ta-?da+", r"et voila", r"voila", r"wherever there s (?:room|space)", r"wherever it fits", r"hold on,? (?:mum|mom|dad|love|honey|a (?:sec|second|moment|minute))", r"make it so", r"engage",
        r"places,? (?:everyone|everybody|people|all)", r"and action", r"(?:breathe|inhale|exhale)(?: in| out)?(?: (?:deeply|slowly|gently))?", r"(?:and )?(?:on|with) (?:the|your|an?) (?:in|out)[ -]?breath", r"take a (?:deep |slow )?breath",
    r"thank you so much", r"thanks so much", r"(?:good )?(?:morning|afternoon|evening)", r"hello", r"dear", r"no wait", r"wait", r"actually", r"oops", r"sorry", r"instead",
)
# when the speaker wants it done is not part of the command: "when I come back I'd like ...", "by the end of this, ..."
_VAGUE_WORDS = sorted((w for w in VAGUE_DISTANCES if not re.search(r"cm|centim", w)), key=len, reverse=True)  # "a touch", "a smidge"
_VAGUE = rf"(?:{'|'.join(map(re.escape, _VAGUE_WORDS))})(?: more)?"
_PRECISE = (r"(?:a couple of|a few|an?|one|two|three|four|five|six|seven|eight|nine|ten|\d+(?:\.\d+)?)\s*"
            r"(?:cm|mm|inch(?:es)?|centimet\w*|millimet\w*)")
_TIME_FRAME = re.compile(r"^\s*(?:(?:when|once|by the time|before) (?:i|you|we) (?:[a-z']+ ){0,3}?(?:back|home|here|in|out|return|returns|done|finished)"
                         r"|(?:by|at|towards?) the end of (?:this|it|all this|the day|today))\b,?\s*|\s*,?\s*\bby now\b")
# addressing the robot ("robot, ...", "..., panda") is not part of the command
_VOCATIVE = re.compile(r"(?:^|(?<=[,.;]))\s*(?:hey |hi |ok |okay )?(?:robot|franka|panda|robot arm|buddy|computer|helm|arm|(?:my )?(?:lovely |trusty |able )?assistant|(?:right |ok |okay |alright )?(?:crew|team|folks|gang|squad|troops|everyone|everybody|people|guys|all|y all|yall|you all))\s*(?=[,.;:]|$)")
# constraints the robot always keeps (it avoids moving anything else): "without touching anything else"
_THINGS = r"(?:anything|everything|something|(?:any of )?the (?:other|remaining|rest of the) (?:thing|object|item)s?|(?:other|remaining) (?:thing|object|item)s?|the rest)"
_CONSTRAINT = re.compile(r"\b(?:(?:and )?(?:while |by )?being careful not to|careful not to|without|(?:and )?(?:dont|don t|do not|try not to|avoid))"
                         r" (?:touch|knock|hit|bump|disturb|move|topple|tip|upset)(?:ing|ed)?"
                         rf" {_THINGS}(?: else)?(?: over| down| around)?\b")
_TEXTING = {"u": "you", "ur": "your", "plz": "please", "plse": "please", "thx": "thanks", "ty": "thanks", "n": "and", "&": "and",
            "mv": "move", "fwd": "forward", "fw": "forward", "bwd": "backward", "bk": "back", "nxt": "next", "obj": "object",
            "lft": "left", "rt": "right", "grn": "green", "blu": "blue", "ylw": "yellow", "wht": "white", "abt": "about",
            "w": "with", "ill": "i will", "lil": "little", "btwn": "between", "bw": "between", "frnt": "front", "tbl": "table", "pic": "pick", "tho": "though", "rite": "right",
            "b4": "before", "nexto": "next to", "infront": "in front", "ontop": "on top", "inbetween": "in between", "onto the top of": "on top of", "bc": "because", "cuz": "because", "nr": "near", "bhnd": "behind", "bowl2": "bowl", "thru": "through",
            "teh": "the", "hte": "the", "th": "the", "cn": "can", "swp": "swap", "mov": "move", "mve": "move", "orng": "orange", "prpl": "purple",
            "blk": "black", "rd": "red", "sm": "small", "lg": "large", "bx": "box", "btl": "bottle", "gimme": "give me", "yr": "your",
            "pls": "please", "outta": "out of", "outa": "out of", "lemme": "let me", "kinda": "kind of", "sorta": "sort of",
            "tryna": "trying to", "bout": "about", "cos": "because", "coz": "because", "rly": "really", "k": "okay", "kk": "okay"}
# "bring it over to sit with the banana": a thing brought somewhere to be there
_KEEP_COMPANY = r"\b((?:bring|move|put|take|carry|get|set|place|haul|scoot|slide|shift)\b[^.;!?]*?)(?: over| across| round| around)? to (?:sit|stand|rest|be|stay|live|hang out|go|hide|wait|lie|nap|sleep|play)"
# a thing complained of as being in the way, said as a sentence of its own (not "... , move it": that names the request)
_IN_THE_WAY = re.compile(r"(^|(?<=[.;!?] ))(?:(?:ugh|argh|man|honestly|seriously|so|well|god|gosh|jeez|sigh)[,!]? )*((?:the|that|this|my) [a-z]+(?: [a-z]+){0,2}?) (?:is|keeps|s)"
                         r"(?: (?:always|still|constantly|just|kind of|sort of|really|totally|completely|now))* (?:in (?:the|my|your) way|getting in (?:the|my) way"
                         r"|blocking (?:things|everything|me|the way|my (?:view|reach|path|arm|hand))|(?:cluttering|crowding|hogging|taking up)(?: up)? [a-z ]+?"
                         r"|obstructing [a-z ]+?)(?: again| all the time| constantly)?(?=\s*(?:[.;!?]|$|,\s*i (?:need|want) it (?:out of there|gone|moved|away)\s*(?:[.;!?]|$)))")
# a complaint about what a thing does to another, said before what to do about it: "the cereal box is crowding the bowl, three
# inches left", "the marker keeps picking on the cube. put it aside": the thing complained of is what "it" means next; said to
# the thing addressed ("cereal box, you're crowding the bowl, ...") it goes, the address said it
_COMPLAINT = re.compile(r"(^|(?<=[.,;!?] ))(?:(?:i swear|honestly|seriously|ugh|god|gosh|man|i feel like|it seems|it looks like|looks like)[,]? )*((?:the|that|this|my) [a-z]+(?: [a-z]+){0,2}?|you) (?:is |are |s |re |has been |have been )?(?:(?:always|still|constantly|just|really|keeps?|kept) )*"
                        r"(?:crowding|cramping|squashing|squeezing|squishing|bumping|poking|elbowing|jostling|shoving|leaning on|pressing on|picking on|bullying|teasing"
                        r"|pestering|bothering|annoying|hassling|hiding|shading|smothering|hogging|blocking|touching|bumping into|getting too close to|too close to)"
                        r"(?: (?:the|that|this|my|your|its|his|her) [a-z]+(?: [a-z]+){0,2}?)(?: (?:again|all day|all the time|constantly|today|lately|so much))*(?=\s*[.,;!?])")
# an undo of the step just said: the thing it moved put back where it was
_UNDO = re.compile(r"\b(?:undo|reverse|revert|take back|roll back) (?:that|it|this|the (?:last )?(?:move|step|one|push))(?: (?:move|step|one))?\b(?: (?:again|please|too|as well))?")
# what is said to a thing told to leave: it goes out of the way
_LEAVE = (r"(?:you )?(?:exit|clear off|go away|get lost|scram|shoo|make yourself scarce|leave the (?:stage|scene|frame|shot))(?: first| now| stage (?:left|right))?"
          r"(?:[ ,-]+(?:and )?(?:go |get )?(?:off )?(?:somewhere )?(?:to the side|aside|out of the way|off stage|offstage))?")
_EXIT = re.compile(rf"(?:^|(?<=[.,;!?] ))(?:and )?{_LEAVE}(?:[ ,;:!.-]+{_LEAVE})*(?=\s*(?:$|[.,;!?]))")
# one thing taking another's place: "the banana takes the soup can's old mark"
_TAKES_PLACE = re.compile(r"\b((?:the|that|this) [a-z ]+?) (?:takes|gets|moves into|steps into|takes over|goes to|slides into) ((?:the|that|this) [a-z ]+?)(?:'s| s|s)? "
                          r"(?:old |former |previous |empty )?(?:mark|spot|place|position)\b")
_BODY_WIDTH_CM = {"hand": 10, "palm": 8, "finger": 2, "thumb": 2}  # a hand's width is about 10 cm, a finger's 2 cm
GERUNDS = {"picking": "pick", "putting": "put", "placing": "place", "moving": "move", "pushing": "push", "grabbing": "grab",
           "taking": "take", "setting": "set", "dropping": "drop", "stacking": "stack", "sliding": "slide", "lifting": "lift",
           "opening": "open", "closing": "close", "bringing": "bring", "going": "go", "shoving": "shove", "nudging": "nudge",
           "getting": "get", "returning": "return", "placing it": "place it", "popping": "pop", "shifting": "shift", "sticking": "stick",
           "scooting": "scoot", "dragging": "drag", "raising": "raise", "swapping": "swap", "tucking": "tuck", "parking": "park"}


# a question asks about the scene; it is never carried out ("is the mug in the bowl?"), unlike a request ("can you ...")
QUESTION = re.compile(r"(?!what i(?: ?'?m| am| ?'?d| would)? (?:after|like|want|need)\b)(?!is there (?:any|a|some) (?:way|chance)\b)(?:is|are|was|were|does|did|what|where|which|how|who|why|when)\b(?! ever\b)(?! (?:it|you) (?:be )?(?:possible|ok|okay|able|alright)\b| about\b"
                      r"| (?:you|you'?re|you are|that'?s|that is|it'?s|it is|all that'?s) (?:done|finished)\b)")


def clean(command: str) -> str:
    """Lower case, polite and filler words removed, gerunds to verbs; clause punctuation kept."""
    text = "".join(c for c in unicodedata.normalize("NFD", command.lower().replace("’", "'")) if not unicodedata.combining(c))  # "plátano": accents go
    text = narration.narrated(text)  # "the arm is going to pick up the banana": the request told to an audience
    # a game's and a garden's words for moving things: "castle the mug and the bowl", "the cube advances 5 cm", "Blue cube, retreat",
    # "transplant the bottle into the gap", "the red cube gets planted on the plate", "heel the mug in just in front of the bowl"
    text = re.sub(r"\bcastle(?= (?:the|that|this|them|it)\b)", "swap", text)
    text = re.sub(r"(^|(?<=[.,;!?] ))((?:the |that |this )?[a-z']+(?: [a-z']+){0,2}?) (advances|retreats)\b", lambda m: f"{m.group(1)}move {m.group(2)} {'forward' if m.group(3) == 'advances' else 'back'}", text)
    text = re.sub(r"\b(advance|retreat)(?= (?:the|that|this|it|them)\b)", lambda m: "move", text)
    text = re.sub(r"(?:^|(?<=[.,;!?] ))(?:now )?(retreat|fall back|back off|withdraw|advance)(?=\s*(?:$|[.,;!?]))", lambda m: f"move it {'forward' if m.group(1) == 'advance' else 'back'}", text)
    text = re.sub(r"\b(?:transplant|replant|re-pot|repot)\b", "move", text)
    text = re.sub(r"\bheel (.+?) in\b(?= (?:just |right )?(?:in front|behind|next|beside|between|on|left|right|to the)\b)", r"put \1", text)
    text = re.sub(r"(^|(?<=[.,;!?] ))((?:the |that |this )?[a-z']+(?: [a-z']+){0,2}?) (?:gets|get|got|is|s) (?:planted|put|placed|set|moved|parked|popped|dropped|stuck|laid) "
                  r"(?=(?:on|in|into|onto|next|beside|behind|between|in front|left|right|to the)\b)", r"\1put \2 ", text)
    text = re.sub(r"(?:^|(?<=[.,;!?] ))((?:in|into|onto|on|on top of|next to|behind|beside) (?:the|that|this) [a-z ]+?) (?:it|she|he|they) (?:go|goes)\b", r"put it \1", text)
    text = re.sub(r"\bwhere (it|they) (?:originally|first|initially|previously|once|used to be|had been) (?:was|were|stood|sat|lay|started)\b", r"where \1 was", text)
    text = re.sub(r"\b(take|get|lift|bring) (it|them|the [a-z ]+?) (?:down )?off (?:of )?(?:the thing|whatever|what) (?:it|they)(?:'s|'re| s| re| is| are)? (?:sitting|standing|resting|lying|perched)(?: on)?\b", r"\1 \2", text)
    text = re.sub(r"\btowards? (?:my|your|our|the robot s|the robot's) (?:side|end|edge)\b", "toward me", text)
    text = re.sub(r"(?:^|(?<=[.,;!?] ))for ((?:the|that|this) [a-z' ]+?)(?=\s*[-,.:;!?])", r"\1", text)  # "knight's move for the mug - hop it over ...": the one it is for
    text = re.sub(r"\b(?:in|into|to|onto)? ?the (?:gap|space|spot|room|slot|opening|hole)(?: that s| that is| left)? (?:right )?(?=between\b)", "", text)  # "into the gap between A and B"
    text = re.sub(r"\boff the (?:board|field|pitch|stage|playing area|bed)\b", "aside", text)  # "move the can off the board to one side"
    text = re.sub(r"\b(?:hop|jump|land|plant|deliver)( it| them| (?:the|that|this) [a-z ]+?)(?: over| across| down)?(?: and)? (?=(?:in|into|onto|on|next to|beside|behind|in front of|to the|left of|right of|between|where|exactly where|at)\b)",
                  r"put\1 ", text)  # "hop it over and into the bowl", "land the cube exactly where the can stood"
    text = re.sub(r"\bwhere (the [a-z ]+?|it|they) (?:stood|sat|was standing|was sitting|used to (?:be|stand|sit))\b", r"where \1 was", text)
    # a thing said to move itself to a place: "the can steps down off the box and lands on the table beside the bowl"
    text = re.sub(r"(^|(?<=[.,;!?] ))((?:the|that|this) [a-z' ]+?) (?:(?:steps|hops|jumps|climbs|comes|gets) (?:down )?off (?:of )?(?:the|that|this) [a-z ]+? and )?"
                  r"(?:lands|hops|steps|jumps|moves|slides|settles|ends up|comes to rest|sits down|walks|strolls|wanders|travels|heads)(?: down| over)? (?:right |just |directly )?"
                  r"(?=(?:on|in|into|onto|next to|beside|behind|in front of|to the|left of|right of|between)\b)", r"\1put \2 ", text)
    # "two inches to the right for the foam brick": the way said first, then whom it is for
    text = re.sub(r"(^|(?<=[.,;!?] ))((?:about |roughly )?(?:\d+(?:\.\d+)?|an?|one|two|three|four|five|six|seven|eight|nine|ten) ?(?:cm|mm|inch\w*|centimet\w*|millimet\w*) "
                  r"(?:to the (?:left|right)|left|right|forward|back|backward|closer|away|toward (?:me|you)|towards (?:me|you))) for ((?:the|that|this) [a-z' ]+?)(?=\s*(?:$|[.,;!?]))",
                  r"\1move \3 \2", text)
    text = re.sub(r"\bno (?:lifting|picking up|picking|grabbing|grasping|carrying) (?=(?:that|the|this|it)\b)", "", text)
    text = re.sub(r"\b(?:dont|do not|don t|don't) (?:lift|pick up|raise|carry|grab) ((?:that|the|this) [a-z ]+?|it)(?=\s*[,.;-]+\s*(?:just |only |simply |instead )?(?:move|push|slide|walk|nudge|shove|ease|scoot|drag)\b)",
                  r"\1", text)  # "don't lift that bowl, just walk it along": the manner ruled out, the thing still moved  # "no lifting that can, just ease it back": the manner ruled out
    text = re.sub(r"\bease (it|them|(?:the|that|this) [a-z ]+?) (?=(?:back|forward|left|right|over|closer|away|toward|towards|to the|into|onto|in|on|off)\b)", r"move \1 ", text)
    text = casual.causative(clock.nautical(clock.clock(_TIME_FRAME.sub("", code_calls.as_words(_by_comparison(voices.plain(text)))))))
    text = _UNDO.sub("put it back where it was", text)  # "move the mug 5 cm left. actually, undo that": where it was before
    text = _EXIT.sub("move it aside", text)  # "Red box, ... Exit -- clear off somewhere out of the way": the one addressed leaves
    text = _TAKES_PLACE.sub(r"put \1 where \2 was", text)  # "the banana takes the soup can's old mark"
    # "Marker, your entrance is between the brick and the mustard": where the one addressed goes
    text = re.sub(r"(?:^|(?<=[.,;!?] ))your (?:entrance|mark|spot|place|position|new (?:home|spot|place)|seat) (?:is|will be|s) (?=(?:in|on|next|beside|behind|between|left|right|to the|in front|upstage|downstage)\b)", "put it ", text)
    text = re.sub(r"\s*,?\s*(?:and )?(?:be (?:quick|fast|snappy|swift|careful|gentle|nice|quiet)(?: about it)?|make it (?:snappy|quick)|look lively"
                  r"|step (?:to it|lively)|(?:and )?(?:on|at) the double|chop[- ]chop)(?=\s*(?:$|[.,;!?]))", "", text)  # "... and be quick about it!"
    text = re.sub(r"(\b(?:swap|switch|exchange|trade)\b[^.;!?]*?),?\s*(?:the |to the )?(?:left|right) (?:for|with|and) (?:the |to the )?(?:left|right)\b", r"\1", text)
    text = re.sub(_KEEP_COMPANY + r" with (?=(?:the|that|this|its|his|her|their|my|your)\b)", r"\1 next to ", text)  # "bring it over to sit with the banana"
    text = re.sub(_KEEP_COMPANY + r"(?= (?:next to|beside|by|near|in|inside|on|behind|in front of|left of|right of|to the|between|under|on top of)\b)", r"\1", text)
    text = focus.singled_out(wishes.as_request(purpose.purpose(technical.technical(formal.formal(radio.radio(text))))))
    text = topic.whichever_of(text)
    text = clarify.amount(clarify.clarify(remarks.people(discourse.drop_talk(discourse.steps_as_clauses(text)))))
    text = speech.repair(text, VERB_START, RELATION_AT)
    text = re.sub(r"\s*\(([^()]*)\)", r", \1,", text)  # a remark in brackets is a clause of its own
    text = re.sub(r"[!?]+", ".", text)
    text = re.sub(r"\s+[-–—]+\s+|\s*[–—]\s*|\s*:\s+", ", ", text)  # a dash or colon between phrases: a pause, as a comma
    text = re.sub(r"\bas well\b", "too", text)  # before "well" goes as a filler
    text = re.sub(r"([a-z][a-z ]*?)\s*(?:<-+>|<=+>|↔|⇔)\s*([a-z][a-z ]*[a-z])", r"swap \1 and \2", text)  # "cereal box <-> mug"
    text = re.sub(rf"\s*(?:-+>|=+>|→|⇒|⟶)\s*(?={VERB_START.pattern})", ", ", text)  # "tall white can -> place it left of the red can"
    text = re.sub(r"\s*(?:-+>|=+>|→|⇒|⟶)\s*(?=(?:next to|in|into|on|onto|behind|left of|right of|in front of|between|beside)\b)", " ", text)
    text = re.sub(r"\s*(?:-+>|=+>|→|⇒|⟶)\s*", " to ", text)  # "mug -> bowl": where it goes
    text = re.sub(r"\b(can|box|bottle|jar|tin|carton|bag|packet|cup|bowl) of (?!the\b)(\w+(?: (?!(?:and|then|in|into|on|onto|to|next|behind|from|for|please|of|at|inside|with)\b)\w+)?)",
                  r"\2 \1", text)  # "the can of tomato", "a tin of tomato soup"
    text = re.sub(r"\s+by (?:its|the|their) (?:handle|rim|top|side|edge|body|lid|middle)s?\b", "", text)  # the grasp is the robot's choice
    text = re.sub(r"\s+and (?:hold|keep) (?:it|them|holding it|holding them)(?: up| there| in the air| steady| still)?(?=$|[.,;!?])", "", text)
    # holding on is what a lift leaves: "keep holding it until I say otherwise"
    text = re.sub(r"(?:^|(?<=[.,;!?])|\s+and\b)\s*(?:and )?(?:keep|continue|just keep) (?:holding|to hold) (?:it|them|on(?: to (?:it|them))?)(?: up| there| in the air)?(?: until [^.,;!?]*)?(?=$|[.,;!?])", " ", text)
    text = re.sub(r"\s+with (?:it|them)(?=$|[.,;])", "", text)  # "into the bowl with it"
    text = re.sub(r"(?:,\s*|\s+)and (?:hold|hold on|hold there|hold still|hold steady|stay there)(?=\s*(?:$|[.;!?]))", "", text)  # "..., and hold."
    # how high a lift goes is the robot's choice: "hold it up high", "lift the can way up high", "up really high"
    text = re.sub(r"\s+(?:(?:way|really|very|super|real|nice and|good and)\s+)?(?:up\s+)?(?:(?:really|very|super|so)\s+)?high(?:\s+up)?(?:\s+in(?:to)? the air)?"
                  r"(?=\s*(?:$|[.,;!?]))", " up", text)
    text = re.sub(rf"\b(?:move|bring|get|take|raise|make) ({_THE_THING}) (?:go )?up (?:in(?:to)? the air|off the (?:table|counter|desk|surface))\b",
                  r"lift \1", text)  # "make it go up in the air"
    text = re.sub(rf"\b(lift|raise|pick up|hold up) ({_THE_THING}) (?:up )?off (?:of )?the (?:table|counter|desk|surface|floor)\b",
                  r"\1 \2", text)  # "lift that mug up off the table"
    text = re.sub(r"\b(?:him|her)\b", "it", text)  # an object is "it" ("you put him beside the bottle")
    # a thing spoken of as a person: "he stands between the couple", "she sits at its left", "their way to the bowl"
    text = re.sub(r"\b(?:he|she)(?= (?:sits|stands|goes|belongs|needs|should|must|has to|will|can|gets|stays|lands|comes|moves|rests|waits|sit|stand|go|rest))\b", "it", text)
    # a stage magician's words: "make it vanish into the bowl", "the levitating mug", "the switcheroo", "whisk it out of the way"
    text = re.sub(r"\bmake (it|them|(?:the|that|this) [a-z ]+?) (?:vanish|disappear|reappear|appear|materiali[sz]e|teleport)(?:[.\s]*)(?=(?:in|into|inside|on|onto|next to|beside|behind|in front of)\b)", r"put \1 ", text)
    text = re.sub(r"\b(?:make (it|them|(?:the|that|this) [a-z ]+?) (?:vanish|disappear)|((?:the|that|this) [a-z ]+?) (?:simply |just )?(?:vanishes|disappears))\b",
                  lambda m: f"move {m.group(1) or m.group(2)} aside", text)
    text = re.sub(r"\b(?:whisk|spirit|magic) (it|them|(?:the|that|this) [a-z ]+?) (?=(?:away|out of|off|aside|into|onto|in|on)\b)", r"move \1 ", text)
    text = re.sub(r"\b(?:levitate|float) (it|them|(?:the|that|this) [a-z ]+?)(?=\s*(?:$|[.,;!?]| up\b))", r"lift \1", text)
    text = re.sub(r"\bthe (?:levitating|floating|flying|vanishing|disappearing|amazing|incredible|mysterious) ([a-z]+(?: [a-z]+)?)\b", r"the \1", text)
    text = re.sub(r"\b(?:do |perform )?the (?:switcheroo|old switcheroo|switch-?a-?roo|swaparoo)\b", "swap them", text)
    # a station's announcements: "the tin is requested at the bowl", "please make their way to the bowl", "report to the front of the bowl"
    text = re.sub(r"\b((?:the|that|this) [a-z ]+?) (?:is|are) (?:requested|wanted|needed|expected|called) (?=(?:at|in|inside|on|next to|beside|behind|in front of|on the|to the)\b)", r"put \1 ", text)
    text = re.sub(r"\b(?:please )?(?:make (?:their|its|his|her|your) way|report|proceed|go|move)(?: directly| now)? to (?=(?:the front|the back|the left|the right|the (?:far|near) side) of\b)", "put it at ", text)
    text = re.sub(r"\b(?:please )?(?:make (?:their|its|his|her|your) way|proceed) (?:over |directly )?to ((?:the|that|this) [a-z ]+?)(?: and (?:wait|stand|sit|stay|rest) (?=(?:on|at|in|by|beside|next to|behind|in front of)\b)| |(?=\s*[.,;!?]|$))",
                  r"put it next to \1 ", text)
    text = re.sub(r"\b(?:please )?(?:take (?:your|its|their|his|her) seat|be seated|have a seat|board|embark) (?=(?:in|inside|on|at|next to|beside)\b)", "put it ", text)
    text = re.sub(r"\b(?:please )?(?:disembark|alight|get off|step off|climb down)(?: (?:from|off) (?:the|that|this) [a-z ]+?)? (?=(?:onto|on|to|at|next to|beside)\b)", "put it ", text)
    text = re.sub(r"\b(?:walk|waltz|shimmy|jockey) (it|them|(?:the|that|this) [a-z ]+?)(?: along(?: the (?:table|counter|surface|floor))?)?[\s,-]+(?=(?:\d|an?|one|two|three|four|five|ten|about|left|right|forward|back|to the|toward|towards|over|closer|away|along)\b)", r"move \1 ", text)
    text = re.sub(r"\bthe (table|floor|counter) proper\b", r"the \1", text)
    text = re.sub(r"(?:^|(?<=[.!?] ))would ((?:the|that|this) [a-z ]+?)(?=,| please\b)", r"\1", text)  # "Would the small white object, ..., please ...": the one addressed
    text = re.sub(r"\bthe (?:passenger|guest|traveller|traveler|customer|party|person|gentleman|lady|patient|contestant|volunteer)s? (?:travelling|traveling|known|listed|booked|going|sitting|registered|named) (?:as|under(?: the name)?) ", "", text)
    text = re.sub(r"\s*,?\s*(?:on|at) (?:the robot s|the robots|the robot|your|my|our|the near|the nearer|the close|the closer) side(?=\s*(?:$|[.,;!?]))", "", text)  # "the front of the bowl, on the robot's side"
    text = re.sub(r"\bfrom (?:itself|yourself|the robot itself)\b", "from you", text)  # "farther away from itself": the robot
    text = re.sub(r"^(?:when|once|by the time) (?:it ?'?s|it is|it has|you ?'?re|you are|you have|that ?'?s|that is|everything ?'?s|everything is|all is|we ?'?re|we are)"
                  r" (?:finished|done|over|through|complete)[,\s]+", "", text)  # "when it's finished, the mug should be ..."
    text = re.sub(r"\s*,?\s+instead of (?:being )?(?:on|in|inside|next to|beside|behind|in front of|on top of|under|at|by) [^.,;!?]*", "", text)
    text = re.sub(r"(?:^|(?<=[.,;!?] )|(?<=\bthen )|(?<=\band ))(?:the |your )?arm (?:back )?(?:to )?home\b", "go home", text)  # "2) arm home"
    text = re.sub(r"\bpark (?:the arm|your arm|yourself|the robot)\b|\bpark(?=\s*(?:$|[.;!?]))", "go home", text)  # "..., then park the arm"
    text = re.sub(r"(?:^|(?<=[.,;!?] )|(?<=\bthen )|(?<=\band ))(?:heel|come back(?: to me)?|back to (?:me|base))(?=\s*(?:$|[.,;!?]))", "go home", text)  # a dog's "heel": back to its place
    text = re.sub(r"\b(?:return|bring|send|put) (?:the arm|your arm|yourself|the robot)(?: back)? to (?:the |its |your )?(?:standby|rest|resting|home|start|starting|neutral|park(?:ed|ing)?)"
                  r"(?: (?:position|pose|spot|place|state))?\b|(?:^|(?<=[.,;!?] ))(?:the |your )?arm back to (?:its )?(?:rest|standby|home|start)(?: position| pose)?(?=\s*(?:$|[.,;!?]))", "go home", text)
    # said to a thing addressed: "Banana, ..., go sit in the bowl": it goes there
    text = re.sub(r"(?:^|(?<=[.,;!?] ))(?:and )?(?:now )?(?:go|come)(?: and)?(?: (?:sit|stand|rest|lie|live|hide|wait))? (?=(?:in|into|inside|on|onto|next to|beside|behind|in front of|to the left of|to the right of|left of|right of|between|on top of)\b)",
                  "put it ", text)
    text = re.sub(r"(?:^|(?<=[.,;!?] )|(?<=\bthen ))(?:and )?return (?:back )?to (?:base|home|(?:the |your |its )?(?:home|start|rest|resting|starting|base|park(?:ed|ing)?|neutral|standby)(?: position| pose| point| spot| place)?)(?=\s*(?:$|[.,;!?]))", "go home", text)
    text = re.sub(r"(?:^|(?<=[.,;!?] )|(?<=\bthen ))(?:and )?back (?:to )?(?:the |your |its )?(?:home|start|rest|starting)(?: position| pose| point)?(?=\s*(?:$|[.,;!?]))", "go home", text)
    text = re.sub(r"\b(?:on )?over (?=(?:beside|next to|near|alongside|behind|in front of|to the|left of|right of)\b)", "", text)  # "over beside the bowl": beside it
    text = re.sub(r"(?<=[a-z]) in (?=(?:behind|in front of|next to|beside|alongside|between|against|on top of|under)\b)", " ", text)  # "tuck it in behind the bowl"
    text = re.sub(rf"\b(?:{'|'.join(SHADES)})[ -](?=(?:{'|'.join(COLOR_WORDS)})\b)", "", text)  # "pale yellow": yellow
    # what the robot is said to be about to do, told to someone else: "the robot's gonna put it in the bowl"
    text = re.sub(rf"(?:(?<=^)|(?<=[.,;!?] ))(?:now |so |and )?(?:the |our |this |my )?(?:robot|arm|franka|panda)(?:'s|'ll| is| s| will| ll)? (?:gonna|going to|about to|will) (?={VERB_START.pattern})", "", text)
    text = re.sub(r"(?:\bover by|(?:^|(?<=[,.;!?] ))by)(?= (?:the|that|this|my|your) )", "next to", text)  # "banana, (over) by the bowl"
    text = re.sub(r"\b((?:\w+ )?\w+) up[.!,]\s*(?:up )?off the (?:deck|table|floor|ground|surface|counter|desk)\b", r"\1 up", text)  # "marker up! off the deck!": lifted
    text = re.sub(r"\b(?:finish|end|wrap(?: it| things)? up|conclude)(?: off| up)? by (?=\w+ing\b)", "", text)  # "and finish by going back home"
    text = re.sub(r"\b(?:perched|balanced|sitting|standing|resting|lying|sat|stood) (?=(?:on|atop|on top of|in|inside) (?:the|that|this|a|an)\b)", "", text)
    text = _VOCATIVE.sub(" ", text)
    text = re.sub(r"(?<![\w'])'?em\b", "them", text)  # "swap 'em"
    for short, word in _TEXTING.items():  # "could u grab the can pls"
        text = re.sub(rf"(?<![\w'-]){re.escape(short)}(?![\w'-])", word, text)
    text = typos.sides(text)
    text = re.sub(r"(?<![\w'-])([lr])(?= of\b)|(?<=\d)( ?(?:cm|mm|in|inch|inches|centimet\w*|millimet\w*) )([lr])(?![\w'-])",  # "L of red can", "10cm L"
                  lambda m: f"{m.group(2) or ''}{'left' if (m.group(1) or m.group(3)) == 'l' else 'right'}", text)
    # spoken fractions and trade units: "two and a half centimetres", "three quarters of an inch", "ten mil", "a hand's width"
    text = re.sub(r"\b(\d+|one|two|three|four|five|six|seven|eight|nine|ten) and a half\b", lambda m: f"{float(NUMBERS.get(m.group(1), m.group(1))) + 0.5:g}", text)
    text = re.sub(r"\b(?:(three)|an?|one) quarters? of an? (?=inch|centimet|cm|millimet|mm)", lambda m: "0.75 " if m.group(1) else "0.25 ", text)
    text = re.sub(r"\b(\d+(?:\.\d+)?|one|two|three|four|five|six|seven|eight|nine|ten|twenty) mils?\b", r"\1 mm", text)
    text = re.sub(r"\b(an?|\d+|one|two|three|four|five|six|seven|eight|nine|ten) (hand|palm|finger|thumb)(?:'?s|s'?)? ?(?:width|breadth)s?\b",
                  lambda m: f"{float(NUMBERS.get(m.group(1), 1 if m.group(1) in ('a', 'an') else m.group(1))) * _BODY_WIDTH_CM[m.group(2)]:g} cm", text)  # "three fingers' width"
    text = re.sub(r"(\d\s*(?:cm|mm|inch\w*|centimet\w*|millimet\w*)\b[^.;!?]*?)[.;,]\s*(?:call it|say|make (?:it|that)|let'?s say) (?:about |roughly )?[\w.]+ (?:cm|mm|inch\w*|centimet\w*|millimet\w*)\b", r"\1", text)
    text = re.sub(r"\b(\d+|one|two|three|four|five|six|seven|eight|nine|ten|twenty)[- ]?ish\b", r"\1", text)  # "three-ish inches"
    text = re.sub(r"(?<!\bhalf )(?<!\bquarter of )\ban? (?=(?:inch|centimet\w*|cm|millimet\w*|mm)\b)", "1 ", text)  # "an inch", not "half an inch"
    # a vague amount made precise later: "a little more to the right, say a couple of inches", "a touch further away, an inch, give or take"
    text = re.sub(rf"\b(?:just )?{_VAGUE}(?! of\b)((?: [^.;,!?]*?)?)[.;,]\s*(?:(?:say|call it|maybe|about|roughly|around|like|so|just|only|at most|tops)\s+)*({_PRECISE})"
                  r"(?:\s*(?:or so|give or take|at most|tops|max|or thereabouts|ish|should do(?: it)?|will do|is (?:fine|enough|plenty)))?(?=\s*(?:$|[.;,!?]))", r"\2\1", text)
    # chat shorthand: "on top blue" is on top of it, "blu 1" the blue one, "2 the left" to the left
    text = re.sub(r"\bon top (?!of\b)(?=(?:the |a |an |that |this )?[a-z])(?!(?:and|then|please|thanks|now|too)\b)", "on top of ", text)
    text = re.sub(rf"\b({'|'.join(COLOR_WORDS)}|big|small|little|large|tall|short|other|left|right|first|last|same) 1\b(?!\s*(?:cm|mm|in|inch|m)\b)", r"\1 one", text)
    text = re.sub(r"(?<=[a-z] )2(?= (?:the|left|right|front|back|behind|me|you|home|it|them|my|your)\b)", "to", text)
    text = re.sub(r"(\d),(\d)", r"\1.\2", text)  # decimal commas
    # "to the mug's left": to the left of the mug; "side by side": next to each other
    text = re.sub(r"\b(?:(?:to|toward|towards) )?(?:the |your )?(?:robot|franka|panda)'?s (left|right)\b", r"to the \1", text)  # its own
    text = _axes(text)
    text = re.sub(r"\b(to|on|at) (?:the )?([a-z ]+?)'s (left|right)(?: hand)?(?: side)?\b", r"\1 the \3 of the \2", text)
    text = re.sub(r"\b(?:to|on|at) (its|their) (left|right)(?:[- ]hand)?(?: side)?\b", lambda m: f"to the {m.group(2)} of {'it' if m.group(1) == 'its' else 'them'}", text)  # "the thing to its right"
    text = re.sub(r"\bside by side\b", "next to each other", text)
    # "the soda can furthest to the left": the leftmost one
    text = re.sub(r"\bthe ((?:[a-z]+ ){0,3}?[a-z]+) (?:that s |that is |which is |thats )?(?:the )?(?:furthest|farthest|most|the most) (?:to|on|at|over to) (?:the|your|my) (left|right)\b",
                  r"the \2most \1", text)
    text = re.sub(r"\b(?:the )?(?:two|three|four|both|all) of (?:them|those|these)\b", "them", text)
    text = re.sub(r"\s+for a (?:little |quick |short |well earned |well-earned |nice )?(?:rest|break|nap|breather|lie[- ]down|sit[- ]down|snooze|kip)\b", "", text)  # what it is for  # "put the two of them next to each other"
    text = re.sub(r"\b(closer to|nearer to|farther from|further from|farther away from|further away from) (?:me|you|the robot) than (?:it|they) (?:is|are|was|were)(?: now| at the moment)?\b",
                  lambda m: "closer" if m.group(1).startswith(("closer", "nearer")) else "further away", text)  # than where it is now
    text = re.sub(r"\b(?:to )?within (?:about |roughly |around |some )?(?:\d+(?:\.\d+)?|an?|one|two|three|four|five|a couple of|a few) ?(?:cm|mm|centimet\w*|millimet\w*|inch\w*|finger\w*)"
                  r" (?:of|from) (?=(?:the|that|this|it|them)\b)", "next to ", text)  # "to within a couple of centimetres of the blue one"
    text = re.sub(r"\bmore at (?:the )?(left|right)\b", r"more to the \1", text)  # "do it more at left"
    text = re.sub(r"\b(?:right|way|all the way) up (?=(?:next to|beside|against|close to|alongside)\b)", "", text)  # "put it right up next to the bottle"
    text = re.sub(r"\b(?:you )?do ((?:it|them|(?:the|that|this) [a-z ]+?)) (?=more (?:to the )?(?:left|right|forward|back)\b)", r"move \1 ", text)
    text = re.sub(r"\b(left|right)[- ]hand (?!side\b)(?=[a-z])", r"\1 ", text)  # "the right-hand one": the right one
    text = re.sub(r"\bmy (left|right)\b", r"the \1", text)  # the speaker stands behind the robot: their left is its left
    text = re.sub(r"\bthe (\w+) one of the (?:two |three |four |\d )?((?:[a-z]+ )?[a-z]+?)s\b", r"the \1 \2", text)  # "the right-hand one of the two soda cans"
    text = re.sub(r"\b(?:adjacent|adjoining|contiguous) to\b", "next to", text)
    text = re.sub(r"\b(?:to|at) (?=(?:behind|beside|in front of|next to|between|inside|onto|on top of)\b)", "", text)  # "to behind of", "at beside of"
    text = re.sub(r"\b(behind|beside|inside) of\b", r"\1", text)
    text = re.sub(r"\b((?:left|right)(?: hand)? side|front|back) from\b", r"\1 of", text)  # "on left side from X"
    text = re.sub(r"\b((?:closest|nearest|closer|nearer|furthest|farthest|further|farther)(?: away)? (?:to|from)) (?:the |your )?(?:robot'?s? )?base\b",
                  r"\1 the robot", text)  # the robot's base
    text = re.sub(r"\b(?:(?:in|into|inside|at|to|on|against|along|by) (?:the )?|(?<!the )(?<!\w))(left|right)(?:[- ]hand)? side of\b", r"to the \1 of", text)  # "in right side of X": a side
    text = re.sub(r"\b(?:in|into|inside|at|to|on) (?:the )?(?:front|near) side of\b", "in front of", text)
    text = re.sub(r"\b(?:in|into|inside|at|to|on) (?:the )?(?:back|rear|far) side of\b", "behind", text)
    text = re.sub(r"\b(?:towards?|to|in|into) (?:yourself|your self|your direction|the direction of you|your way)\b", "toward you", text)
    text = re.sub(r"\bbetween (?:(?:you|yourself|me|myself|the robot|us) and ((?:the|that|this) [a-z]+(?: [a-z]+)?)|((?:the|that|this) [a-z]+(?: [a-z]+)?) and (?:you|yourself|me|myself|the robot|us))(?: itself| yourself| myself)?\b",
                  lambda m: f"in front of {m.group(1) or m.group(2)}", text)  # "between the box and yourself": nearer the robot than the box
    text = re.sub(r"\bchange (?:the )?(?:place|places|position|positions|spot|spots)(?: of)? (.+?) (?:with|and) ", r"swap \1 with ", text)
    text = re.sub(r",? (?:so )?(?:each one|each|both)(?: of them)? (?:go|goes|ends? up|sits?|is) (?:where|in the place)(?: is)? the other(?: one)?(?: (?:is|was|sits|sat))?(?=$|[,.;!?])", "", text)
    text = re.sub(r"\bmake (it|them) (?:go|move|slide|shift)\b", r"move \1", text)  # "make it go left"
    # "the marker needs to come back ten mil": a thing that has to go some way is moved that way
    text = re.sub(r"\b(?:could|can|would|will|might) (it|they|that) (?=(?:come|go|move|slide|shift|get) )", r"\1 needs to ", text)  # "could it come toward me"
    text = re.sub(r"\b((?:the|that|this|my) [a-z ]+?|it|they) (?:needs|has|ought|must|should|is going|wants|would like)(?: to)? (?:come|go|move|slide|shift|get|be moved|be pushed|be slid) "
                  r"(?=(?:back|forwards?|backwards?|left|right|closer|nearer|away|ahead|toward|towards|over|\d|a |an |about|half|one|two|three|four|five|ten|to the left|to the right)\b)",
                  r"move \1 ", text)
    text = re.sub(r"\bmore (?:near|close)(?: (?:of|to|from))? (you|me)\b", r"closer to \1", text)  # "more near of you"
    text = re.sub(r"\bmore far(?: away)?(?: (?:of|to|from))? (you|me)\b", r"away from \1", text)  # "more far from you"
    text = re.sub(r"\b(to|on) (left|right)( hand)?( side)?\b", r"\1 the \2\4", text)  # "move it to right side"
    text = places.positions(text)
    text = re.sub(r"(?<!\ba )\b(little|tiny) bit\b", r"a \1 bit", text)
    text = re.sub(r"\b((?:the|that|this|my|it) ?[a-z]*(?: [a-z]+)?)'s been\b", r"\1 has been", text)  # "the green cube's been moved": has been
    # "the mug's dirty": the mug is (a statement), where "the mug's handle" is the mug's
    text = re.sub(r"\b((?:the|that|this|my) [a-z]+(?: [a-z]+)?)'s (?=(?:dirty|empty|full|broken|wet|sticky|heavy|too|so|really|very|not|just|still|always"
                  r"|in the way|in my way|blocking|sitting|lying|standing|getting|been|gonna|going|kind of|sort of|fine|ok|okay|a bit|a little|a|an|quite|rather|pretty"
                  r"|awkward|big|huge|bulky|massive|tiny|small|slippery|fragile|wobbly|tippy|light|hard|easy|awfully|dead|far|miles|right)\b)", r"\1 is ", text)
    text = re.sub(r"\b(it|that|this)'s (?=(?:in|on|at|too|so|very|really|just|blocking|sitting|standing|lying|right|not|still|a|an|the)\b)", r"\1 is ", text)  # "it's in the way"
    text = re.sub(r"(?<=\w)'(?:s|re|ll|d|ve)\b", "", text).replace("'", "")
    text = _CONSTRAINT.sub(" ", text)
    text = casual.described(casual.light_verb(text))
    text = re.sub(r"\b(?:your|my|the robot s|the robots) (left|right)\b", r"the \1", text)  # the robot faces the table as the speaker does
    text = re.sub(r"\bi like (?:you )?to\b", " ", text)  # "i'd like you to" once "'d" is gone
    text = re.sub(r"\bso (?:that )?(?:i|we|you|everyone|the class|the kids|they|people)(?: all)? (?:can|could|may|will) (?:see|watch|look at|check)"
                  r"(?: it| them)?\b", " ", text)  # what it is for, not what to do
    text = re.sub(r"\bmore (?:close|near)\b", "closer", text)
    # what the move is for, naming no place: "put the marker aside so it can think about what it did"
    text = re.sub(r"\s*,?\s*\bso (?:that )?(?:it|they|he|she|we|i|you|everyone|everybody|(?:the |our )?(?:people|audience|crowd|class|kids|guests|visitors|folks|judges)(?: [a-z]+){0,4}?)"
                  r" (?:can|could|will|would|may|might|gets to|get to|stops|stop|quits|no longer|isn t|is not|doesn t|does not|won t|will not|wont|isnt|doesnt) ([^.,;!?]*)",
                  lambda m: m.group(0) if has_relation(m.group(1)) or re.match(r"(?:be|sit|stand|rest|go|fit|stay|end up|lie|land)\b", m.group(1)) else "", text)
    text = re.sub(r"\bso (?:that )?(?:it|they|its)(?: (?:is|are|sits|sit|stands|stand|ends up|end up|lands|rests|will be|goes|stays|is now))?\b", " ", text)
    text = re.sub(r"\b(?:one by one|one at a time|one after (?:the )?other|individually|in turn)\b", " ", text)
    # a floating quantifier: "the cans all go in the bowl", "the mug and the can both go ..."
    text = re.sub(r"\b((?:them|they|the [a-z]+(?: [a-z]+)?)) (?:both|all|each)(?= (?:go|goes|belong|belongs|need|needs|should|must|have"
                  r"|has|in|into|inside|on|onto|next|beside|behind|to)\b)", r"\1", text)
    # "get the banana out of the way", "put the can to one side", "clear the mug away": aside (a later move makes it a take)
    text = re.sub(r"\b(?:(?:the|that|this|my) )?([a-z]+(?: [a-z]+)?) (?:is|s) (?:in (?:the|my|your) way|blocking(?: (?:things|everything|me|the way))?),? (?:(?:so|please|could you|can you) )*"
                  r"(move|get|shift|push|put|take) (?:it|that)(?: away)?(?=$|[.,;])", r"\2 the \1 aside", text)  # "the banana is in the way, move it"
    text = _IN_THE_WAY.sub(r"\1put \2 aside", text)
    text = _COMPLAINT.sub(lambda m: m.group(1) + ("" if m.group(2) == "you" else m.group(2)), text)  # "that foam brick keeps getting in my way.": a complaint said alone asks for it moved
    text = re.sub(r"\b(?:(?:somewhere|someplace|anywhere) else|elsewhere)\b", " aside ", text)
    text = re.sub(r"(?:,?\s*(?:and|then|and then) )?\b(?:stay|stop|remain|wait|sit tight|rest|keep still)(?: right)? (?:there|put|where it is|where you are|in place)(?=\s*(?:$|[.,;!?]))", "", text)  # "move it somewhere else"
    text = re.sub(r"\b(?:out of (?:the|my|your|our|his|her|their) (?:way|path|workspace|work space|work area|workzone|reach)(?: of [^,.;]*?(?=$|[.,;]| and\b| then\b))?|(?:from|off) (?:my|your|our|the) path|(?:off )?to (?:one|the|a) side(?! of\b))", " aside ", text)
    text = re.sub(r"\baside(?:\s+(?:somewhere|someplace|anywhere|for now|for a bit|for a while|aside))+\b", "aside", text)
    text = re.sub(r"\s+(?:first|to begin with|to start with|beforehand)(?=\s*[,;.]?\s*(?:and )?then\b)", "", text)  # "move the can aside first, then ...": in the order said  # "out of the way somewhere"
    text = re.sub(r"\b(?:put|tuck|stash|stow|store|set|place|park|clear) ([^,.;]+?)(?<!\bfurther)(?<!\bfarther)(?<!\bmore) (?:away|aside)(?=\s*(?:$|[.,;])| and\b| then\b)", r"put \1 aside", text)  # "tuck the banana away"
    text = re.sub(r"\bclear (away|off|out) (?!(?:the|that|this|those|these|my|your|a|an|it|them)\b)", r"clear \1 the ", text)  # "clear away cereal box"
    text = re.sub(r"\bclear (?:away |off |out )?((?:the|that|this|those|these|my|your|a|an) [a-z]+(?: (?!(?:away|off|out|aside|and|then)\b)[a-z]+)*?)"
                  r"(?: (?:away|off|out|aside))?(?: for (?:me|us))?(?=\s*(?:$|[.,;])| and\b| then\b)",
                  r"move \1 aside", text)
    # "the blocks in a line with the green one between the red and the blue": the one placed says the line
    text = re.sub(r"\b(?:(?:put|place|set|arrange|lay out|line up|get|have|want|need|like) )?(?:all )?(?:the (?:two |three |four |five )?(?:[a-z]+ )?([a-z]+s)|them|these|those)(?: up)?"
                  r" in (?:a|one) (?:straight )?(?:line|row)(?: up)?,? with (the [a-z ]+?) (?:(?:sitting|standing|placed|going|put|set|right|being) )*"
                  r"(between\b|in (?:the )?(?:middle|centre|center)\b(?: of (?:them|the line|the row))?)",
                  lambda m: f"put {m.group(2)} between" + ("" if m.group(3).startswith("between") else f" the other two{' ' + m.group(1) if m.group(1) else ''}"), text)
    text = re.sub(r"\bline ((?:up )?.+?)(?: up)? (?:with|next to|beside|alongside|by) ", lambda m: f"put {re.sub(r'^up ', '', m.group(1))} next to ", text)
    text = re.sub(r"\bline up (.+?)(?: in a row| side by side)?(?=$|[.,;]| then\b)|\bline (.+?) up(?: in a row| side by side)?(?=$|[.,;]| then\b)",
                  lambda m: f"put {m.group(1) or m.group(2)} next to each other", text)
    # "right" as an intensifier ("right beside the box"), not a side ("the can on the right next to ...")
    text = re.sub(r"(?<!the )(?<!far )(?<!further )(?<!farther )(?<!more )\bright (?=(?:next to|beside|behind|in front of|between|on top of|inside|into|onto|against|in|on)\b)", "", text)
    # "the cup, though, belongs on its left": a contrast set off in the middle of a clause is not a pause in it
    text = re.sub(r"\s*,\s*(?:though|however|by contrast|on the other hand|for its part|in turn|meanwhile|instead)\s*,\s*", " ", text)
    for filler in FILLERS:
        text = re.sub(rf"(?:(?<=^)|(?<=[\s,.;])){filler}(?=$|[\s,.;])", " ", text)
    text = re.sub(rf"(?:^|(?<=[\s,.;]))do (?={VERB_START.pattern})", "", text)  # "do go back home": emphasis
    text = re.sub(rf"\bafter(?:wards?)?,? (?={VERB_START.pattern})", "then ", text)  # "..., after go home": then (a gerund is still "-ing" here)
    for g, v in GERUNDS.items():
        text = re.sub(rf"\b{g}\b", v, text)
    text = re.sub(r"[^a-z0-9.,; ]+", " ", text)
    text = brands(" ".join(text.split()))
    # the object said first, then the robot told what it does with it: "the cereal box you are pushing 5 cm forward"
    text = re.sub(rf"(?:^|(?<=[.,;] ))((?:the|that|this) [a-z ]+?) you (?:{_YOU_MODAL} )?({VERB_START.pattern})", r"\2 \1", text)
    text = re.sub(rf"(?:^|(?<=[.,;] ))you (?:{_YOU_MODAL} )?(?={VERB_START.pattern})", "", text)  # "orange cylinder, you are sliding it left"
    text = _verb_last(text)
    return re.sub(r"\bto (forwards?|backwards?|ahead)\b", r"\1", text)  # "to forward"


# a phrase whose command verb comes last after "you" or "now" ("on the table you put it", "from the box the cup you
# take", "on the table now putting"): said verb first
_VERB_LAST = re.compile(rf"(?:^|(?<=[.,;] ))((?:the|that|this|from|off|out of|on|onto|in|into|next to|behind|to the)\b(?:(?![.,;]).)*?)"
                        rf"(?: (?:you|we|now))+ ((?:{VERB_START.pattern}))(?: (it|them))?(?=\s*(?:$|[.,;]))")  # "you" / "now" marks it: "on the stack" is no verb


def _verb_last(text: str) -> str:
    """``text`` with each verb-final phrase said verb first, its source after the thing taken
    ("take from the box the cup" -> "take the cup from the box"): a source is never the thing moved."""
    def first(m: re.Match[str]) -> str:
        said = f"{m.group(2)} {m.group(3) + ' ' if m.group(3) else ''}{m.group(1)}"
        return re.sub(r"^(\w+(?: up)?) ((?:from|off|out of) (?:the|that|this) [a-z ]+?) ((?:the|that|this) [a-z ]+)$", r"\1 \3 \2", said)
    return _VERB_LAST.sub(first, text)


def _by_comparison(text: str) -> str:
    """A place said by comparison with another thing: "closer to me than the mug (is)" is in front
    of it, "farther from me than the tin" behind it, "further left than the bottle" left of it."""
    text = re.sub(r"\b(?:closer|nearer) to (?:me|you|the robot|us) than ((?:the|that|this) [a-z ]+?)(?: is| are| does)?(?: now)?(?=$|[.,;!?])", r"in front of \1", text)
    text = re.sub(r"\b(?:farther|further) (?:away )?from (?:me|you|the robot|us) than ((?:the|that|this) [a-z ]+?)(?: is| are| does)?(?: now)?(?=$|[.,;!?])", r"behind \1", text)
    text = re.sub(r"\b(?:farther|further|more) (?:to the )?(left|right) than ((?:the|that|this) [a-z ]+?)(?: is| are| does)?(?=$|[.,;!?])", r"to the \1 of \2", text)
    return re.sub(r"\b(?:of|from|at|in) the (left|right)(?:[- ]hand)? side\b(?! of)", r"on the \1", text)  # "the can of the right side"


def split_command(command: str) -> list[str]:
    """Clauses at 'then', 'and then', 'after that', commas, semicolons, full stops and 'and' before
    a verb; parts without a verb are glued back ("the mug, the can and the banana")."""
    text = _in_order(clean(command))
    text = re.sub(r"\s+after(?=$|[.,;])", "", text)  # "go back home after"
    text = re.sub(r"\b(?:and after that|and then|after that|afterwards|afterward|and finally|and after|once (?:that s |that is |that |you re |you are |it s |it is |it |you )?(?:done|finished|over)"
                  r"|when (?:that s |you re |you )?(?:done|finished)|(?:but )?(?:in|at|by) the end)\b", ",", text)
    text = re.sub(r"\s+but (?=(?:dont|do not|never|no need to|leave|keep|stay)\b)", ", ", text)  # "..., but don't put the mug in it"
    text = _run_on(text)
    cut, lead = r"\s*(?:,|;|\.(?!\d)|\bthen\b|\band\b|\bbefore that\b)\s*", r"^(?:(?:first|firstly|second|secondly|next(?! to\b)|finally|lastly|last|also|and|then|after|to start|to begin)\s+)+"
    parts = [re.sub(lead, "", p.strip()) for p in re.split(cut, text) if p and p.strip()]
    # the phrase each sentence opens with: never the tail of the sentence before it
    opening = {re.sub(lead, "", first.strip()) for sentence in re.split(r"\.(?!\d)", text) if (first := next((q for q in re.split(cut, sentence) if q.strip()), ""))}
    clauses: list[str] = []
    verb_re = re.compile(rf"^(?:{'|'.join(re.escape(v) for v in sorted(ALL_VERBS, key=len, reverse=True))})\b")
    parts = [re.sub(rf"^you (?:{_YOU_MODAL} )?(?={verb_re.pattern[1:]})", "", p) for p in parts]  # "the banana, you (must) put in the bowl"
    parts = [_prohibition(p, verb_re) for p in parts]
    parts = topic.fronted(topic.joined(topic.choice(topic.partitive(parts)), verb_re), verb_re, comma=bool(re.match(r"[^,;.]*?(?<!\bthen)\s*,", text)))
    rel_re = re.compile(rf"\s(?:{'|'.join(re.escape(w) for w, _ in RELATIONS if w not in ('to', 'by', 'over', 'near'))})\s")
    for part in filter(None, parts):
        if clauses and clauses[-1].startswith("dont touch ") and re.fullmatch(r"(?:leave|keep off|not) (?:it|them|that)(?: alone| be)?", part):
            continue  # "Leave the mustard. Leave it!": said again
        if clauses and not verb_re.match(part) and not AGAIN.fullmatch(part) and not _DESIRE.match(part) and not _OTHER_VERB.match(part):
            verb = verb_re.match(clauses[-1])
            rel = rel_re.search(f" {clauses[-1]} ")
            # "the strawberry in the bowl and the banana too": a verbless placing lends its place as a put does
            put = verb.group(0) if verb and verb.group(0) in PUT else "" if not verb and rel and rel.start() > 0 and not _STATES.search(f"{clauses[-1]} {part}") else None
            if BEYOND.match(clauses[-1]):
                put = None  # "pour it into the red box, be daring and bold": no place lent on from what the robot cannot do
            if AVOID.match(part) or ((_WILL_BE.match(part) or _GOES_THERE.match(part)) and verb_re.match(clauses[-1])) or (
                    part in opening and _STATES.search(clauses[-1]) and not verb_re.match(clauses[-1]) and _NAMED_ALONE.fullmatch(part) and not _STATES.search(part)):
                # "these sodas are a mess. the one on the left, ...": a thing named after a statement is not part of it,
                # and named alone it says what "it" means next
                if not (AVOID.match(part) or _WILL_BE.match(part) or _GOES_THERE.match(part) or rel_re.search(f" {part} ")):
                    part = f"{topic.TOPIC}{part}"
                # "..., and don't touch the mug"; "..., it should be back where it is"; "... aside. the strawberry goes in the bowl": a step of its own
                clauses.append(part)
            elif (same := re.fullmatch(r"(?:(?:in|on|into|onto|to|at) )?(?:the )?same (\w+)(?: again| too| as well)?", part)) and rel and (
                    same.group(1) in ("place", "spot", "one", "location", "position") or re.search(rf"\b{same.group(1)}\b", clauses[-1][rel.start():])):
                continue  # "Red one too, same plate!": the place said again
            elif REFINE.fullmatch(part) and _SIDE_REL.search(f" {clauses[-1]} "):  # "put the can next to the bowl, on the left": which side
                clauses.append(part)
            elif _AMOUNT.fullmatch(part) or _MOTION.fullmatch(part) or (re.fullmatch(rf"(?:by )?{_HOW_FAR}(?: or so)?", part) and re.search(r"cm|mm|centimet|millimet|inch", part)):  # "bring the mug closer, 10 centimeter": how far; "red cube. forward ten cm": where
                clauses[-1] = f"{clauses[-1]} {part}"
            elif _OTHER_SIDE.fullmatch(part) and (flipped := _flip_side(clauses[-1])):  # "now the soup can, but the other side"
                clauses[-1] = flipped
            elif put is not None and rel and (m := re.fullmatch(rf"(.+?),? {_OTHER_SIDE.pattern}", part)) and (flipped := _flip_side(clauses[-1])):
                clauses.append(f"{put} {m.group(1)} {flipped[rel.start():].strip()}".strip())  # "the mug behind the bowl and the banana on the other side"
            elif m := re.fullmatch(r"the one ((?:on|at|in|to|closest|nearest|closer|nearer|furthest|farthest|further|farther|that|which)\b.*)", part):
                clauses[-1] = f"{clauses[-1]} {m.group(1)}"  # "pick up the green cube, the one furthest from you": which one
            elif WHICH_ONE.match(part):  # "..., which one is farthest from you? pick that one up": a question of its own
                clauses.append(part)
            elif re.match(r"(?:which|who) |that (?:is|are|was|were|s|sits|stands|lies|rests|has|have|had|looks|seems|i|you|we|they|it)\b", part):  # "... on the red cube, which is on the plate": says which
                clauses[-1] = f"{clauses[-1]} {part}"
            elif _PLACE_ALONE.fullmatch(part) and not rel_re.search(f" {_TOWARD_SPEAKER.sub('', clauses[-1])} "):
                # "put the mug, in front of the red can": where it goes, said after a pause; "closer to me, in front of the can": the place says how close
                clauses[-1] = f"{re.sub(rf'(?:,? and)?(?: down| over| back)? {_TOWARD_SPEAKER.pattern}$', '', clauses[-1])} {part}"
            elif put is not None and rel and rel_re.search(f" {part} "):
                clauses.append(f"{put} {part}".strip())  # "put the can in the bowl and the mug on the box"
            elif _SAYS.match(part):  # "..., my eyes aren't what they used to be": a remark of its own
                clauses.append(part)
            elif put is not None and rel and "between" not in rel.group(0) and not rel_re.search(f" {part} ") and not _AMOUNT.search(part):
                # "put the cube in the bowl and then the banana (too)": the same verb and place
                obj = re.sub(r"\s(?:too|as well|also)$", "", part)
                clauses.append(f"{put} {obj} {clauses[-1][rel.start():].strip()}".strip())
            elif re.match(r"(?:from|off|off of|out of) (?:the|that|this) ", part):
                clauses[-1] = f"{clauses[-1]} {part}"  # "strawberry, from the red cube down, ...": where it comes from, never another thing
            elif part in opening and clauses[-1].startswith("dont touch ") and not _STATES.search(part) and not rel_re.search(f" {part} ") and not part.startswith(("or ", "nor ")):
                clauses.append(f"{topic.TOPIC}{part}")  # "Leave the mustard. Rubik's cube instead, get it": the thing meant now, not one more kept still
            elif part in opening and not verb_re.match(clauses[-1]) and _NAMED_ALONE.fullmatch(part) and not _STATES.search(part) and not rel_re.search(f" {part} "):
                clauses.append(f"{topic.TOPIC}{part}")  # "..., drives me mad. The one on the left, could you ...": what "it" means next
            else:
                clauses[-1] = f"{clauses[-1]} and {part}"
        else:
            clauses.append(part)
    return clauses


_PLACE_ALONE = re.compile(rf"(?:(?:down|back|over|up) )?(?:{'|'.join(re.escape(w) for w, k in sorted(RELATIONS, key=lambda r: -len(r[0])) if k not in ('to', 'sides') and w not in ('by', 'over', 'near', 'toward', 'towards', 'closer to', 'nearer to'))}) (?:the|that|this|it|them)\b.*")
_TOWARD_SPEAKER = re.compile(r"\b(?:closer|nearer|close|near)(?: to)? (?:me|you|us|the robot|yourself)\b")  # a way, not a place by a thing
_STATES = re.compile(rf"\b{STATEMENT_VERB}\b")  # "the can is lined up behind the box, it looks cluttered": said of things, nothing placed
_OTHER_SIDE = re.compile(r"(?:but |and |only )*(?:on |to |at |onto )?(?:the )?(?:other|opposite) (?:side|way|one)(?: (?:this time|instead|of it|round|around))?")
_SIDES = {"left": "right", "right": "left", "in front of": "behind", "behind": "in front of"}


def _flip_side(clause: str) -> str | None:
    """``clause`` with its side of the reference turned to the opposite one ("left of" -> "right of"); None without a side."""
    m = re.search(r"\b(left|right|in front of|behind)\b(?=(?: of)? (?:the|that|this|it|them)\b)", clause)
    return None if m is None else f"{clause[: m.start()]}{_SIDES[m.group(1)]}{clause[m.end():]}"


_OTHER_VERB = re.compile(r"(?!(?:and|then|but|so|or|too|also|if|when|unless|once|because|since|while|until|whether|as|than|like|with|without|for|to|of|in|on|at|by|from)\b)[a-z]+ (?:them|it|me|you|us|him|her)\b")  # "prove them wrong": a verb the planner does not know, never an object
_THE_THING = r"(?:it|them|(?:the|that|this)(?: (?!and\b|then\b)[a-z]+)+?)"  # one object named, up to the next clause
_YOU_MODAL = r"(?:are going to|are|re|must to|must|should|have to|need to|will|can|could|shall|gotta|gonna)"  # "you must to put it ..."
_SIDE_REL = re.compile(rf"\s(?:{'|'.join(re.escape(w) for w, k in RELATIONS if k in ('next', 'left', 'right', 'front', 'behind'))})\s")
_AMOUNT = re.compile(r"(?:by )?(?:about |around |roughly )?\d+(?:\.\d+)? ?(?:cm|mm|centimet\w*|millimet\w*|inch\w*)")
# a way and how far alone ("forward ten centimetres", "two and a half centimetres back toward the robot", "half an inch toward me")
_HOW_FAR = (r"(?:(?:about|around|roughly|another|just) )?(?:\d+(?:\.\d+)?|a|an|one|two|three|four|five|six|seven|eight|nine|ten|fifteen|twenty|half an?|a couple(?: of)?"
            r"|a few|(?:one|two|three|four|five) and a half|three quarters of an?)(?: ?(?:cm|mm|centimet\w*|millimet\w*|inch\w*|mil|mils|hand s width|finger s width))?")
_WAY = (r"(?:(?:to the |to your |over to the )?(?:left|right)|forwards?|backwards?|back|ahead|away(?: from (?:me|you|the robot))?|(?:closer|nearer)(?: to)? (?:me|you|the robot)"
        r"|closer|nearer|toward(?:s)? (?:me|you|the robot))")
_MOTION = re.compile(rf"{_WAY}(?: {_WAY})* {_HOW_FAR}|{_HOW_FAR} {_WAY}(?: {_WAY})*")  # how far always: "the blocks, right, ..." is no push
_NOT_BEFORE_VERB = {"and", "then", "to", "you", "i", "we", "please", "dont", "not", "can", "could", "will", "would", "should", "must", "also",
                    "just", "me", "or", "so", "first", "firstly", "next", "second", "secondly", "finally", "lastly", "after", "afterwards",
                    "now", "let", "lets", "go", "help", "never", "gonna", "wanna"}


def _run_on(text: str) -> str:
    """A pause before a verb and "it" that the speaker did not mark ("grab the green one put it on
    the red one"): a clause boundary."""
    verbs = "|".join(re.escape(v) for v in sorted(PUT + PUSH + TAKE, key=len, reverse=True))
    return re.sub(rf"(?<=[a-z])(\s+)(?=(?:{verbs}) (?:it|them)\b)",
                  lambda m: ", " if text[: m.start()].split()[-1] not in _NOT_BEFORE_VERB else m.group(1), text)


_SAYS = re.compile(r"(?:my|our|i|we|you|they|he|she|this|these|those|there)\b.*\b(?:is|are|arent|isnt|was|were|am|have|has|had|can|cant"
                   r"|used to|looks?|seems?|will|shall|gonna)\b")
_AXIS = {"+x": "forward", "-x": "back", "+y": "left", "-y": "right"}


def _axes(text: str) -> str:
    """A roboticist's axes in the robot's frame ("5 cm in -y", "along +x"): the way they point;
    "i.e. ..." after it only says the same again."""
    text = re.sub(r"(?:\b(?:in|along|toward|towards|in the)\s+)?(?<![\w+-])([+-])\s?([xy])\b(?: (?:direction|axis))?",
                  lambda m: _AXIS[m.group(1) + m.group(2)], text)
    return re.sub(r",?\s*\b(?:i\.?\s?e\.?|in other words)(?=[\s,])[^.;]*", "", text)



_KEEP_STILL = re.compile(r"(?:but |and |while )?(?:(?:leave|keep) (.+?) (?:exactly |just |right )?(?:where (?:it|they) (?:is|are|was|were|sits?|stands?)(?: now)?"
                         r"|alone|as (?:it|they) (?:is|are)|in (?:its|their) (?:place|spot)|in place|be|untouched|still)"
                         r"|(?:keep|stay) (?:clear|away) (?:of|from) (.+)"
                         r"|leave ((?:the|that|this|those|these) (?:(?!(?:in|on|at|by|next|behind|beside|near|to|for|with|and|then|out|there|here)\b)[a-z]+ ?)+))")  # "leave the bowl!"


def _prohibition(part: str, verb_re: re.Pattern[str]) -> str:
    """"don't put the mug in the bowl", "not the banana": what is not to be done keeps its object
    still ("dont touch the mug"); it never becomes the action."""
    m = re.match(r"(?:but )?not (.+)$", part)
    if m and (re.match(r"(?:out |over |up |down )?(?:there|here|anywhere|somewhere|where)\b", m.group(1))
              or not re.search(r"\b(?:it|them)\b", m.group(1)) and relation_start(re.sub(r"^(?:out|over|up|down|back) ", "", m.group(1)))):
        return ""  # "put the can behind the box, not out in the open": a place ruled out, said beside the place meant
    if m and not verb_re.match(m.group(1)):
        return f"dont touch {m.group(1)}"
    m = _KEEP_STILL.fullmatch(part)
    if m and not re.fullmatch(r"(?:it|them|that|this|those|these)", kept := (m.group(1) or m.group(2) or m.group(3)).strip()):
        return f"dont touch {kept}"  # "leave the mug where it is", "keep clear of the bowl"
    m = re.match(r"(?:please )?(?:dont|don t|do not|never|no need to)\s+(.+)$", part)
    if not m or AVOID.match(part):
        return part
    if re.fullmatch(r"(?:place|put|set|drop|release|let go of|lay) (?:it|them)(?: down| back)?", m.group(1)):
        return ""  # "grasp the mug and hold it. do not place it": it stays in the hand
    verb = verb_re.match(m.group(1))
    if not verb and re.fullmatch(r"[a-z]+ (?:it|them)(?: over| up| down| too hard)?", m.group(1)):
        return ""  # "easy, don't squash it": how to handle what is being moved, not a thing to keep still
    rest = m.group(1)[verb.end():].strip() if verb else m.group(1)
    rest = re.sub(r"^(?:up|down|back|over)\s+", "", rest)
    cut = [i for i in (re.search(rf"\s{re.escape(w)}\s", f" {rest} ") for w, _ in RELATIONS) if i]
    obj = f" {rest} "[: min(i.start() for i in cut)].strip() if cut else rest
    return f"dont touch {obj}" if obj else part


def avoided(clause: str) -> tuple[str, str]:
    """A clause without a named thing not to touch, and that thing's phrase ("" if none): "don't
    touch the mustard" -> ("", "the mustard"); "pick up the cube without hitting the bowl" ->
    ("pick up the cube", "the bowl")."""
    m = AVOID.search(clause)
    if not m:
        return clause, ""
    parts = re.split(r",? (?:and|or|nor) ", m.group(1).strip())  # "the red or the blue cube": neither, each a cube
    head = parts[-1].split()[-1]
    parts = [f"{p} {head}" if p.split()[-1] in COLOR_WORDS or p.split()[-1] in (*BIG, *SMALL) else p for p in parts[:-1]] + parts[-1:]
    return clause[: m.start()].strip(), " and ".join(parts)


_PAST = {"picked": "pick", "grabbed": "grab", "taken": "take", "took": "take", "lifted": "lift", "moved": "move", "pushed": "push",
         "placed": "place", "dropped": "drop", "opened": "open", "closed": "close", "gotten": "get", "got": "get"}


def _in_order(text: str) -> str:
    """Clauses in the order they are to happen: "do A after you (have) done B" and "before you do
    A, do B" -> "B, A"; "do A before you do B" -> "A, B"."""
    verbs = "|".join(re.escape(v) for v in sorted([*ALL_VERBS, *_PAST], key=len, reverse=True))
    you = r"(?:you |i )?(?:have |ve )?"
    text = re.sub(r"\s+\.$", ".", text)
    m = re.fullmatch(rf"before {you}((?:{verbs})\b.+?), (.+)", text)
    # "put A where B was, but before that, move B": said after, done first; "A second, then/first B"; "A afterwards, first B"
    # ("A, and after that B" is in order); "A, but not until you've B"
    late = (re.fullmatch(r"(.+?),? (?:but |and )?(?:even )?(?:before (?:that|this|you do (?:that|this|it)|doing (?:that|this|so))|first(?: of all)?)[,:]? (.+?)\.?", text)
            or re.fullmatch(r"(.+?) (?:(?:second|last)[,;]? (?:then |and )?(?:first|before that)?|(?:afterwards|after that)[,;]? (?:then |and )?(?:first|before that))[,:]? ?(.+?)\.?", text)
            or re.fullmatch(rf"(.+?),? (?:but )?not (?:until|before) {you}((?:{verbs})\b.+?)\.?", text))
    if m:
        first, then = m.group(2), m.group(1)
    elif late and (VERB_START.match(late.group(2)) or late.group(2).split()[0] in _PAST):
        first, then = late.group(2), f"then {late.group(1)}"
    elif m := re.fullmatch(rf"(.+?),? (?:after|once|as soon as) {you}((?:{verbs})\b.+)", text):
        first, then = m.group(2), m.group(1)
    elif m := re.fullmatch(rf"(.+?),? before {you}((?:{verbs})\b.+)", text):
        first, then = m.group(1), m.group(2)
    else:
        return text
    first = re.sub(r"^\w+", lambda w: _PAST.get(w.group(0), w.group(0)), first)
    then = re.sub(r"^\w+", lambda w: _PAST.get(w.group(0), w.group(0)), then)
    if first != text and re.search(r"\bbefore (?:that|this)\b", first):  # "C, but before that B, and even before that A": A, B, C
        first = _in_order(first.rstrip("."))
    return f"{first}, {then}"


# "I'd like the can next to the box", "I need the box moved 5 cm left" (after clean(): "i like ...")
_DESIRE = re.compile(r"^i (?:would |d )?(?:like|want|need|wish)(?: you to| to have| to see)?\s+(.+)$")
_PARTICIPLE = re.compile(r"^(.+?)\s+(?:moved|put|placed|pushed|pulled|slid|shifted|set|taken|brought|stacked|dropped|"
                         r"nudged|shoved|scooted|dragged|carried|lifted|picked up|sitting|standing|lying)\b\s*(.*)$")
_PLACE_WORD = re.compile(r"\s(?:" + "|".join(re.escape(w) for w, k in RELATIONS if k != "to") + r")\s")
_ASK = re.compile(r"^(?:(?:can|could|may|might|shall) i (?:please )?(?:have|get|grab|borrow|take|see)|i (?:ll |will )?take)\s+(.+)$")
# "the banana goes in the bowl", "can the mug go in the bowl", "the cup should go behind the bowl"
_MODAL_WORDS = r"(?:should|needs to|need to|has to|have to|must|will|would|is to|ought to|is supposed to)"
WHICH_ONE = re.compile(r"(?:which|what) (one|\w+) (?:is|s) (.+)")
# a noun phrase said alone (no verb of its own: "the one on the left", not "the marker hasn't moved")
_NAMED_ALONE = re.compile(r"(?:the|that|this) (?:(?!(?:is|isnt|are|arent|was|wasnt|were|werent|has|hasnt|have|havent|had|does|doesnt|did|didnt|will|wont"
                          r"|can|cant|should|would|could|keeps|looks|seems|been|moved|got|gets)\b)[a-z]+ ?)+")
_GOES_THERE = re.compile(r"^(?:the|that|this|my|it|they)\b[a-z ]*? (?:goes|go|belongs|belong|needs to go|has to go|ought to go|is going) (?:back )?(?:in|into|inside|on|onto|next|beside|behind|in front|left|right|between|to the)\b")
_WILL_BE = re.compile(rf"^.+? {_MODAL_WORDS} (?:have |be |go |end up |stay )")
_MODAL = r"(?:should|needs to|need to|has to|have to|must|can|could|will|would|is to|ought to|is supposed to)"
_GOES = re.compile(rf"^(?:(?:can|could|will|would|should|shall|may) )?(.+?)\s+(?:[a-z]+ly\s+)?(?:(?:{_MODAL}\s+)?(?:go|be|sit|end up|stand|live|stay)(?: (?:sitting|standing|lying|resting))?"
                   r"|goes|belongs|belong|sits|stays|lives|is going|are going|ends up|lands)\s+(?:(?:down|over|right) )?(.+)$")


# Statements and passives that say what should happen, with the imperative each means ({0}, {1}: its groups).
_STATEMENTS: tuple[tuple[re.Pattern[str], str], ...] = (
    # "could the can be picked up"
    (re.compile(r"^(?:can|could|would|will|should|may|might|shall) (.+?) be (?:picked up|lifted|raised)$"), "pick up {0}"),
    # "could the mug be moved into the bowl"
    (re.compile(r"^(?:can|could|would|will|should|may|might|shall) (.+?) be (?:moved|pushed|shifted|slid|put|placed|set|dropped|stacked|transferred)\b\s*(.+)$"),
     "move {0} {1}"),
    # "the box needs to be moved 5 cm forward"
    (re.compile(rf"^(.+?) (?:{_MODAL} (?:have been|be|get)|is to be|are to be|wants to be|want to be|has been|have been|is|are|was|were|gets|got)"
                r" (?:moved|pushed|shifted|slid|put|placed|set)\b\s*(.+)$"),
     "move {0} {1}"),
    # "the red can and the white can should have traded places"
    (re.compile(rf"^(?:(?:it |that )?(?:would |d |will )?be \w+ if )?(.+?) (?:{_MODAL} |to )?(?:have |had )?(?:traded|swapped|switched|exchanged|trade|swap|switch|exchange)"
                r" (?:places|positions|spots|seats|squares)$"), "swap {0}"),
    # "it'd be great if the banana was in the bowl": the state wished for, made
    (re.compile(r"^(?:it |that |this )?(?:would |d |will |s |is )?be (?:great|nice|good|lovely|helpful|awesome|perfect|ideal|brilliant|wonderful|cool|best|better)"
                r" if (.+?) (?:was|were|is|are|sat|stood|ended up|could be|would be) (.+)$"), "put {0} {1}"),
    # "the bowl needs the banana in it", "the plate could use the cube on it": the thing it wants there
    (re.compile(r"^(.+?) (?:needs|wants|could use|should have|must have|has to have|is missing) (.+?) (in|on|inside|on top of|next to|beside|behind|in front of) (?:it|them)$"),
     "put {1} {2} {0}"),
    # "at the end it should be right back where it is now"
    (re.compile(rf"^(.+?) (?:{_MODAL} )?(?:be|end up|stay|go)? ?(?:right )?back (?:where (?:it|they) (?:is|are|was|were|started)(?: now)?|in (?:its|their) (?:place|spot))$"),
     "put {0} back"),
)



def rephrase(clause: str) -> str:
    """The imperative a clause without a leading verb means, or the clause unchanged: a wish
    ("i like X next to Y" -> "put X next to Y"; "i need X moved 5 cm left" -> "move X 5 cm left"),
    a statement of where a thing goes ("X goes/should go/belongs in Y" -> "put X in Y"), or a bare
    object and place ("mug in the bowl" -> "put mug in the bowl")."""
    c = clause.strip()
    m = _ASK.match(c)
    if m:  # "can i have the banana": a request to be handed it
        return f"hand me {m.group(1)}"
    m = _DESIRE.match(c)
    if m:
        rest = re.sub(r"\s+to (?:be|go|sit|stand|end up|stay|rest|lie)(?= )", "", m.group(1))  # "i want X to be next to Y"
        p = _PARTICIPLE.match(rest)
        if p and p.group(2):
            return f"move {p.group(1)} {p.group(2)}"
        if p and re.search(r"\b(?:picked up|lifted)$", rest):  # "i'd like the cylinder picked up"
            return f"pick up {p.group(1)}"
        # "i want the mug by the bowl": put it there; "i want the banana": give it to me
        if said := casual.terse(rest, has_relation(rest)):  # "i'd like the cube an inch further away"
            return said
        placed = _PLACE_WORD.search(f" {rest} ")
        return f"put {rest}" if placed else f"hand me {rest}"
    for pattern, imperative in _STATEMENTS:
        if m := pattern.match(c):
            return imperative.format(*m.groups())
    if not VERB_ANYWHERE.search(c) and (said := casual.terse(c, has_relation(c))):  # "cereal box forward 10cm", "all cans by bowl"
        return said
    m = _GOES.match(c)
    if m and relation_start(m.group(2)):
        return f"put {m.group(1)} {m.group(2)}"
    if has_relation(" ".join(c.split()[1:])) and not VERB_ANYWHERE.search(c):
        return f"put {c}"
    return speech.object_first(c, VERB_ANYWHERE) or c  # "the red fruit put in front of the banana"
