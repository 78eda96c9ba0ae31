"""The bundled synthetic capture round trip: render with known ground truth, convert, compare."""

from __future__ import annotations

import json

import numpy as np
import pytest

from realsim.pipeline import convert
from realsim.synth.tabletop import make_tabletop_capture


@pytest.fixture(scope="module")
def converted(tmp_path_factory: pytest.TempPathFactory) -> tuple[dict, dict]:
    root = tmp_path_factory.mktemp("synthetic")
    capture = make_tabletop_capture(root / "capture", seed=0)
    convert(capture, root / "out", overrides={"robot": {"enabled": False}})
    gt = json.loads((capture / "ground_truth.json").read_text())
    return gt, json.loads((root / "out" / "scene.json").read_text())


def test_table_floor_and_every_object_are_recovered(converted: tuple[dict, dict]) -> None:
    gt, scene = converted
    kinds = sorted(p["kind"] for p in scene["planes"])
    assert kinds == ["floor", "table"]
    table = next(p for p in scene["planes"] if p["kind"] == "table")
    assert table["height"] == pytest.approx(gt["table"]["height"], abs=0.002)
    assert sorted(o["label"] for o in scene["objects"]) == sorted(o["label"] for o in gt["objects"])


def test_objects_sit_where_they_were_rendered(converted: tuple[dict, dict]) -> None:
    gt, scene = converted
    # ground-truth world -> realsim world, through the camera both frames know
    to_ours = np.asarray(scene["capture"]["input_to_world"]) @ np.linalg.inv(np.asarray(gt["camera"]["pose_optical_to_world"]))
    by_label = {o["label"]: o for o in scene["objects"]}
    for g in gt["objects"]:
        ours = by_label[g["label"]]
        base = to_ours[:3, :3] @ np.asarray(g["position"]) + to_ours[:3, 3]
        assert np.linalg.norm(base[:2] - np.asarray(ours["position"][:2])) < 0.005, g["label"]
        gt_top = base[2] + g["size"][2]
        assert ours["position"][2] + ours["size"][2] == pytest.approx(gt_top, abs=0.003), g["label"]
        if g["shape"] == "cylinder":
            assert ours["size"][0] == pytest.approx(g["size"][0], abs=0.004), g["label"]


def test_stacked_object_rests_on_the_one_below(converted: tuple[dict, dict]) -> None:
    gt, scene = converted
    ids = {o["label"]: o["id"] for o in scene["objects"]}
    names = {o["id"]: o["label"] for o in gt["objects"]}
    for g in gt["objects"]:
        ours = next(o for o in scene["objects"] if o["label"] == g["label"])
        expected = ids[names[g["resting_on"]]] if g["resting_on"] is not None else None
        assert ours["resting_on"] == expected, g["label"]
    assert scene["settle"]["max_displacement"] < 0.005
