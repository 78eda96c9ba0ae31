"""Words of the offline scene parser: numbers, colours, materials, supports, fillers and the
relation markers (regular expressions, longest first)."""

from __future__ import annotations

NUMBERS = {"a": 1, "an": 1, "one": 1, "single": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
           "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "couple": 2, "pair": 2, "another": 1, "dozen": 12, "few": 3,
           "several": 4, "some": 3, "both": 2, "bunch": 4, "handful": 4, "lots": 5, "many": 5}
PLURAL_COUNT = 3  # "oranges", "some apples": several
VAGUE = {"some", "several", "few", "lots", "many", "bunch", "handful"}  # quantities, not numbers said
COLORS = {
    "red": (0.8, 0.1, 0.1), "green": (0.15, 0.6, 0.2), "blue": (0.15, 0.3, 0.8), "yellow": (0.95, 0.85, 0.15),
    "orange": (0.95, 0.5, 0.1), "purple": (0.5, 0.2, 0.6), "pink": (0.95, 0.55, 0.7), "white": (0.95, 0.95, 0.95),
    "black": (0.08, 0.08, 0.08), "grey": (0.5, 0.5, 0.5), "gray": (0.5, 0.5, 0.5), "brown": (0.45, 0.3, 0.15),
    "silver": (0.75, 0.75, 0.78), "gold": (0.85, 0.7, 0.25), "beige": (0.9, 0.85, 0.7), "teal": (0.1, 0.55, 0.55),
    "cyan": (0.2, 0.8, 0.85), "navy": (0.1, 0.15, 0.4), "clear": (0.85, 0.92, 0.95), "dark": (0.15, 0.15, 0.15),
}
MATERIALS = {"wooden": (0.6, 0.45, 0.3), "wood": (0.6, 0.45, 0.3), "plastic": None, "metal": (0.7, 0.7, 0.72), "steel": (0.7, 0.7, 0.72),
             "glass": (0.85, 0.92, 0.95), "ceramic": None, "paper": None, "cardboard": (0.75, 0.6, 0.4), "wicker": (0.7, 0.55, 0.35),
             "cast": None, "iron": (0.2, 0.2, 0.2), "porcelain": (0.95, 0.95, 0.95), "aluminium": (0.8, 0.8, 0.82), "aluminum": (0.8, 0.8, 0.82)}
# support words -> (kind, height override); "coffee table" is low
SUPPORTS = {"table": ("table", None), "desk": ("desk", None), "workbench": ("table", 0.9), "bench": ("table", 0.9), "counter": ("counter", None),
            "countertop": ("counter", None), "worktop": ("counter", None), "floor": ("floor", None), "ground": ("floor", None),
            "shelf": ("shelf", None), "bookshelf": ("shelf", None), "island": ("counter", None), "nightstand": ("table", 0.6),
            "stove": ("counter", None), "stovetop": ("counter", None), "cooktop": ("counter", None), "hob": ("counter", None),
            "sideboard": ("counter", None), "burner": ("counter", None), "dresser": ("table", 0.8), "windowsill": ("shelf", None)}
LOW_TABLES = {"coffee": 0.45, "side": 0.6, "bedside": 0.6}
NOT_SUPPORT_AFTER = {"lamp", "cloth", "mat", "runner", "tennis", "top", "leg", "drawer", "knife", "saw"}
FILLER = {"the", "there", "is", "are", "s", "some", "its", "it", "that", "which", "has", "have", "i", "we", "you", "my", "our", "your",
          "see", "put", "set", "placed", "sitting", "standing", "lying", "sits", "stands", "lies", "rests", "resting", "just", "also",
          "kitchen", "dining", "office", "living", "room", "scene", "here", "me", "image", "empty", "full", "open", "closed", "new",
          "old", "nice", "little", "bit", "each", "other", "them", "they", "those", "these", "this", "up", "down", "out", "around",
          "sort", "kind", "type", "stuff", "things", "thing", "bunch", "got", "sat", "left", "right", "corner", "middle", "center",
          "centre", "edge", "side", "back", "front", "top", "together", "neatly", "too", "else", "whole", "next", "near", "far", "end",
          "be", "should", "want", "like", "would", "let", "make", "made", "with", "of", "and", "or", "but", "so", "at", "to", "onto",
          "each", "every", "could", "please", "setup", "find", "notice", "spot", "keep", "keeps", "will", "might", "may", "usually",
          "always", "probably", "currently", "he", "she"}
