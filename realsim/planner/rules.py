"""Offline rule planner: English as people say it -> primitive calls and the goals to check.

A command is cleaned of polite and filler words ("could you please", "go ahead and", "for me"),
split into clauses ("then", "and then", "after that", commas, "and" before a verb), and each
clause is read as a verb phrase ("pick up", "set down", "drop into", "put back", "slide"...),
the objects it acts on (see :mod:`realsim.planner.reference`: pronouns, colours, sizes,
ordinals, locators, quantities), and a relation to a target (in, on, onto, next to, left of,
right of, behind, in front of, between, on the table) or a push direction and distance.
Quantities ("all the cans", "both blocks", "the mug and the can") become one call per object.
The planner emits a typed :class:`Program` of :class:`Call` objects, which runs through the
registry's bindings; its rendered text is for display and logs.
Anything it cannot read, or any reference that is unknown or ambiguous, raises
:class:`InputError` naming the candidates: nothing is done to a wrong object.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

from realsim.errors import InputError
from realsim.planner import aliases, compass, measures, typos
from realsim.planner.aside import ASIDE, WHERE, aside, where_was
from realsim.planner.asides import is_aside, without_talk
from realsim.planner.conditions import branch
from realsim.planner.fit import check_fits, held_in, holds_things
from realsim.planner.goals import AtHome, Between, Checkpoint, DrawerClosed, DrawerOpen, Goal, Inside, Lifted, NextTo, On, OnTable, Placed, SideOf
from realsim.planner.lexicon import AGAIN, ALL_VERBS, BEYOND, PARTICLES, PUSH, PUT, RELATIONS, SURFACES, TAKE, VERB_START, relation_start
from realsim.planner.mentions import mentioned, named_alone
from realsim.planner.phrasing import avoided, rephrase, split_command
from realsim.planner.program import Call, Program
from realsim.planner.push_clause import TOWARD, push_clause, push_relative
from realsim.planner.pushes import beside_measure, distance, is_push
from realsim.planner.reference import Context
from realsim.planner.refine import refine, refines
from realsim.planner.sentences import cleaned, is_question, is_request, split_pieces, split_sentences
from realsim.planner.steps import EACH_OTHER, SWAP, Parser, Step, each_other, objects_named, other_side, repeat, swap
from realsim.planner.topic import TOPIC, compared
from realsim.planner.types import ObjectInfo, Plan
from realsim.planner.vocab import COLOR_WORDS, GENERIC, VAGUE_DISTANCES, name_words, norm, singular

HELP = (
    "the offline planner understands: pick up X; put X in/on/next to/left of/behind/between Y; put X on the table; "
    "put X back/down; push X left/right/forward/back (by N cm); open/close the drawer; open/close the gripper; go home "
    "(joined by 'then', 'and' or commas; X may be 'it', 'all the cans', 'the big red box', 'the second can from the left'); "
    "set ANTHROPIC_API_KEY to use Claude for free-form commands"
)


class RulePlanner:
    """The offline planner; its calls are the same primitives Claude's programs use."""

    name = "rules"

    def plan(self, command: str, scene_objects: list[ObjectInfo], robot_yaw: float = 0.0,
             robot_base: tuple[float, float] | None = None) -> Plan:
        calls, goals, checkpoints = _planned(command, scene_objects, robot_yaw, robot_base)
        program = Program(tuple(calls), command)
        return Plan(program=program.source(), goals=goals, planner=self.name, calls=program, checkpoints=checkpoints)

_OTHER_TWO = re.compile(r"(?:the )?(?:other (?:two|2)|two others|other ones|others|rest)(?: (?:of the )?([a-z]+s))?")  # "between the other two cubes"

def parse_calls(command: str, objects: Sequence[ObjectInfo], robot_yaw: float = 0.0,
                robot_base: tuple[float, float] | None = None) -> tuple[list[Call], list[Goal]]:
    """Primitive calls and the goals that hold at the end for ``command``; raises :class:`InputError` when it cannot."""
    return _planned(command, objects, robot_yaw, robot_base)[:2]


def _planned(command: str, objects: Sequence[ObjectInfo], robot_yaw: float,
             robot_base: tuple[float, float] | None) -> tuple[list[Call], list[Goal], list[Checkpoint]]:
    """The calls of ``command``, its goals at the end, and its checkpoints."""
    steps = parse_steps(command, objects, robot_yaw, robot_base)
    goals, checkpoints = _goals(steps, {o.name: o.position[:2] for o in objects})
    return [c for s in steps for c in s.calls], goals, checkpoints


