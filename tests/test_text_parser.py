"""The offline parser: supports, counts, attributes, containment, stacks, rows and relations."""

from __future__ import annotations

import pytest

from realsim.text.parser import parse_scene
from realsim.text.schema import SceneSpec, clamp, json_schema


def _objs(text: str) -> dict[str, tuple]:
    return {o.id: (o.label, o.count, o.on, o.inside, o.stacked) for o in parse_scene(text).objects}


def test_issue_example() -> None:
    spec = parse_scene("a kitchen table with a mug, a bowl, two soda cans and a cereal box")
    assert [(s.kind, s.height_m) for s in spec.supports] == [("table", 0.75)]
    assert {o.label: o.count for o in spec.objects} == {"mug": 1, "bowl": 1, "soda can": 2, "cereal box": 1}
    assert all(o.on == "table" for o in spec.objects)


@pytest.mark.parametrize("text,expected", [
    ("a stack of three books on the desk", {"book": ("book", 3, "desk", None, True)}),
    ("two plates stacked on the counter", {"plate": ("plate", 2, "counter", None, True)}),
    ("a tray holding two cups", {"tray": ("tray", 1, "table", None, False), "cup": ("cup", 2, None, "tray", False)}),
    ("a basket of oranges on the floor", {"basket": ("basket", 1, "floor", None, False), "orange": ("orange", 3, None, "basket", False)}),
    ("a bowl with two apples in it", {"bowl": ("bowl", 1, "table", None, False), "apple": ("apple", 2, None, "bowl", False)}),
    ("three apples in a bowl on the table", {"apple": ("apple", 3, None, "bowl", False), "bowl": ("bowl", 1, "table", None, False)}),
])
def test_quantities_containment_stacks(text: str, expected: dict) -> None:
    assert _objs(text) == expected


def test_each_object_on_its_support() -> None:
    spec = parse_scene("a lamp on the desk and a basket on the floor, plus a mug")
    on = {o.label: o.on for o in spec.objects}
    assert on == {"lamp": "desk", "basket": "floor", "mug": "desk"}
    assert {s.id for s in spec.supports} == {"desk", "floor"}


def test_relations_and_pronouns() -> None:
    spec = parse_scene("On the desk there's a laptop and a mug next to it. A lamp behind the laptop, a book to the left of the mug")
    rel = {o.label: [(r.relation, r.target) for r in o.relations] for o in spec.objects}
    assert rel["mug"] == [("next_to", "laptop")] and rel["lamp"] == [("behind", "laptop")] and rel["book"] == [("left_of", "mug")]
    assert all(o.on == "desk" for o in spec.objects)


def test_rows_attributes_and_contents_follow_their_container() -> None:
    spec = parse_scene("a row of four cans on the shelf, a large red wooden bowl, and a crate full of potatoes next to the bowl")
    cans, bowl, crate, potato = spec.objects
    assert (cans.count, cans.row, cans.on) == (4, True, "shelf")
    assert (bowl.size, bowl.color, bowl.material) == ("large", "red", "wooden")
    assert potato.inside == "crate" and [(r.relation, r.target) for r in crate.relations] == [("next_to", "bowl")]


def test_unknown_nouns_warned_and_liquids_dropped() -> None:
    spec = parse_scene("a bottle of water, a jar of jam, two glasses and a toy dinosaur")
    assert [(o.label, o.count) for o in spec.objects] == [("water bottle", 1), ("jam jar", 1), ("glass", 2), ("toy dinosaur", 1)]
    assert any("toy dinosaur" in w for w in spec.warnings)
    assert parse_scene("a table").objects == []


def test_clamp_records_changes_and_schema_inlines() -> None:
    spec = SceneSpec.model_validate({"supports": [{"id": "table", "kind": "table", "height_m": 7}],
                                     "objects": [{"id": "mug", "label": "mug", "count": 99, "on": "shelf", "position": [1.4, 0.5]}]})
    fixed, notes = clamp(spec)
    assert fixed.supports[0].height_m == 2.0 and fixed.objects[0].count == 24 and fixed.objects[0].on is None
    assert fixed.objects[0].position == (1.0, 0.5) and len(notes) == 4
    assert "$ref" not in str(json_schema()) and "objects" in json_schema()["properties"]


