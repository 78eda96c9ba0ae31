"""The scene being read: supports, objects and the relations the parser applies between them."""

from __future__ import annotations

from dataclasses import dataclass

from realsim.physics.size_table import lookup
from realsim.text.schema import SUPPORT_DEFAULTS, ObjectSpec, RelationSpec, SceneSpec, SupportSpec


@dataclass
class Phrase:
    """A noun phrase: an object mention, a support or a pronoun."""

    kind: str  # "object" | "support" | "pronoun"
    spec: ObjectSpec | None = None
    support: str | None = None  # support id
    plural: bool = False
    region: str | None = None
    definite: bool = False  # "the mug": an object already named, when there is one
    each: bool = False  # "next to each plate": one subject per instance of the target
    counted: bool = False  # a number word was said ("a", "two"): not a bare plural or mass noun


def known(label: str) -> bool:
    """True when the size table knows the label (an exact, alias or close match)."""
    return lookup(label) is not None  # fuzzy matches are typos only (size_table.is_typo)


class Builder:
    """Collects supports and objects and applies relations between phrases."""

    def __init__(self) -> None:
        self.spec = SceneSpec()
        self.support_order: list[str] = []
        self.contents: set[str] = set()  # ids said to be in or on an object with "with" or "of"
        self.uncounted: set[str] = set()  # ids of bare plurals and mass nouns ("toys", "fruit")

    def add_support(self, p: Phrase) -> None:
        kind = p.support or "table"
        if self.spec.support(kind) is None:
            height = float(p.region) if p.region else SUPPORT_DEFAULTS[kind][0]
            self.spec.supports.append(SupportSpec(id=kind, kind=kind, height_m=height, size_m=SUPPORT_DEFAULTS[kind][1]))  # type: ignore[arg-type]
            self.support_order.append(kind)

    def add_object(self, p: Phrase) -> None:
        """Add the phrase's object, or point it at the one already named ("the mug")."""
        assert p.spec is not None
        if p.definite:
            words = set(p.spec.label.split())
            same = [o for o in self.spec.objects if (o.label == p.spec.label or words & set(o.label.split())) and (not p.spec.color or o.color == p.spec.color)]
            if same:
                p.spec = same[-1]
                return
        ids = {o.id for o in self.spec.objects}
        base, k = p.spec.id.replace(" ", "_"), 2
        p.spec.id = base
        while p.spec.id in ids:
            p.spec.id, k = f"{base}_{k}", k + 1
        if not p.counted:
            self.uncounted.add(p.spec.id)
        self.spec.objects.append(p.spec)

    def relate(self, subjects: list[Phrase], rel: str, target: Phrase) -> None:
        """Apply ``subject rel target`` to each subject (a support target sets the support)."""
        for s in subjects:
            if s.spec is None or s is target:
                continue
            if target.kind == "support":
                if rel in ("on", "in"):
                    s.spec.on, s.spec.inside = target.support, None
                elif rel == "under":
                    self.add_support(Phrase("support", support="floor"))
                    s.spec.on, s.spec.inside = "floor", None
                continue
            t = target.spec
            if t is None:
                continue
            if rel == "in":
                s.spec.inside, s.spec.on = t.id, None
            elif rel == "on":
                s.spec.on, s.spec.inside = t.id, None
            elif rel == "under":  # "a book under the mug": the mug is on the book
                if t.on is None and t.inside is None:
                    t.on = s.spec.id
                else:
                    self.spec.warnings.append(f"'{s.spec.display} under {t.display}': {t.display} already rests elsewhere; ignored")
            else:
                if target.each and s.spec.count == 1:  # "a mug next to each plate": one mug per plate
                    s.spec.count = t.count
                if t.id in (s.spec.on, s.spec.inside):  # "a vase with a candle next to it": beside it, not in it
                    s.spec.on = s.spec.inside = None
                s.spec.relations.append(RelationSpec(relation=rel, target=t.id))  # type: ignore[arg-type]

    def add_part(self, owner: Phrase, part: str) -> None:
        """"a box with a lid": a part of the object said before "with"; a box gets a hinged lid, others keep their model."""
        from realsim.procedural.generate import kind_for

        if part == "lid" and owner.spec is not None and kind_for(owner.spec.label) in ("box", "upright_box", "primitive_box"):
            owner.spec.label = owner.spec.name = f"lidded {owner.spec.label}"

    def with_default(self, owner: Phrase, p: Phrase) -> None:
        """What "X with Y" means for Y: on a support, in a container, else on X."""
        from realsim.procedural.families import CONTAINERS
        from realsim.procedural.generate import kind_for

        if owner.kind == "support":
            self.relate([p], "on", owner)
        elif owner.spec is not None and p.spec is not None:
            self.relate([p], "in" if kind_for(owner.spec.label) in CONTAINERS else "on", owner)
            self.contents.add(p.spec.id)

    def finish(self) -> None:
        """Default supports, names, and warnings for what is not in the size table."""
        spec = self.spec
        elevated = [s for s in self.support_order if s != "floor"]
        if not spec.supports or (elevated == [] and any(o.on is None and o.inside is None for o in spec.objects) and "floor" not in self.support_order):
            self.add_support(Phrase("support", support="table"))
        default = elevated[0] if elevated else ("floor" if "floor" in self.support_order else "table")
        for o in [o for o in spec.objects if (o.inside or o.id in self.contents) and o.id in self.uncounted and not known(o.label)]:
            where = o.inside or o.on  # "a vase with flowers", "a box of screws": bulk contents the table does not know are
            # not modelled; a counted one ("a plate with a sandwich on it") is an object of its own, a stand-in box
            spec.warnings.append(f"{o.label!r}{' in the ' + where.replace('_', ' ') if where else ''} is not in the size table: left out")
            spec.objects.remove(o)
        for o in spec.objects:
            if o.on is None and o.inside is None:
                o.on = default
            if not known(o.label):
                spec.warnings.append(f"{o.label!r} is not in the size table: a box of default size stands in")
        used = {o.on for o in spec.objects} | {o.inside for o in spec.objects}
        spec.supports = [s for s in spec.supports if s.id in used] or spec.supports[:1]
