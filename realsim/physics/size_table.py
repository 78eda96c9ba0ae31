"""Lookup of typical object sizes and material properties (``size_tables/*.yaml``).

The lookup tolerates case, plurals, underscores/spaces/hyphens, YCB-style numeric prefixes,
aliases and near-synonyms (``difflib`` fuzzy matching on names and aliases).
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import yaml

from realsim.resources import data_dir

TABLE_DIR = data_dir("size_tables")
SAFE_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml when available: ~10x faster

FORMS = ("solid", "closed_container", "open_container", "hollow")


@dataclass(frozen=True)
class Material:
    """A material of the size table: density, MuJoCo friction, restitution and where they come from."""

    name: str
    density: float  # kg/m^3
    friction: tuple[float, float, float]  # MuJoCo (sliding, torsional, rolling)
    restitution: float
    source: str = ""


@dataclass(frozen=True)
class ObjectCategory:
    """One kind of object in the size table: extents, mass range, material, form (solid, shell, container) and aliases."""

    name: str
    size: tuple[float, float, float]  # min / typical / max of the largest extent (m)
    dims: tuple[float, ...]  # typical extents, largest first (m)
    mass: tuple[float, float, float]  # min / typical / max (kg)
    material: str
    form: str = "solid"
    shell: float = 0.003  # wall thickness (m) for containers / hollow objects
    contents: float = 0.0  # bulk density of the enclosed volume (kg/m^3), closed containers
    aliases: tuple[str, ...] = ()
    joint: dict[str, Any] | None = None

    @property
    def hollow(self) -> bool:
        return self.form != "solid"


@dataclass(frozen=True)
class Match:
    """The result of a lookup: the category, how it was found and a 0..1 score."""

    category: ObjectCategory
    how: str  # "exact" | "alias" | "fuzzy"
    score: float
    query: str = ""
    matched: str = ""
    notes: tuple[str, ...] = field(default=())


def normalize_label(text: str) -> str:
    """Lower case, digits/underscores/hyphens to spaces, single spaces: ``'025_Mug'`` -> ``'mug'``."""
    s = text.strip().lower()
    s = re.sub(r"^[\d_\-\s]+", "", s)
    s = re.sub(r"[_\-\./]+", " ", s)
    s = re.sub(r"[^a-z0-9 ]+", "", s)
    return re.sub(r"\s+", " ", s).strip()


def _singular_word(word: str) -> str:
    if len(word) <= 3 or word.endswith(("ss", "us", "is")):
        return word
    for suffix, repl in (("ies", "y"), ("ves", "f"), ("ches", "ch"), ("shes", "sh"), ("xes", "x"), ("oes", "o"), ("s", "")):
        if word.endswith(suffix):
            return word[: -len(suffix)] + repl
    return word


def singular(text: str) -> str:
    """The singular of each word of an object name ("soda cans" -> "soda can")."""
    return " ".join(_singular_word(w) for w in text.split())


@lru_cache(maxsize=None)
def load_materials(path: str | None = None) -> dict[str, Material]:
    """All materials from ``materials.yaml``."""
    raw = yaml.load(Path(path or TABLE_DIR / "materials.yaml").read_text(), Loader=SAFE_LOADER)["materials"]
    return {
        k: Material(k, float(v["density"]), tuple(float(x) for x in v["friction"]), float(v["restitution"]), str(v.get("source", "")))
        for k, v in raw.items()
    }


@lru_cache(maxsize=None)
def load_objects(path: str | None = None) -> dict[str, ObjectCategory]:
    """All categories from ``objects.yaml``."""
    raw = yaml.load(Path(path or TABLE_DIR / "objects.yaml").read_text(), Loader=SAFE_LOADER)["objects"]
    out = {}
    for k, v in raw.items():
        form = v.get("form", "solid")
        if form not in FORMS:
            raise ValueError(f"objects.yaml: {k}: unknown form {form!r}")
        out[k] = ObjectCategory(
            name=k,
            size=tuple(float(x) for x in v["size"]),
            dims=tuple(float(x) for x in v.get("dims", [v["size"][1]])),
            mass=tuple(float(x) for x in v["mass"]),
            material=str(v["material"]),
            form=form,
            shell=float(v.get("shell", 0.003)),
            contents=float(v.get("contents", 0.0)),
            aliases=tuple(str(a) for a in v.get("aliases", []) or []),
            joint=v.get("joint"),
        )
    return out


@lru_cache(maxsize=None)
def _index() -> dict[str, tuple[str, str]]:
    """normalized name -> (category, "exact"|"alias"), singular forms included."""
    idx: dict[str, tuple[str, str]] = {}
    for name, cat in load_objects().items():
        for text, how in [(name, "exact")] + [(a, "alias") for a in cat.aliases]:
            n = normalize_label(text)
            for key in (n, singular(n), n.replace(" ", "")):
                idx.setdefault(key, (name, how))
    return idx


def material(name: str) -> Material:
    """A material by name (``default`` when unknown)."""
    mats = load_materials()
    return mats.get(name, mats["default"])


@lru_cache(maxsize=4096)
def lookup(label: str, cutoff: float = 0.8) -> Match | None:
    """The category for ``label`` or None when nothing is close enough.

    Tries, in order: exact name/alias (after normalization and singularization), the last word(s)
    of a multi-word label ("red coffee mug" -> "coffee mug" -> "mug"), then difflib fuzzy matching.
    """
    objects = load_objects()
    idx = _index()
    q = normalize_label(label)
    if not q:
        return None
    words = q.split()
    candidates = [q, singular(q), q.replace(" ", "")]
    # drop leading words ("red coffee mug" -> "coffee mug" -> "mug") and trailing ("mug base" -> "mug")
    for i in range(1, len(words)):
        tail = " ".join(words[i:])
        candidates += [tail, singular(tail)]
    for i in range(len(words) - 1, 0, -1):
        head = " ".join(words[:i])
        candidates += [head, singular(head)]
    for c in candidates:
        if c in idx:
            name, how = idx[c]
            exact = c in (q, singular(q), q.replace(" ", ""))
            return Match(objects[name], how if exact else "alias", 1.0 if exact else 0.9, label, c)
    typed = singular(q)
    for near in difflib.get_close_matches(typed, list(idx), n=5, cutoff=cutoff):
        if is_typo(typed, near):
            name, _ = idx[near]
            return Match(objects[name], "fuzzy", difflib.SequenceMatcher(None, typed, near).ratio(), label, near)
    return None


def is_typo(typed: str, word: str) -> bool:
    """True when ``typed`` reads as a misspelling of ``word``: the same first letter and at most
    one slip (an extra, missing, wrong or swapped letter) per five letters, two at most.

    Similar-looking different words are not typos: "coaster" is no "toaster", "rubber" no
    "scrubber".
    """
    if not typed or not word or typed[0] != word[0]:
        return False
    return _slips(typed, word) <= min(2, max(1, len(word) // 5))


def _slips(a: str, b: str) -> int:
    """Edit distance counting a swap of two neighbouring letters as one slip (optimal alignment)."""
    d = [[i + j if i * j == 0 else 0 for j in range(len(b) + 1)] for i in range(len(a) + 1)]
    for i in range(1, len(a) + 1):
        for j in range(1, len(b) + 1):
            d[i][j] = min(d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1]))
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                d[i][j] = min(d[i][j], d[i - 2][j - 2] + 1)
    return d[len(a)][len(b)]