def parse_steps(command: str, objects: Sequence[ObjectInfo], robot_yaw: float = 0.0,
                robot_base: tuple[float, float] | None = None) -> list[Step]:
    """The steps (calls and goals) ``command`` asks for; raises :class:`InputError` when it cannot."""
    # "the mug is Falcon", "north is away from you", "call a square 5 cm": what the speaker set up, said plainly
    command = measures.made_up_units(compass.bearings(aliases.named(command)))
    if is_question(command):
        raise InputError(f"{command.strip()!r} is a question; realsim acts on commands such as 'put the mug in the bowl'")
    try:
        return _finish(*_read(command, Parser(objects, robot_yaw, robot_base)))
    except InputError:
        for units, pieces in ((split_sentences(command), False), (split_pieces(command), True)):  # sentences, then phrases between commas
            read = _read_by_unit(units, Parser(objects, robot_yaw, robot_base), pieces) if len(units) > 1 else None
            if read is not None:
                return _finish(*read)
        raise


def _read(command: str, p: Parser) -> tuple[list[Step], dict[str, str]]:
    """The steps of ``command`` and the objects it says not to touch (name -> how it was named)."""
    command = branch(command, p.resolver) or command  # "if the mug is in the bowl, ...": the branch that holds
    clauses = split_command(command)
    if not clauses:
        raise InputError(f"the command is empty; {HELP}")
    steps: list[Step] = []
    kept: dict[str, str] = {}  # objects the command says not to touch, and how it named them
    asides: list[InputError] = []  # clauses that were talk around the command ("ugh my desk is a mess")
    for c in clauses:
        c, phrase = avoided(c)
        if phrase:  # the robot keeps clear of every object it is not asked to move; a named one it must not move at all
            named = p.resolver.resolve(phrase, Context(p.ctx.last), allow_plural=True)
            kept |= {o.name: phrase for o in named}
            p.ctx.set(named)
        if c.startswith(TOPIC) and (m := BEYOND.match(c[len(TOPIC):])):  # "peel the banana and put it in the bowl": the peel cannot be done
            raise InputError(f"the robot cannot {m.group(0)}: it picks up, puts, pushes, swaps and opens drawers; {HELP}")
        if c.startswith(TOPIC):  # "the thing at the back, push it ...": what "it" means next
            p.ctx.set(p.resolver.resolve(c[len(TOPIC):], Context(p.ctx.last), allow_plural=True))
        elif c and steps and refines(steps[-1], " ".join(c.split())):  # "put the can next to the bowl, on the left"
            steps[-1] = refine(steps[-1], " ".join(c.split()))
        elif c:
            try:
                step = repeat(steps) if AGAIN.fullmatch(" ".join(c.split())) else typos.retry(c, p.resolver.scene_words, lambda t: _clause(t, p))
                if not (steps and _same(step, steps[-1])):  # "Mug, up. Lift it.": held already; "On the plate. ON it.": said again
                    steps.append(step)
                    p.moved |= set(step.objects)
            except InputError as exc:
                step = _salvaged(c, p)  # "pick up the banana and let's go": the command without its talk
                if step is not None:
                    steps.append(step)
                    p.moved |= set(step.objects)
                    continue
                if not named_alone(c, p) and not is_aside(c, p):  # "mm, the foam brick, the red one, ...": what "it" means next
                    raise
                asides.append(exc)
    if asides and not steps and not kept:
        raise asides[0]
    return steps, kept


def _read_by_unit(sentences: list[str], p: Parser, pieces: bool = False) -> tuple[list[Step], dict[str, str]] | None:
    """The steps of a message read one sentence (or phrase) at a time, when it does not read as a
    whole: a sentence that is talk ("we're back!", "for the LAST time:", "Which one is the mug?
    Right.") is skipped, or names what "it" means next; a request that cannot be done is never
    skipped (None: the whole message is refused). A phrase (``pieces``) is skipped only when it
    names no thing of the scene and sets no condition ("gosh", "totally fine if not" is one)."""
    steps: list[Step] = []
    kept: dict[str, str] = {}
    for sentence in sentences:
        before, moved, taken = list(p.ctx.last), set(p.moved), list(p.taken)
        try:
            more, also_kept = _read(sentence, p)
        except InputError:
            p.moved, p.taken = moved, taken  # what a failed sentence began is undone
            p.ctx.set(before)
            if not cleaned(sentence):  # "Totally fine if not.": polite words only
                continue
            placed = _placed_there(sentence, p) or _asked_within(sentence, p)  # "Green cube. On the plate."; "I hate to ask, but could you ..."
            if placed is not None:
                more, also_kept = placed
            elif is_request(sentence, p.resolver.scene_words) or (pieces and not _idle(sentence, p)):
                return None
            elif re.match(r"(?:from|off|off of|out of)\b", cleaned(sentence)):  # "..., from the box down, ...": where it comes from, never "it"
                p.ctx.set(before)
                continue
            else:
                p.ctx.set(mentioned(sentence, p) or before)
                continue
        steps += [s for s in more if not (steps and _same(s, steps[-1]))]  # "On the plate. ON it.": said again
        kept |= also_kept
    return (steps, kept) if steps else None


