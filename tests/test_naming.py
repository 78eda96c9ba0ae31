"""Offline names a person can say: colour and shape, distinct within a scene (real Kinect scans)."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from conftest import MOSD
from realsim.colours import colour_words
from realsim.pipeline import convert
from realsim.understanding.naming import Name, balanced, distinct, offline_name, shape_word, white_balance, white_point
from realsim.understanding.shape_label import is_cylinder, is_prism

NO_ROBOT = {"robot": {"enabled": False}}
COLOURS = {"red", "orange", "yellow", "green", "blue", "purple", "pink", "brown", "white", "grey", "black"}
SHAPES = {"box", "can", "cup", "bowl", "disc", "cylinder", "object"}


def test_colour_words_of_plain_colours() -> None:
    rgb = np.array([[0.8, 0.1, 0.1], [0.1, 0.6, 0.15], [0.15, 0.2, 0.8], [0.9, 0.85, 0.2], [0.92, 0.92, 0.9],
                    [0.45, 0.45, 0.47], [0.05, 0.05, 0.05], [0.45, 0.28, 0.12]])
    assert colour_words(rgb).tolist() == ["red", "green", "blue", "yellow", "white", "grey", "black", "brown"]


def test_some_colours_balanced_to_the_captures_white_point_are_white_balances_bit_for_bit() -> None:
    rng = np.random.default_rng(2)
    colours = rng.uniform(0.0, 0.8, (5000, 3)) * [0.9, 0.95, 1.0]
    colours[rng.random(5000) < 0.1] = np.nan
    picked = rng.random(5000) < 0.3
    assert np.array_equal(balanced(colours[picked], white_point(colours)), white_balance(colours)[picked], equal_nan=True)
    few = colours[:5]  # too few colours to balance: left as they are
    assert white_point(few) is None and np.array_equal(balanced(few, None), few, equal_nan=True)


def test_white_balance_removes_a_colour_cast() -> None:
    rng = np.random.default_rng(0)
    scene = rng.uniform(0.1, 0.9, size=(5000, 3))
    scene[:200] = 0.95  # a white patch
    bluish = scene * np.array([0.7, 0.8, 1.0])
    assert colour_words(white_balance(bluish)[:200]).tolist().count("white") == 200


def test_shape_words_from_completed_solids() -> None:
    can = trimesh.creation.cylinder(radius=0.033, height=0.10, sections=32)
    can.apply_translation([0, 0, 0.05])
    word, adjective, cylinder, _ = shape_word(can.extents, np.zeros((0, 3)), np.zeros(2), is_cylinder(can, can.extents), False)
    assert (word, cylinder) == ("can", True) and adjective == ""
    box = trimesh.creation.box(extents=[0.16, 0.06, 0.21])
    box.apply_translation([0, 0, 0.105])
    assert shape_word(box.extents, np.zeros((0, 3)), np.zeros(2), False, is_prism(box))[0] == "box"
    # a bowl: round, squat, its observed inside lower than its rim
    bowl = trimesh.creation.cylinder(radius=0.08, height=0.06, sections=32)
    bowl.apply_translation([0, 0, 0.03])
    r = np.sqrt(np.random.default_rng(1).uniform(0, 1, 3000)) * 0.08
    a = np.random.default_rng(2).uniform(0, 2 * np.pi, 3000)
    z = 0.01 + 0.05 * (r / 0.08) ** 2
    pts = np.column_stack([r * np.cos(a), r * np.sin(a), z])
    assert shape_word(bowl.extents, pts, np.zeros(2), True, False)[0] == "bowl"
    name, _ = offline_name(bowl.extents, pts, np.tile([[0.9, 0.9, 0.88]], (100, 1)), np.zeros(2), True, False)
    assert name.label == "white_bowl"
    # only its near outside seen (no points inside the rim): a cylinder, unless completion built it open
    outside = pts[np.abs(pts[:, 1]) > 0.06]
    assert shape_word(bowl.extents, outside, np.zeros(2), True, False)[0] == "cylinder"
    assert shape_word(bowl.extents, outside, np.zeros(2), True, False, open_top=True)[0] == "bowl"


def test_look_alikes_are_told_apart() -> None:
    names = [Name("red_box", "red", "box", ""), Name("red_box", "red", "box", ""), Name("white_can", "white", "can", ""),
             Name("tall_white_can", "white", "can", "")]
    out = distinct(names, [1.0, 2.0, 1.0, 1.0], [[("red", 0.6), ("white", 0.3)], [("red", 0.7), ("blue", 0.2)], [("white", 1.0)], [("white", 1.0)]],
                   [0.1, 0.9, 0.3, 0.6])
    labels = [n.label for n in out]
    assert labels[:2] == ["small_red_box", "big_red_box"]
    assert labels[2:] == ["left_white_can", "right_tall_white_can"]  # same size, one colour: told apart by position


def test_a_generic_name_does_not_single_out_one_of_several_same_coloured_objects() -> None:
    """ "the red object" may mean the red box too: the generic one gets a telling word, the box keeps its name."""
    names = [Name("red_object", "red", "object", ""), Name("red_box", "red", "box", ""), Name("white_can", "white", "can", "")]
    out = distinct(names, [1.0, 3.0, 1.0], [[("red", 1.0)], [("red", 1.0)], [("white", 1.0)]], [0.2, 0.5, 0.8])
    assert [n.label for n in out] == ["small_red_object", "red_box", "white_can"]
    alone = distinct(names[:1] + names[2:], [1.0, 1.0], [[("red", 1.0)], [("white", 1.0)]], [0.2, 0.8])
    assert [n.label for n in alone] == ["red_object", "white_can"]  # the only red thing: nothing to tell apart


@pytest.mark.parametrize("scan", ["test0", "test45", "test55"])
def test_scanned_objects_get_distinct_colour_and_shape_names(scan: str, tmp_path) -> None:
    scene = convert(MOSD / f"{scan}.pcd", tmp_path / scan, overrides=NO_ROBOT)
    said = []
    for o in scene.objects:
        words = o.label.split("_")
        assert words[-1] in SHAPES or any("size-table category" in n for n in o.notes), o.name
        assert COLOURS & set(words), o.name
        assert o.name == f"obj{o.id}_{o.label}"
        if any("open container" in n for n in o.notes):  # completed hollow: a person calls it a bowl or a cup
            assert words[-1] in ("bowl", "cup"), o.name
        said.append("_".join(w for w in words if w not in ("tall", "flat")))
    assert len(set(said)) == len(said), said
    for name in said:  # "the red object" must not be one object's name while another red one exists
        words = name.split("_")
        if len(words) == 2 and words[1] == "object":
            assert sum(words[0] in other.split("_") for other in said) == 1, said
    for bad in ("hat", "speaker", "headphones", "stuffed_animal", "clock", "power_drill"):
        assert not any(bad in o.label for o in scene.objects)


def test_with_a_key_claude_labels_the_capture_own_rgb(tmp_path, monkeypatch: pytest.MonkeyPatch) -> None:
    """No photo file: the organized cloud's colours are the photo Claude labels (local Messages server)."""
    import sys
    from pathlib import Path

    import yaml

    sys.path.insert(0, str(Path(__file__).parent))
    from anthropic_server import tool_use
    from test_understanding import RoutingServer, tool_name
    from test_understanding_convert import _photo_objects, manifest_reply

    from realsim.synth.tabletop import make_tabletop_capture
    from realsim.understanding.photo import PHOTO_TOOL

    capture = make_tabletop_capture(tmp_path / "capture", seed=0)
    meta = yaml.safe_load((capture / "capture.yaml").read_text())
    meta.pop("labels")
    (capture / "capture.yaml").write_text(yaml.safe_dump(meta))
    assert not list(capture.glob("photo.*"))
    photo = _photo_objects(capture)
    seen_images = []

    def route(body):
        if tool_name(body) == PHOTO_TOOL:
            seen_images.extend(b for m in body["messages"] for b in m["content"] if isinstance(b, dict) and b.get("type") == "image")
            return tool_use(PHOTO_TOOL, {"objects": photo}, input_tokens=1500, output_tokens=300)
        return manifest_reply(body)

    with RoutingServer(route) as server:
        monkeypatch.setenv("ANTHROPIC_API_KEY", "sk-test-local")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", server.base_url)
        scene = convert(capture, tmp_path / "out", overrides=NO_ROBOT)
    assert len(seen_images) == 1
    from_photo = [o for o in scene.objects if any("from the photo" in n for n in o.notes)]
    assert len(from_photo) >= len(photo) - 1
    assert {o.label for o in from_photo} <= {p["label"] for p in photo}