MASS_NOUNS = r"water|juice|milk|soda|wine|beer|coffee|tea|jam|honey|oil|flour|rice|pasta|cereal|sugar|salt|soup|sauce|cream|butter|food|snacks|candy|sand|soil|dirt"
PRONOUNS = {"it", "them", "this", "that", "these", "those", "one"}
# Marker patterns, longest first; each becomes a token "§<kind>§".
MARKERS: list[tuple[str, str]] = [
    (r"stacked (?:up )?on top of each other|stacked up|(?:stacked|piled) on each other|on top of each other|on top of one another|stacked|piled up|piled", "STACKED"),
    (r"\b(?:a |one )?(?:stack|pile|tower|heap) of|(?:stack|pile)(?: up)?(?= (?:\d+|two|three|four|five|six|some|several|few|the|all|my) )", "STACKOF"),
    (r"\b(?:a |one )?(?:row|line) of", "ROWOF"),
    (r"in a (?:row|line)|lined up|side by side|in a neat row", "ROW"),
    (r"(?:in|at|on|to|near) the (?:very )?(?:middle|centre|center|corner|edge|far end|near end|back|front)(?: part)? of", "on"),
    (r"(?:to|on|at) the left(?: hand side)? of|left of", "left_of"),
    (r"(?:to|on|at) the right(?: hand side)? of|right of", "right_of"),
    (r"in front of", "in_front_of"),
    (r"behind|in back of", "behind"),
    (r"next to|beside|besides|near|nearby|alongside|close to|by|in between|between", "next_to"),
    (r"(?:on|at|to) the left(?: hand)?(?: side)?", "REGION_left"),
    (r"(?:on|at|to) the right(?: hand)?(?: side)?", "REGION_right"),
    (r"(?:on|at|in|to) the (?:back|far end|rear)(?: side)?", "REGION_back"),
    (r"(?:on|at|in|to) the (?:front|near end)(?: side)?", "REGION_front"),
    (r"(?:in|at) the (?:very )?(?:middle|centre|center)", "REGION_middle"),
    (r"full of|filled with|containing|holding|that holds|which holds|that has|has|have|holds|with", "with"),
    (r"inside of|inside|into|within|in", "in"),
    (r"on top of|ontop of|on to|onto|on|upon|atop|on top", "on"),
    (r"under|underneath|beneath|below", "under"),
    (r"of", "of"),
    (r"plus|as well as|also", "ALSO"),
    (r"and|along with|then|together with|[,]|there is|there are|i've got|i got|is|are|"
     r"sits|stands|lies|sitting|standing|lying|placed|resting|rests|stand|sit|lie", "and"),
    (r"[.;!?]", "SENT"),
    (r"[:]", "SENT:"),
]
# where on its support a "REGION_<name>" marker puts an object: (x, y) in [0, 1], left to right, front to back
REGIONS = {"left": (0.2, 0.5), "right": (0.8, 0.5), "back": (0.5, 0.8), "front": (0.5, 0.2), "middle": (0.5, 0.5)}
# parts of a thing: "a box with a lid", "a pot with two handles" describe it, they are not objects of their own
PARTS = {"lid", "handle", "spout", "cap", "cork", "knob", "strap", "hinge", "leg", "wheel", "button", "label", "sticker"}
REL_MARKERS = {"on", "in", "next_to", "left_of", "right_of", "behind", "in_front_of", "under"}


# "I need a scene with ...", "can you make me a desk with ...": a request, not an object
PREAMBLE = (r"^\W*(?:please\s+|hey\s+|ok\s+|so\s+)*(?:(?:i|we)\s+(?:need|want|would like|'d like)|(?:can|could|would)\s+you\s+"
            r"(?:please\s+)?(?:make|build|create|give|set up|generate|show)|make|build|create|give|set up|generate|simulate|show|imagine|picture)"
            r"\s+(?:me\s+|us\s+)?(?:(?:a|an|the|one)\s+)?(?:(?:simple|small|little|simulated|simulation|new)\s+)*"
            r"(?:scene|setup|set-up|room|layout|simulation|picture|environment)?\s*(?:with|of|where|in which|that has|containing|showing)?\b")
# fixtures of a room: named as landmarks ("next to the sink"), never built as objects
FIXTURES = {"sink", "wall", "window", "door", "fridge", "refrigerator", "freezer", "oven", "dishwasher", "radiator", "fireplace",
            "couch", "sofa", "bed", "wardrobe", "closet", "cupboard", "staircase", "stairs", "doorway", "corner"}
MEASURES = r"roll|rolls|tube|tubes|sheet|sheets|loaf|loaves|slice|slices|piece|pieces|chunk|chunks|wedge|wedges|head|heads|stick|sticks|bar|bars|block|blocks|ear|ears|clove|cloves|sprig|sprigs"