_POINTS = re.compile(r"\b(?:it|them|one|ones|that|this|those|these|there|here|left|right|front|back|behind|near|next|on|in|into|onto|touch\w*|move\w*|drop\w*)\b")


def _idle(piece: str, p: Parser) -> bool:
    """Whether a phrase is idle talk: no condition, choice or negation, and no thing of the scene
    named except as the one thing it is about ("la banana")."""
    words = re.sub(r"[^a-z0-9 ]", " ", piece.lower()).split()
    said = {w for w in p.resolver.scene_words if w not in GENERIC} | set(COLOR_WORDS)
    names = any(w.isdigit() or singular(w) in said for w in words)
    if re.search(r"\b(?:if|unless|when|whenever|otherwise|instead|out of|among|of all|except|but)\b", piece.lower()):
        return False
    if re.search(r"\b(?:not|no|dont|don't|never)\b", piece.lower()) and (names or _POINTS.search(piece.lower())):
        return False  # "not the red one", "don't drop it"; "no fumbles allowed" denies nothing of the scene
    return named_alone(piece, p) or not names


def _asked_within(sentence: str, p: Parser) -> tuple[list[Step], dict[str, str]] | None:
    """The request a hedge leads up to: what follows "to", "you", "could", "please" ... when it
    begins with a verb the planner knows ("I was wondering, if it's no bother, whether you might
    nudge the brick 2 cm left")."""
    said = cleaned(sentence)
    m = re.search(rf"\b(?:to|you|could|would|might|can|will|please|kindly|just)\s+(?={VERB_START.pattern})", said)
    if m is None:
        return None
    try:
        return _read(said[m.end():], p)
    except InputError:
        return None


def _placed_there(sentence: str, p: Parser) -> tuple[list[Step], dict[str, str]] | None:
    """A sentence that is only a place ("On the plate.") after a thing was named: that thing put there."""
    place = cleaned(sentence)
    if not p.ctx.last or not relation_start(place):
        return None
    m = re.fullmatch(r"(.+?) (?:it|there|that one)(?: (?:goes|go|it goes|please))?", place)
    if m and len(p.ctx.last) == 1 and len(p.ctx.seen) >= 2 and p.ctx.seen[-2] != p.ctx.last[0]:
        thing, target = p.ctx.seen[-2], p.ctx.last[0]  # "Strawberry. Bowl. In it goes.": the first named, into the second
        try:
            return _read(f"put {thing.name} {m.group(1)} {target.name}", p)
        except InputError:
            return None
    try:
        return _read(f"put it {place}", p)
    except InputError:
        return None


def _finish(steps: list[Step], kept: dict[str, str]) -> list[Step]:
    """The steps to run, checked: no pending take, nothing the command said not to touch."""
    for i, step in enumerate(steps):
        if step.pending and not any(s.objects for s in steps[i + 1 :]):
            raise InputError(step.pending)
    steps = _superseded(steps)
    calls = [c for s in steps for c in s.calls]
    clash = sorted({str(a) for c in calls for a in c.args if isinstance(a, str) and a in kept})
    if clash:
        raise InputError(f"the command says not to touch {', '.join(kept[n] for n in clash)} ({', '.join(clash)}) but also acts on it; "
                         "say which you mean")
    if not steps:
        raise InputError(f"the command only says what not to touch; what should I do? {HELP}")
    return steps


def _same(step: Step, before: Step) -> bool:
    """Whether ``step`` only says ``before`` again: the same calls to the same ends ("swap the can and
    the mug (swap 'em)" is one swap)."""
    return [c.name for c in step.calls] == [c.name for c in before.calls] and sorted(map(repr, step.goals)) == sorted(map(repr, before.goals))


def _salvaged(clause: str, p: Parser) -> Step | None:
    """The step of ``clause`` without talk glued to its ends, or None when no such cut reads."""
    for head in without_talk(" ".join(clause.split()), p):
        if not VERB_START.match(head) and not re.search(r"\b(?:goes|go|belongs?|should (?:be|go|sit))\b", head):
            continue  # what is left must still ask for something: "the cubes" alone is not a command
        try:
            return _clause(head, p)
        except InputError:
            continue
    return None


def _superseded(steps: list[Step]) -> list[Step]:
    """An object moved out of the way that a later step moves anyway is only taken up first
    ("get the banana out of the way, put it behind the box")."""
    out = []
    for i, step in enumerate(steps):
        later = {o for s in steps[i + 1 :] for o in s.objects}
        if step.aside and len(step.objects) == 1 and step.objects[0] in later:
            step = Step([Call("grasp", step.objects)], [Lifted(step.objects[0])], step.objects)
        out.append(step)
    return out