@pytest.mark.parametrize("text,expected", [
    # contents the size table does not know are left out, whatever links them ("with", "of")
    ("on the dining table there's a plate with some cheese", {"plate": ("plate", 1, "table", None, False)}),
    ("a workbench with a drill and a box of screws", {"drill": ("drill", 1, "table", None, False), "box": ("box", 1, "table", None, False)}),
    # a measure word names the food itself
    ("a loaf of bread on the counter", {"bread": ("bread", 1, "counter", None, False)}),
    # a location phrase ends the list of what is in the container
    ("a bowl with two apples in the middle of the table and a banana",
     {"bowl": ("bowl", 1, "table", None, False), "apple": ("apple", 2, None, "bowl", False), "banana": ("banana", 1, "table", None, False)}),
    # a bare plural before a colon names the objects listed after it
    ("fruit on the counter: two apples and a pear", {"apple": ("apple", 2, "counter", None, False), "pear": ("pear", 1, "counter", None, False)}),
    # a request's preamble is not an object
    ("I need a scene with an apple in a bowl", {"apple": ("apple", 1, None, "bowl", False), "bowl": ("bowl", 1, "table", None, False)}),
    ("could you make me a desk with a laptop", {"laptop": ("laptop", 1, "desk", None, False)}),
    # a fixture of the room is where things are, never built
    ("a cat bowl on the floor by the fridge", {"bowl": ("bowl", 1, "floor", None, False)}),
    ("two glasses on the counter next to the sink", {"glass": ("glass", 2, "counter", None, False)}),
    # the target of a relation may be a stack
    ("a mug to the left of a stack of two books", {"mug": ("mug", 1, "table", None, False), "book": ("book", 2, "table", None, True)}),
])
def test_phrasing_people_use(text: str, expected: dict) -> None:
    assert _objs(text) == expected


def test_a_similar_word_is_not_a_typo() -> None:
    spec = parse_scene("two coasters and a bannana on the table")
    labels = {o.label for o in spec.objects}
    assert "banana" in labels and "toaster" not in labels  # a typo is corrected; another word is not
    assert any("coaster" in w for w in spec.warnings)


def test_where_on_the_support() -> None:
    """"on the left", "in the middle", "at the back": a place on the support, before or after the object."""
    spec = parse_scene("a toolbox on the left, a hammer in the middle and two screwdrivers on the right. At the back there is a lamp.")
    at = {o.label: o.position for o in spec.objects}
    assert at == {"toolbox": (0.2, 0.5), "hammer": (0.5, 0.5), "screwdriver": (0.8, 0.5), "lamp": (0.5, 0.8)}


def test_plus_ends_a_list_of_contents() -> None:
    objs = _objs("a bowl holding three lemons, plus a mug and a spoon")
    assert objs["lemon"][3] == "bowl" and objs["mug"][2:4] == ("table", None) and objs["spoon"][2:4] == ("table", None)


def test_counted_unknown_things_are_objects_bulk_ones_contents() -> None:
    """"a plate with a sandwich on it": a stand-in object; "a box of screws", "some cheese": contents, left out."""
    spec = parse_scene("a plate with a sandwich on it, a box of screws and a board with some cheese")
    assert {o.label: (o.count, o.on) for o in spec.objects} == {"plate": (1, "table"), "sandwich": (1, "plate"), "box": (1, "table"),
                                                               "board": (1, "table")}
    assert any("sandwich" in w and "stands in" in w for w in spec.warnings)
    assert any("screw" in w and "left out" in w for w in spec.warnings) and any("cheese" in w and "left out" in w for w in spec.warnings)


def test_stack_as_a_verb() -> None:
    assert _objs("stack three bowls on the counter")["bowl"] == ("bowl", 3, "counter", None, True)


def test_a_relation_said_before_its_subject() -> None:
    """"..., and behind the kettle a jar": the jar is behind the kettle (not the teacup), and a mug stays on its table."""
    spec = parse_scene("In front of the kettle there is a teacup, and behind the kettle a jar. A mug on the table, and on the shelf a vase.")
    rel = {o.label: [(r.relation, r.target) for r in o.relations] for o in spec.objects}
    assert rel["teacup"] == [("in_front_of", "kettle")]
    assert rel["jar"] == [("behind", "kettle")]
    assert {o.label: o.on for o in spec.objects}["mug"] == "table" and {o.label: o.on for o in spec.objects}["vase"] == "shelf"


def test_who_is_not_what_and_stacks_of_several_phrases() -> None:
    spec = parse_scene("On my desk you'd find two books and a tablet stacked, and we've got a mug.")
    assert {o.label: (o.count, o.on, o.stacked) for o in spec.objects} == {"book": (2, "desk", True), "tablet": (1, "book", False),
                                                                           "mug": (1, "desk", False)}


def test_parts_measures_and_between() -> None:
    """A part after "with" describes its owner ("a box with a lid" is a lidded box); "a roll of tape" is tape;
    "between them" places a thing beside them."""
    spec = parse_scene("a box with a lid, a pot with two handles, a roll of tape. There are 2 mugs. Between them there's a teapot.")
    assert {o.label: o.count for o in spec.objects} == {"lidded box": 1, "pot": 1, "tape": 1, "mug": 2, "teapot": 1}
    assert [(r.relation, r.target) for o in spec.objects if o.label == "teapot" for r in o.relations] == [("next_to", "mug")]
