"""The words people use for a tabletop scene: normalization, colours, sizes, kinds, directions.

Shared by the rule planner (to read commands) and the Claude planner (to describe the scene in
the same words). Everything here is data or a pure function of text and numbers.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from functools import lru_cache

COLORS: dict[str, tuple[float, float, float]] = {
    "red": (0.8, 0.1, 0.1), "green": (0.15, 0.6, 0.2), "blue": (0.15, 0.3, 0.8), "yellow": (0.9, 0.85, 0.15),
    "orange": (0.95, 0.55, 0.1), "purple": (0.5, 0.2, 0.6), "pink": (0.95, 0.5, 0.7), "black": (0.05, 0.05, 0.05),
    "white": (0.95, 0.95, 0.95), "gray": (0.5, 0.5, 0.5), "brown": (0.45, 0.3, 0.15),
}
COLOR_WORDS: dict[str, str] = {**{c: c for c in COLORS}, "grey": "gray", "silver": "gray", "gold": "yellow", "golden": "yellow",
                               "beige": "brown", "tan": "brown", "violet": "purple", "crimson": "red", "navy": "blue", "maroon": "red",
                               "reddish": "red", "greenish": "green", "bluish": "blue", "blueish": "blue", "yellowish": "yellow",
                               "orangish": "orange", "orangey": "orange", "purplish": "purple", "pinkish": "pink", "blackish": "black",
                               "whitish": "white", "greyish": "gray", "grayish": "gray", "brownish": "brown",
                               "pale": "white", "cream": "white", "ivory": "white"}  # "pale" alone: whitish ("pale yellow": yellow, see SHADES)
# a shade said before a colour only qualifies it: "pale yellow" is yellow, "dark red" red
SHADES = ("pale", "light", "dark", "bright", "deep", "soft", "dull", "off")
# the colours in the languages people mix in (accents are folded before reading); never a misspelling's target
FOREIGN_COLOR_WORDS: dict[str, str] = {"rouge": "red", "rojo": "red", "roja": "red", "rosso": "red", "rossa": "red", "vermelho": "red",
                               "bleu": "blue", "bleue": "blue", "azul": "blue", "blau": "blue", "vert": "green", "verte": "green", "verde": "green",
                               "grun": "green", "gruen": "green", "jaune": "yellow", "amarillo": "yellow", "amarilla": "yellow", "gelb": "yellow",
                               "giallo": "yellow", "gialla": "yellow", "blanc": "white", "blanche": "white", "blanco": "white", "blanca": "white",
                               "weiss": "white", "bianco": "white", "bianca": "white", "noir": "black", "noire": "black", "negro": "black",
                               "negra": "black", "schwarz": "black", "nero": "black", "nera": "black", "naranja": "orange", "rosa": "pink"}
COLOR_WORDS.update(FOREIGN_COLOR_WORDS)

_WIDE = ("wide", "wider", "widest", "fat", "fatter", "fattest", "thick", "thicker", "thickest", "chunky", "broad", "broader", "broadest")
_NARROW = ("skinny", "skinnier", "skinniest", "thin", "thinner", "thinnest", "slim", "slimmer", "slimmest", "narrow", "narrower", "narrowest", "slender")
BIG = ("big", "large", "bigger", "larger", "biggest", "largest", "huge", "giant", "tall", "taller", "tallest", "high", "long", "longer", "longest", *_WIDE)
SMALL = ("small", "smaller", "smallest", "little", "tiny", "mini", "short", "shorter", "shortest", "low", *_NARROW)
SIZE_AXIS = {"tall": 2, "taller": 2, "tallest": 2, "high": 2, "short": 2, "shorter": 2, "shortest": 2, "low": 2,
             "long": -1, "longer": -1, "longest": -1,
             **{w: -2 for w in (*_WIDE, *_NARROW)}}  # -1: the longest extent; -2: the narrower side of the footprint; absent: volume

ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "1st": 1, "2nd": 2, "3rd": 3, "4th": 4, "5th": 5}
NUMBERS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9, "ten": 10,
           "eleven": 11, "twelve": 12, "fifteen": 15, "twenty": 20, "thirty": 30, "a couple of": 2, "a couple": 2, "a pair of": 2}

SYNONYMS: dict[str, tuple[str, ...]] = {
    "cup": ("mug", "glass"), "mug": ("cup",), "tin": ("can",), "can": ("tin",), "carton": ("box",),
    "box": ("carton", "block", "cube"), "block": ("cube", "box", "brick"), "cube": ("block", "box"), "brick": ("block",),
    "dish": ("plate", "bowl"), "plate": ("dish",), "bottle": ("jar",), "jar": ("bottle",), "ball": ("sphere",),
    "bin": ("basket", "container"), "basket": ("bin",), "pen": ("marker",), "marker": ("pen",), "jug": ("pitcher",),
    "pitcher": ("jug",), "drill": ("power drill",), "cleanser": ("bleach",), "bleach": ("cleanser",),
    "puck": ("cylinder", "disk", "disc"), "disc": ("cylinder", "puck"), "disk": ("cylinder", "puck"),
}
# brand names people use for the thing (said as one word: :func:`brands` joins "cheez its", "campbell's")
BRANDS: dict[str, tuple[str, ...]] = {
    "spam": ("meat",), "hormel": ("meat",), "clorox": ("bleach",), "softscrub": ("bleach", "cleanser"), "windex": ("bottle", "cleaner"),
    "coke": ("soda", "can"), "cocacola": ("soda", "can"), "pepsi": ("soda", "can"), "sprite": ("soda", "can"), "fanta": ("soda", "can"),
    "redbull": ("soda", "can"), "drpepper": ("soda", "can"), "cheezit": ("cracker",), "ritz": ("cracker",), "jello": ("gelatin",),
    "lego": ("block", "brick"), "duplo": ("block", "brick"), "sharpie": ("marker",), "expo": ("marker",), "crayola": ("marker",),
    "campbell": ("soup", "can"), "progresso": ("soup", "can"), "heinz": ("ketchup",), "frenchs": ("mustard",), "french": ("mustard",), "guldens": ("mustard",),
    "chiquita": ("banana",), "dole": ("banana",), "kelloggs": ("cereal",), "cheerios": ("cereal",),
    "pringles": ("chip", "can"), "tupperware": ("container", "bowl"), "pyrex": ("dish", "bowl"), "dixie": ("cup",),
    "dewalt": ("drill",), "makita": ("drill",), "bosch": ("drill",), "ryobi": ("drill",), "fiskars": ("scissors",), "stanley": ("hammer",),
    "folgers": ("coffee", "can"), "nerf": ("ball",), "nutella": ("jar",), "oreo": ("cookie",),
}
SYNONYMS.update(BRANDS)
_BRAND_SPELLINGS = {"cheez its": "cheezit", "cheez it": "cheezit", "cheezits": "cheezit", "coca cola": "cocacola", "red bull": "redbull",
                    "dr pepper": "drpepper", "soft scrub": "softscrub", "french s": "frenchs", "gulden s": "guldens", "kellogg s": "kelloggs",
                    "campbell s": "campbell", "campbells": "campbell", "de walt": "dewalt", "jell o": "jello"}


def brands(text: str) -> str:
    """``text`` (lower case, punctuation gone) with a brand said in pieces or with its possessive as one
    word of :data:`BRANDS` ("cheez its" -> "cheezit", "campbell s" -> "campbell")."""
    for said, word in sorted(_BRAND_SPELLINGS.items(), key=lambda kv: -len(kv[0])):
        text = re.sub(rf"\b{said}\b", word, text)
    return re.sub(rf"\b({'|'.join(BRANDS)}) s\b", r"\1", text)
# words naming a kind of object rather than one: they select by the size table's record
KINDS: dict[str, tuple[str, ...]] = {
    "fruit": ("banana", "apple", "strawberry", "orange", "lemon", "pear", "peach", "plum", "lime", "grape", "fruit"),
    "food": ("banana", "apple", "strawberry", "orange", "lemon", "pear", "peach", "plum", "can", "box", "cracker", "sugar",
             "soup", "meat", "jello", "gelatin", "pudding", "cereal", "mustard", "ketchup", "bread", "chip"),
    "tool": ("drill", "scissors", "hammer", "screwdriver", "wrench", "plier", "clamp", "knife", "spatula"),
    "toy": ("cube", "block", "brick", "ball", "dinosaur", "toy", "car", "lego", "duck"),
    "dish": ("plate", "bowl", "mug", "cup", "glass", "dish"),
    "container": ("bowl", "mug", "cup", "basket", "bin", "box", "pot", "jar", "pitcher", "glass", "tray", "bucket"),
    "drink": ("can", "bottle", "cup", "mug", "glass"),
    # shapes, from what a thing is called (a can is round, a carton square)
    "round": ("can", "tin", "cylinder", "ball", "sphere", "orange", "apple", "lemon", "lime", "peach", "plum", "tomato", "bowl", "plate",
              "mug", "cup", "bottle", "jar", "glass", "pot", "bucket", "disk", "disc"),
    "cylinder": ("can", "tin", "cylinder", "bottle", "mug", "cup", "jar", "glass", "pot", "marker", "pen", "tube"),
    "square": ("box", "cube", "block", "brick", "carton", "package", "parcel", "crate"),
    "flat": ("plate", "tray", "book", "board", "lid", "coaster", "sheet", "card", "disk", "disc"),
}
for _shape, _kind in (("cylindrical", "cylinder"), ("boxy", "square"), ("rectangular", "square"), ("cubic", "square"),
                      ("cuboid", "square"), ("spherical", "round"), ("circular", "round")):
    KINDS[_shape] = KINDS[_kind]
# what things of a kind are usually made of, for "the cardboard one" when the scene records no material
_BOXES = ("box", "carton", "package", "parcel", "cereal", "cracker", "sugar", "pudding", "gelatin", "jello")
MATERIAL_KINDS: dict[str, tuple[str, ...]] = {
    "cardboard": _BOXES, "paper": (*_BOXES, "bag", "cup"),
    "metal": ("can", "tin", "pot", "pan", "spoon", "fork", "knife", "wrench", "hammer", "scissors", "screwdriver", "plier", "clamp"),
    "ceramic": ("mug", "cup", "plate", "bowl", "vase", "pot", "saucer", "teapot"),
    "wooden": ("block", "cube", "board", "spoon", "bowl", "spatula"), "foam": ("brick", "ball", "sponge", "block"),
    "rubber": ("ball", "duck", "brick", "toy", "strawberry", "banana"),
}
for _word, _material in (("metallic", "metal"), ("aluminium", "metal"), ("aluminum", "metal"), ("steel", "metal"), ("porcelain", "ceramic"),
                         ("china", "ceramic"), ("wood", "wooden"), ("squishy", "foam"), ("spongy", "foam"), ("rubbery", "rubber")):
    MATERIAL_KINDS[_word] = MATERIAL_KINDS[_material]
# the colours a kind of object usually has, for "the yellow fruit" when the capture gives no colour
TYPICAL_COLORS: dict[str, tuple[str, ...]] = {
    "banana": ("yellow",), "lemon": ("yellow",), "strawberry": ("red",), "cherry": ("red",), "tomato": ("red",),
    "apple": ("red", "green"), "lime": ("green",), "pear": ("green", "yellow"), "orange": ("orange",), "plum": ("purple",),
    "mustard": ("yellow",), "ketchup": ("red",), "carrot": ("orange",), "cracker": ("red",), "spam": ("blue",),
    # the packaging a product kind usually comes in (a capture whose texture is missing says nothing)
    "meat": ("blue",), "soup": ("red", "white"), "brick": ("red",), "marker": ("black",), "bleach": ("white",), "cleanser": ("white",),
}
_TO_ME = r"(?: (?:to|from) (?:me|you|the robot|yourself))?"
# a comparative said of one object with nothing to compare it to but the speaker: its extreme
COMPARATIVES = ((rf"(?:closer|nearer){_TO_ME}", "nearest"), (rf"(?:further|farther)(?: away)?{_TO_ME}", "farthest"),
                (r"(?:more|further|farther) (?:to the )?left", "leftmost"), (r"(?:more|further|farther) (?:to the )?right", "rightmost"))
GENERIC = ("thing", "object", "item", "stuff", "one", "piece")

DIRECTION_WORDS: dict[str, str] = {
    "left": "left", "leftward": "left", "leftwards": "left", "right": "right", "rightward": "right", "rightwards": "right",
    "forward": "forward", "forwards": "forward", "ahead": "forward", "away": "forward", "away from me": "forward",
    "away from you": "forward", "further away": "forward", "farther away": "forward", "further": "forward",
    "farther": "forward", "back": "back", "backward": "back", "backwards": "back", "toward me": "back",
    "towards me": "back", "toward you": "back", "towards you": "back", "toward the robot": "back",
    "towards the robot": "back", "closer": "back", "closer to you": "back", "nearer": "back",
}
UNITS: dict[str, float] = {
    "cm": 0.01, "centimeter": 0.01, "centimetre": 0.01, "mm": 0.001, "millimeter": 0.001, "millimetre": 0.001,
    "m": 1.0, "meter": 1.0, "metre": 1.0, "in": 0.0254, "inch": 0.0254, "inche": 0.0254, "ft": 0.3048, "foot": 0.3048, "feet": 0.3048,
}
VAGUE_DISTANCES: dict[str, float] = {"a tiny bit": 0.03, "a little bit": 0.04, "a bit": 0.05, "a little": 0.05, "slightly": 0.03,
                                     "a touch": 0.03, "a lot": 0.20, "a few centimeters": 0.05, "a few centimetres": 0.05,
                                     "a few cm": 0.05, "a couple of centimeters": 0.02, "a couple of cm": 0.02,
                                     "a hair": 0.01, "a smidge": 0.02, "a smidgen": 0.02, "a tad": 0.03,
                                     "a wee bit": 0.03, "a fraction": 0.01, "a skosh": 0.02, "a titch": 0.02}


# parts a kind of thing has, for "the thing with the handle" (only kinds that have the part are meant)
PARTS: dict[str, tuple[str, ...]] = {
    "handle": ("mug", "cup", "pitcher", "jug", "kettle", "pan", "saucepan", "pot", "teapot", "drill", "hammer", "screwdriver", "spatula", "knife",
               "scissors", "basket", "bucket", "bag", "mallet", "wrench", "ladle", "spoon", "fork", "brush", "iron", "skillet", "suitcase"),
    "lid": ("jar", "pot", "kettle", "pitcher", "teapot", "box", "tin", "bin", "container", "tupperware", "saucepan"),
    "cap": ("bottle", "marker", "pen", "jar", "tube"),
    "spout": ("pitcher", "jug", "kettle", "teapot", "watering"),
    "blade": ("knife", "scissors", "saw", "spatula"),
    "trigger": ("drill", "spray"),
    "stem": ("strawberry", "apple", "cherry", "pear", "glass", "wineglass"),
    "label": ("can", "tin", "bottle", "jar", "box"),
}


def has_part(said: str, words: set[str]) -> bool:
    """Whether a thing named by ``words`` has the part ``said`` names ("the handle", "a lid", "handles")."""
    return any(singular(w) in PARTS and words & set(PARTS[singular(w)]) for w in said.split())


def singular(word: str) -> str:
    """English singular of one word (good enough for object nouns)."""
    irregular = {"knives": "knife", "boxes": "box", "glasses": "glass", "dishes": "dish", "matches": "match", "scissors": "scissors",
                 "feet": "feet", "inches": "inch", "berries": "berry", "strawberries": "strawberry", "cherries": "cherry",
                 "tomatoes": "tomato", "potatoes": "potato", "its": "its", "this": "this", "these": "these", "those": "those",
                 "bus": "bus", "lens": "lens", "is": "is", "was": "was", "has": "has", "does": "does", "pliers": "plier"}
    if word in irregular:
        return irregular[word]
    if len(word) > 3 and word.endswith("ies"):
        return word[:-3] + "y"
    if len(word) > 3 and word.endswith(("ches", "shes", "xes", "sses", "zes")):
        return word[:-2]
    if len(word) > 3 and word.endswith("s") and not word.endswith(("ss", "us", "is", "os")):
        return word[:-1]
    return word


def is_plural(word: str) -> bool:
    """Whether a word is a plural noun (not a function word ending in s)."""
    return singular(word) != word and word not in ("its", "this", "is", "was", "has")


def norm(text: str) -> str:
    """Lower case, underscores and hyphens to spaces, punctuation dropped (decimal points kept)."""
    s = text.lower().replace("_", " ").replace("-", " ").replace("'s ", " ").replace("’", "'")
    s = re.sub(r"(?<!\d)\.|\.(?!\d)", " ", s)
    s = re.sub(r"[^a-z0-9. ']+", " ", s).replace("'", "")
    return " ".join(s.split())


def name_words(text: str) -> list[str]:
    """Singular words of a label, alias or body name ("obj3_red_boxes" -> red, box)."""
    return [singular(w) for w in norm(text).split() if not re.fullmatch(r"obj\d+|\d+", w)]


def color_name(rgb: Sequence[float] | None) -> str | None:
    """The colour word for an RGB triple (0-1) in the planner's vocabulary (``gray`` for grey), or None."""
    from realsim.colours import colour_name

    word = colour_name(rgb)
    return None if word is None else COLOR_WORDS.get(word, word)


@lru_cache(maxsize=512)
def record(label: str) -> tuple[str, str, str] | None:
    """(category, material, form) of a label from the size table, or None."""
    from realsim.physics.size_table import lookup

    match = lookup(label)
    if match is None:
        return None
    c = match.category
    return c.name, str(getattr(c, "material", "") or ""), str(getattr(c, "form", "") or "")


def with_colors(objects: Sequence, meta: dict) -> list:
    """``objects`` (:class:`ObjectInfo`) with colour words from scene.json's ``color`` (RGB) where
    they have none."""
    from dataclasses import replace

    rgb = {o.get("body") or o.get("name"): o.get("color") for o in meta.get("objects", [])}
    return [o if o.color else replace(o, color=color_name(rgb.get(o.name))) for o in objects]