def _goals(steps: list[Step], starts: dict[str, tuple[float, ...]]) -> tuple[list[Goal], list[Checkpoint]]:
    """Goals still to hold once every step is done, and checkpoints for those a later step undoes
    (a mug put in the bowl, then taken out; home, then the arm moved again): each checked when its
    step ends. A lift that a later placing needs anyway is no checkpoint; one before the object is
    put back where it started ("lift it, then put it back") is the point of the command, and is."""
    goals: list[Goal] = []
    checkpoints: list[Checkpoint] = []
    done = 0
    for i, step in enumerate(steps):
        later = steps[i + 1 :]
        later_objects = {o for s in later for o in s.objects}
        for g in step.goals:
            if isinstance(g, AtHome):
                kept = not any(s.moves_robot and not any(isinstance(h, AtHome) for h in s.goals) for s in later)
            else:
                kept = getattr(g, "obj", None) not in later_objects and not _disturbed(g, later)
            if kept:
                goals.append(g)
            elif step.calls and not (isinstance(g, Lifted) and not _put_back(g.obj, later, starts)):
                checkpoints.append(Checkpoint(done, done + len(step.calls), g))
        done += len(step.calls)
    return goals, checkpoints


def _put_back(obj: str, later: list[Step], starts: dict[str, tuple[float, ...]]) -> bool:
    """Whether the last goal later steps set for ``obj`` puts it down where it started (within 2 cm)."""
    placed = [g for s in later for g in s.goals if getattr(g, "obj", None) == obj]
    start = starts.get(obj)
    return (bool(placed) and isinstance(placed[-1], Placed) and start is not None
            and math.dist(placed[-1].xy, start[:2]) <= 0.02)


def _disturbed(goal: Goal, later: list[Step]) -> bool:
    """A relation to an object that a later step moves is not checked (it was true when made),
    except what a pushed container or support carries along ("... then push the bowl")."""
    later_objects = {o for s in later for o in s.objects}
    if isinstance(goal, (Inside, On)):
        pushed = {c.args[0] for s in later for c in s.calls if c.name == "push" and c.args}
        handled = {c.args[0] for s in later for c in s.calls if c.name != "push" and c.args}
        later_objects -= pushed - handled
    refs = [getattr(goal, a, None) for a in ("container", "support", "ref", "a", "b")]
    return any(r in later_objects for r in refs if r)


# ----------------------------------------------------------------------------------------------
# clauses


def _clause(clause: str, p: Parser) -> Step:
    c = " ".join(clause.split())
    if re.fullmatch(r"(?:(?:go|return|move|come|head|get)(?: back)?(?: to)?(?: (?:the|your))? (?:home|start|starting|rest|resting|initial|ready|normal|usual|original|default|neutral)"
                    r"(?: position| pose| posture| point| spot| place)?|reset(?: yourself| the arm| arm)?|home(?: it| the arm| yourself)?|(?:go back and )?(?:have|take) a (?:rest|break)|go back|return|retract(?: the arm)?"
                    r"|(?:go|move|return|come) home)", c):
        return Step([Call("go_home")], [AtHome()])
    m = re.fullmatch(r"(open|close|shut) (?:the |your )?(?:gripper|hand|fingers|claw)|release(?: it| that| the object)?|let (?:it )?go(?: of it)?|drop it|let go of (.+)", c)
    if m:
        if c.startswith(("release", "let", "drop")) or m.group(1) == "open":
            return Step([Call("open_gripper")], [], moves_robot=False)
        return Step([Call("close_gripper")], [], moves_robot=False)
    m = re.fullmatch(r"(pull open|pull out|open|close|shut|push in|push closed|push shut) (.+?)(?: all the way| fully| completely| halfway)?", c)
    if m and (m.group(1) in ("open", "close", "shut") or re.search(r"drawer|door|cabinet|lid", m.group(2))):
        return _articulate(m.group(1), m.group(2), p)
    m = SWAP.fullmatch(c)
    if m:
        return swap(m.group(1), m.group(2), p)
    if not re.search(r"\b(?:closer|nearer)\b", c):  # "bring the mug closer to me" moves it, not into the hand
        c = re.sub(r"^(?:hand|pass|give|bring) (.+?) (?:over to me|over here|over|to me|here)$", r"hand me \1", c)
    verb, rest = _verb(c)
    if verb is None and (m := BEYOND.match(c) or _BEYOND_ASKED.search(c)):  # "(how about you) pour the soup into the bowl": no primitive does it
        raise InputError(f"the robot cannot {m.group(1) if m.lastindex else m.group(0)}: it picks up, puts, pushes, swaps and opens drawers; {HELP}")
    if verb is None and (m := _MEANS.fullmatch(c)):  # "tidy up by putting the mug in the bowl": the means is the command
        return _clause(m.group(1), p)
    if verb is None:  # "the banana goes in the bowl", "i like the can next to the box", "mug in the bowl"
        said = rephrase(c)
        if m := SWAP.fullmatch(said):  # "the can and the box should have traded places"
            return swap(m.group(1), m.group(2), p)
        verb, rest = _verb(said)
    if verb is None:
        raise InputError(f"cannot understand {clause!r}; {HELP}")
    if verb in (*PUT, *PUSH, *TAKE) and (m := ASIDE.fullmatch(rest)):  # "move the banana out of the way"
        return aside(m.group(1), p)
    if verb in (*PUT, *TAKE) and (m := WHERE.fullmatch(rest)) and (step := where_was(m.group(1), m.group(2), p)) is not None:
        return step  # "put the mug where the banana was"
    if re.search(r"\b(?:further|farther|more) (?:to the )?(?:left|right|back|forward|front)\b(?=.*\b(?:on|onto|in|into|inside|next to|beside|behind"
                 r"|in front of|between|on top of)\s+(?:the|a|an|it|them)\b)", rest):
        rest = compared(rest)  # "put the cube further left on the plate": which cube, then where
    # "bring the mug 5 cm closer": any moving verb with a way and a distance (or "closer") is a push
    by = verb in PUT and (distance(rest) is not None or re.search(r"\b(?:closer|nearer|further|farther)\b", rest)
                          or re.search(r"\bto the (?:left|right)(?: side)?(?: a bit| a little| slightly)?$", rest))  # "put the mug to the left"
    m = TOWARD.fullmatch(rest) if verb in (*PUSH, *PUT, *TAKE) else None
    if m and verb not in PUSH and "away from" not in m.group(2):  # "take the mug away from the bowl": only away moves it
        m = None
    if m and (verb not in PUT or "from" in m.group(2) or distance(rest) is not None):
        return push_relative(m, distance(rest), p)  # "push the mug toward the bowl"; "slide X toward Y" puts it next to Y
    if (verb in PUSH or by) and is_push(rest):
        # "move it further left": "further" says more of that way, not away
        return push_clause(re.sub(r"\b(?:further|farther|more)\s+(?=(?:to the )?(?:left|right|back|backwards?|forwards?|ahead)\b)", "", rest), p, clause)
    if verb in ("hand me", "give me", "pass me", "bring me"):
        return _take(rest, p)
    if verb in PUT:
        step = _put(verb, rest, p, clause)
        if step is not None:
            return step
        if verb in TAKE:
            return _take(rest, p)
        raise InputError(f"where to? {clause!r} names no place I can read (in, on, next to, left of, behind, between, "
                         f"on the table, back, down); {HELP}")
    if verb in TAKE:  # "take the can to the bowl" moves it; "take the can on the left" only names it
        if verb in _LIFTS and _find_relation(rest) and (named := _named_by_place(rest, p)):
            return named  # "pick up the can next to the bowl" where one can is next to it: that can, lifted
        try:
            step = _put(verb, rest, p, clause) if _find_relation(rest) else None
        except InputError:
            step = None
        return step if step is not None else _take(rest, p)
    raise InputError(f"cannot understand {clause!r}; {HELP}")


# a verb no primitive does, asked of the robot inside a clause ("how about you pour the soup", "I need you to peel it")
_BEYOND_ASKED = re.compile(rf"\b(?:you|to|please|just|and|then|could|can|would|will|must|should)\s+({BEYOND.pattern[:-2]})\b(?=\s+(?:the|it|them|that|this|some|a|an|out|in|into|over|up)\b)")
_MEANS = re.compile(rf".+? by ((?:{VERB_START.pattern}).+)")  # a purpose, then "by" and what to do


def _verb(c: str) -> tuple[str | None, str]:
    for v in sorted(ALL_VERBS, key=len, reverse=True):
        if c == v or c.startswith(v + " "):
            return v, c[len(v):].strip()
    return None, c


_LIFTS = ("pick up", "pick", "grab", "grasp", "lift up", "lift", "raise", "hold up", "hold", "snag")  # what only lifts: never carries somewhere


def _named_by_place(rest: str, p: Parser) -> Step | None:
    """The lift of the one object ``rest`` names with its place ("the red thing behind the cube"), if the place holds now."""
    before = list(p.ctx.last)
    try:
        found = p.resolver.resolve(rest, Context(p.ctx.last), allow_plural=False)
        head = p.resolver.resolve(rest[: _find_relation(rest)[0][0]].strip(), Context(p.ctx.last), allow_plural=True, loose=True)
        if len(found) == 1 and found[0] in head:  # the place picks one of what the words before it name
            return _take(rest, p)
    except InputError:
        pass
    p.ctx.set(before)
    return None


def _take(rest: str, p: Parser) -> Step:
    rest = re.sub(r"\s+(?:up|off the table|from the table|up high|in the air|into the air|and hold it|at (?:lift|that|this|the same|full) height)$", "", rest)
    # "lift the cube 5 cm": a lift has one height (about 10 cm); the number does not name the object
    rest = re.sub(r"\s+(?:up )?(?:by )?(?:about |around )?\d+(?:\.\d+)? ?(?:cm|mm|centimet(?:er|re)s?|millimet(?:er|re)s?|inch(?:es)?)"
                  r"(?: up| high| off the table| into the air| in the air)?$", "", rest)
    # "lift the mug up a bit", "raise the can slightly": a lift has one height, a vague amount too
    vague = "|".join(re.escape(w) for w in sorted(VAGUE_DISTANCES, key=len, reverse=True))
    rest = re.sub(rf"(?:\s+up)?\s+(?:{vague})(?:\s+(?:up|higher|off the table))?$", "", rest)
    objs = objects_named(rest, p)
    if len(objs) > 1:  # "take the banana and the strawberry and put them in the bowl": the put carries them
        p.ctx.set(objs)
        return Step([], [], (), moves_robot=False,
                     pending=f"the hand holds one object at a time: {', '.join(o.name for o in objs)}; say what to do with each")
    o = objs[0]
    p.ctx.set(objs)
    return Step([Call("grasp", (o.name,))], [Lifted(o.name)], (o.name,))


def _find_relation(rest: str) -> list[tuple[int, int, str]]:
    """(start, end, kind) of every relation word in ``rest``, left to right, longest first."""
    out = []
    for words, kind in RELATIONS:
        for m in re.finditer(rf"(?<![a-z]){re.escape(words)}(?![a-z])", rest):
            out.append((m.start(), m.end(), kind))
    out.sort(key=lambda t: (t[0], -(t[1] - t[0])))
    return out


def _put(verb: str, rest: str, p: Parser, clause: str) -> Step | None:
    rest = re.sub(r"\s+(?:again|once more)$", "", rest)  # "set it down again"
    if p.ctx.last and _starts_with_relation(re.sub(r"^(?:down|back|over) ", "", rest)):
        rest = f"it {rest}"  # "take the can and put next to the box": the object just named
    # "put X back" / "put X down" / "set X down" with no place: where it was, or where it is now
    rest = re.sub(r"\s+(?:back )?(?:exactly |precisely |right |just )?(?:to |in |into |on )?(?:where (?:it|they) (?:was|were|came from|belongs?|started)|where (?:you|i) (?:found|got|took) (?:it|them)(?: from)?"
                  r"|its (?:original |old |starting )?(?:place|spot|position)|(?:the )?same (?:place|spot|position))$",
                  " back", f" {rest}").strip()
    rest = "it back" if rest == "back" else rest  # "put back (in the) same place": the object just named
    if verb == "stack" and not _find_relation(rest):  # "stack the cubes": a tower, the biggest at the bottom
        objs = objects_named(rest, p)
        if len(objs) < 2:
            raise InputError(f"stack {rest!r} on what? name a second object; {p.resolver.listing()}")
        return each_other(objs, "on", p)
    m = re.fullmatch(r"(.+?)\s+(back|down)(?: where it (?:was|came from|belongs)| in its (?:place|spot)| on its spot)?", rest)
    if verb in ("put back", "put down", "set down", "lay down") and not _find_relation(rest):
        m = re.fullmatch(r"(.+)", rest)
    if m and not _relation_tail(rest):
        objs = objects_named(m.group(1), p)
        p.ctx.set(objs)
        return Step([Call("place", (o.name, [round(v, 3) for v in o.position])) for o in objs],
                     [Placed(o.name, (round(o.position[0], 3), round(o.position[1], 3))) for o in objs], tuple(o.name for o in objs))
    on_table = re.search(rf"\s+(?:on|onto|down on) {SURFACES}(?=\s+(?:to the |in front|behind|next|beside|left|right|between|near|by)\b)", rest)
    if on_table:  # "stand it on the table to the left of the cylinder": both hold
        step = _put(verb, rest[: on_table.start()] + rest[on_table.end():], p, clause)
        if step is not None:
            step.goals.extend(OnTable(o) for o in step.objects if not any(isinstance(g, OnTable) and g.obj == o for g in step.goals))
        return step
    last_error: InputError | None = None
    for start, end, kind in _find_relation(rest):
        obj_phrase, target_phrase = rest[:start].strip(), rest[end:].strip()
        if (not obj_phrase or not target_phrase or _starts_with_relation(target_phrase)
                or (kind == "to" and re.search(r"\b(?:left|right|front|back|side|top|edge)\b.*\bof\b", target_phrase))):
            continue  # "move the banana over next to the can": "over" is a particle here
        if re.search(r"\b(?:closest|nearest|closer|nearer|farthest|furthest|farther|further|next|close|near|(?:that|which) (?:is|s))$", obj_phrase):
            continue  # "pick up the can closest to the bowl": a locator that says which can
        if _SPOT.match(target_phrase) and _starts_with_relation(_SPOT.sub("", target_phrase, count=1).strip()):
            continue  # "move the box on the left next to the mug": "on the left" says which box
        try:
            return _relation(obj_phrase, kind, target_phrase, p, verb)
        except InputError as exc:
            last_error = last_error or exc
    if last_error is not None:
        raise last_error
    return None


_SPOT = re.compile(r"(?:the )?(?:far |very )?(?:left|right|middle|centre|center|front|back|end|edge|corner)(?: side| end| hand side| edge)?\b")


def _starts_with_relation(text: str) -> bool:
    return any(s == 0 for s, _, _ in _find_relation(text))


def _relation_tail(rest: str) -> bool:
    return any(s > 0 and rest[e:].strip() for s, e, _ in _find_relation(rest))


def _relation(obj_phrase: str, kind: str, target_phrase: str, p: Parser, verb: str) -> Step:
    target_phrase, *exception = re.split(r"\s+(?=(?:except|but not|other than|apart from|save for|excluding|besides)\s)", target_phrase, maxsplit=1)
    obj_phrase = f"{obj_phrase} {exception[0]}" if exception else obj_phrase  # "all the fruit in the bowl except the banana"
    obj_phrase = beside_measure(obj_phrase, kind)
    target_phrase = re.sub(r"\s+(?:again|too|as well|please|there)$", "", target_phrase).strip()
    target_phrase = re.sub(r"\s+(?:where it was|where it belongs|so it stands|upright)$", "", target_phrase).strip()
    if re.fullmatch(SURFACES, target_phrase) and kind in ("on", "to", "in"):
        objs = objects_named(obj_phrase, p)
        p.ctx.set(objs)
        calls, goals = [], []
        for o in objs:
            calls.append(Call("place_down", (o.name,)))
            goals.append(OnTable(o.name))
        return Step(calls, goals, tuple(o.name for o in objs))
    if kind == "between":
        if others := _OTHER_TWO.fullmatch(target_phrase):  # "the green one between the other two (blocks)": the two others of its kind
            named = objects_named(obj_phrase, p)
            kind_noun = others.group(1) or f"{name_words(named[0].label)[-1]}s"
            refs = [o for o in p.resolver.resolve(f"the {kind_noun}", Context(p.ctx.last), allow_plural=True) if o.name not in {n.name for n in named}]
        else:
            refs = p.resolver.resolve(target_phrase, Context(p.ctx.last), allow_plural=True)
        if len(refs) != 2:
            raise InputError(f"between needs two objects; {target_phrase!r} names {len(refs)}")
        objs = [o for o in objects_named(obj_phrase, p) if o.name not in {r.name for r in refs}]
        if not objs:
            raise InputError(f"cannot put an object between itself and another; {p.resolver.listing()}")
        p.ctx.set(objs)
        a, b = refs
        return Step([Call("place_between", (o.name, a.name, b.name)) for o in objs],
                     [Between(o.name, a.name, b.name) for o in objs], tuple(o.name for o in objs))
    if kind == "sides":  # "the cans on either side of the mug": the one on the left goes left
        ref = _target(target_phrase, obj_phrase, p, None)
        pair = sorted((o for o in objects_named(obj_phrase, p) if o.name != ref.name), key=lambda o: -p.resolver.robot_xy(o)[1])
        if len(pair) != 2:
            raise InputError(f"either side of {ref.name} takes two objects; {obj_phrase!r} names {len(pair)}")
        p.ctx.set(pair)
        return Step([Call("place_beside", (o.name, ref.name, s)) for o, s in zip(pair, ("left", "right"))],
                    [SideOf(o.name, ref.name, s) for o, s in zip(pair, ("left", "right"))], tuple(o.name for o in pair))
    if EACH_OTHER.fullmatch(target_phrase) and kind in ("next", "on", "to"):  # "put the cans next to each other"
        return each_other(objects_named(obj_phrase, p), "on" if kind == "on" else "next", p)
    want = {"in": "container", "on": "support"}.get(kind)
    if target_phrase in ("there", "that place", "the same place", "the same spot"):
        if p.ctx.place is None:
            raise InputError(f"'{target_phrase}' does not refer to any place yet; name it; {p.resolver.listing()}")
        target = p.ctx.place
    else:
        target = _target(target_phrase, obj_phrase, p, want)
        if want == "container":  # "we want the strawberry in it": not the banana
            target = held_in(target_phrase, target, p.ctx.place, p.resolver.listing())
    p.ctx.place = target
    objs = objects_named(obj_phrase, p)  # ordinals count the target too; a plural leaves it out
    if len(objs) > 1:
        objs = [o for o in objs if o.name != target.name]
    elif objs[0].name == target.name:
        raise InputError(f"cannot put {target.name} {kind} itself; {p.resolver.listing()}")
    p.ctx.set(objs)
    if kind == "to":
        kind = "in" if "container" in target.affordances else "on" if "support" in target.affordances else "next"
    elif kind == "in" and "support" in target.affordances and not holds_things(target) and target.size[2] <= min(0.04, 0.35 * min(target.size[:2])):
        kind = "on"  # "the cube into the plate": a flat thing (a plate, a tray) holds things on it, not in it
    calls, goals = [], []
    for o in objs:
        if kind == "in":
            check_fits(o, target, p.resolver.listing())
            calls.append(Call("place_in", (o.name, target.name)))
            goals.append(Inside(o.name, target.name))
        elif kind == "on":
            calls.append(Call("place_on", (o.name, target.name)))
            goals.append(On(o.name, target.name))
        elif kind == "next":
            calls.append(Call("place_beside", (o.name, target.name, "next")))
            goals.append(NextTo(o.name, target.name))
        else:  # a side; "the other side": opposite to where the object is now
            side = other_side(p, o, target) if kind == "other" else kind
            calls.append(Call("place_beside", (o.name, target.name, side)))
            goals.append(SideOf(o.name, target.name, side))
    return Step(calls, goals, tuple(o.name for o in objs))


def _target(target_phrase: str, obj_phrase: str, p: Parser, want: str | None) -> ObjectInfo:
    """The one object ``target_phrase`` names; "one" stands for the moved object's noun ("put the
    green cube beside the red one": the red cube), else for any object; of two it could name, one
    being the moved object, the other."""
    ctx = Context(p.ctx.last, p.ctx.place)
    head = _head_noun(obj_phrase, p)
    if head and re.search(r"\bone$", target_phrase) and not re.search(r"\bother one$", target_phrase):
        try:
            return p.resolver.resolve(re.sub(r"\bone$", head, target_phrase), ctx, want=want, allow_plural=False)[0]
        except InputError:
            pass
    try:
        return p.resolver.resolve(target_phrase, ctx, want=want, allow_plural=False)[0]
    except InputError:  # a thing is never placed by itself: "put the mug by the round container" (bowl or mug)
        moved = p.resolver.resolve(obj_phrase, ctx, loose=True) if obj_phrase else []
        if len(moved) != 1:
            raise
        return p.resolver.resolve(target_phrase, ctx, want=want, exclude=[moved[0].name], allow_plural=False)[0]


def _head_noun(phrase: str, p: Parser) -> str | None:
    """The noun a phrase ends with ("the green cube": cube; "it": the last object's label)."""
    said = re.sub(r"\s+(?:(?:from|on|at|in|to) (?:the )?(?:very )?(?:left|right|front|back|far end|near end|middle|centre|center)(?: side| end)?"
                  r"|(?:closest|nearest|farthest|furthest)(?: away)?(?: to| from)? .*)$", "", " " + norm(phrase))  # "the second can from the left": can
    words = re.sub(rf"{PARTICLES}$", "", said).split()
    if not words:
        return None
    if words[-1] in ("it", "them", "this", "that") and p.ctx.last:
        return name_words(p.ctx.last[0].label)[-1] if name_words(p.ctx.last[0].label) else None
    word = singular(words[-1])
    return None if word in (*GENERIC, "one", "ones", "it", "them") or word.isdigit() else word


def _articulate(verb: str, phrase: str, p: Parser) -> Step:
    want = "door" if "door" in phrase or "lid" in phrase else "drawer"
    words = norm(phrase).split()
    if words and words[-1] in ("drawer", "door", "cabinet") and not any(w in o.affordances for o in p.objects for w in (want,)):
        raise InputError(f"the scene has no {want}; {p.resolver.listing()}")
    try:
        objs = objects_named(phrase, p, want=want)
    except InputError:
        objs = [o for o in p.objects if want in o.affordances]
        if len(objs) != 1:
            raise
    o = objs[0]
    if not {"drawer", "door"} & set(o.affordances):
        raise InputError(f"{o.name} does not {verb.split()[0]}: the robot opens and closes only drawers and doors; {p.resolver.listing()}")
    p.ctx.set([o])
    if verb in ("open", "pull open", "pull out"):
        return Step([Call("open_drawer", (o.name,))], [DrawerOpen(o.name, 0.3 if want == "door" else 0.05)], (o.name,))
    return Step([Call("close_drawer", (o.name,))], [DrawerClosed(o.name)], (o.name,))


# ----------------------------------------------------------------------------------------------
# pushes (the words: realsim.planner.pushes) and swaps
