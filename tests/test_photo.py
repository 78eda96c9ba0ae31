"""A photo alone becomes a scene: Claude's description (local Messages server) -> text pipeline."""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path
from typing import Any, Iterator

import mujoco
import numpy as np
import pytest
from PIL import Image

sys.path.insert(0, str(Path(__file__).parent))
from anthropic_server import MessagesServer, tool_use  # noqa: E402

from realsim import llm  # noqa: E402
from realsim.cli import main  # noqa: E402
from realsim.composition.settle import rest_check  # noqa: E402
from realsim.perception.capture import load_capture  # noqa: E402
from realsim.pipeline import convert, pipeline_for  # noqa: E402
from realsim.runtime import Sim, run_command  # noqa: E402
from realsim.text.claude import SCENE_TOOL  # noqa: E402
from realsim.text.schema import ObjectSpec  # noqa: E402
from realsim.text.stage import display_label  # noqa: E402
from realsim.understanding.photo_scene import PhotoParams, photo_scene  # noqa: E402

NAMES = {"mug": ("coffee mug", "mug"), "can": ("soup can", "can"), "cereal_box": ("cereal box", "cereal box"),
         "shoe_box": ("shoe box", "box"), "block": ("wooden block", "toy block")}


@pytest.fixture(scope="module")
def photo(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[str, Any]]:
    """A rendered synthetic tabletop as photo.png, alone in a folder, and a description recorded
    from its ground truth (what Claude would answer)."""
    from realsim.perception.pcd_io import read_pcd
    from realsim.synth.tabletop import make_tabletop_capture

    cap = make_tabletop_capture(tmp_path_factory.mktemp("synthetic") / "capture", seed=0)
    cloud = read_pcd(cap / "scene.pcd")
    h, w = cloud.grid_shape
    folder = tmp_path_factory.mktemp("photo_only")
    Image.fromarray((np.nan_to_num(cloud.colors.reshape(h, w, 3)) * 255).astype(np.uint8)).save(folder / "photo.png")
    gt = json.loads((cap / "ground_truth.json").read_text())
    size = gt["table"]["size"]
    objects = []
    for o in gt["objects"]:
        name, label = NAMES[o["label"]]
        entry = {"id": o["label"], "label": label, "name": name, "count": 1, "rgb": [round(c * 255) for c in o["color"]],
                 "color": "", "size_m": o["size"]}
        if o["resting_on"] is None:
            entry["position"] = [o["position"][0] / size[0] + 0.5, o["position"][1] / size[1] + 0.5]
            entry["on"] = "table"
        else:
            entry["on"] = next(p["label"] for p in gt["objects"] if p["id"] == o["resting_on"])
        objects.append(entry)
    reply = {"supports": [{"id": "table", "kind": "table", "height_m": gt["table"]["height"], "size_m": size}], "objects": objects}
    return folder, reply


@pytest.fixture
def server(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Iterator[MessagesServer]:
    with MessagesServer() as srv:
        monkeypatch.setenv("ANTHROPIC_API_KEY", "sk-test-local")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", srv.base_url)
        monkeypatch.setenv("REALSIM_CACHE", str(tmp_path / "cache"))
        monkeypatch.setenv("REALSIM_LLM_MAX_RETRIES", "1")
        yield srv


def test_photo_scene_follows_the_description(photo: tuple[Path, dict], server: MessagesServer, tmp_path: Path) -> None:
    folder, reply = photo
    assert pipeline_for(folder) == "photo" and pipeline_for(folder / "photo.png") == "photo"
    server.push_tool(SCENE_TOOL, reply)
    out = tmp_path / "out"
    scene = convert(folder, out, seed=0)
    request = server.requests[0]
    assert request["tools"][0]["name"] == SCENE_TOOL and request["messages"][0]["content"][0]["type"] == "image"
    by_id = {e["id"]: e for e in reply["objects"]}
    objs = {o.label: o for o in scene.objects}
    label = {e["id"]: display_label(ObjectSpec.model_validate(e)) for e in reply["objects"]}
    assert sorted(objs) == sorted(label.values()) and "coffee mug" in objs
    for e in reply["objects"]:
        o = objs[label[e["id"]]]
        assert np.allclose(o.color, np.asarray(e["rgb"]) / 255, atol=0.01), (e["name"], o.color)
        if "position" not in e:  # stacked in the photo: on the object named
            below = next(p for p in scene.objects if p.id == o.resting_on)
            assert below.label == label[by_id[e["on"]]["id"]]
    free = [(e, objs[label[e["id"]]]) for e in reply["objects"] if "position" in e]
    for a, oa in free:  # left/right and front/back order kept for objects clearly apart in the photo
        for b, ob in free:
            for axis in (0, 1):
                if a["position"][axis] < b["position"][axis] - 0.15:
                    assert oa.position[axis] < ob.position[axis], (a["name"], b["name"], axis)
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert rest_check(model, 2.0)["max_displacement"] < 0.005
    assert (out / "assets" / "photo.png").is_file() and model.geom("photo_backdrop") is not None
    assert server.calls == 1 and scene.llm["calls"] == 1
    sim = Sim.load(out)
    record = run_command(sim, "pick up the coffee mug", planner="rules")
    assert record.success, record.summary()


def test_offline_photo_fails_at_once(photo: tuple[Path, dict], tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    folder, _ = photo
    for source in (folder, folder / "photo.png"):
        started = time.perf_counter()
        assert main(["convert", str(source), "-o", str(tmp_path / "out"), "-q"]) == 2
        assert time.perf_counter() - started < 3.0
        assert not (tmp_path / "out").exists()


def _photo_scene(folder: Path, cached: bool = True):
    return photo_scene(load_capture(folder / "photo.png"), PhotoParams(use_cache=cached))


def test_invalid_reply_repaired_once_then_clear_error(photo: tuple[Path, dict], server: MessagesServer) -> None:
    folder, reply = photo
    server.push_tool(SCENE_TOOL, {"objects": [{"id": "mug", "count": "many"}]})
    server.push_tool(SCENE_TOOL, reply)
    scene = _photo_scene(folder)
    assert server.calls == 2 and "invalid" in json.dumps(server.requests[1]["messages"])
    assert len(scene.scene_spec.objects) == len(reply["objects"])
    server.push_tool(SCENE_TOOL, {"objects": "none"})
    server.push_tool(SCENE_TOOL, {"objects": [{"label": 3}]})
    with pytest.raises(llm.LLMError, match="failed validation twice"):
        _photo_scene(folder)


@pytest.mark.parametrize("status,message", [(429, "rate limit"), (529, "overloaded")])
def test_rate_limit_and_overload_retried_then_clear_error(photo: tuple[Path, dict], server: MessagesServer, status: int, message: str) -> None:
    folder, reply = photo
    server.push_error(status)
    server.push_tool(SCENE_TOOL, reply)  # the retry succeeds
    assert _photo_scene(folder).scene_spec.objects
    server.push_error(status)
    server.push_error(status)
    with pytest.raises(llm.LLMError, match=message):
        _photo_scene(folder, cached=False)
    assert server.calls == 4


def test_timeout_retried_then_clear_error(photo: tuple[Path, dict], server: MessagesServer, monkeypatch: pytest.MonkeyPatch) -> None:
    folder, reply = photo
    monkeypatch.setenv("REALSIM_LLM_TIMEOUT", "0.3")
    server.push_delay(1.0, tool_use(SCENE_TOOL, reply))
    server.push_delay(1.0, tool_use(SCENE_TOOL, reply))
    with pytest.raises(llm.LLMError, match="timed out"):
        _photo_scene(folder)


def test_out_of_range_values_clamped_and_recorded(photo: tuple[Path, dict], server: MessagesServer) -> None:
    folder, _ = photo
    server.push_tool(SCENE_TOOL, {"supports": [{"id": "table", "kind": "table", "height_m": 9.0, "size_m": [1.2, 0.8]}],
                                  "objects": [{"id": "mug", "label": "mug", "count": 300, "position": [1.7, -0.2], "rgb": [300, 0, 0]}]})
    scene = _photo_scene(folder)
    spec = scene.scene_spec
    assert spec.supports[0].height_m == 2.0 and spec.objects[0].count == 24
    assert spec.objects[0].position == (1.0, 0.0) and spec.objects[0].rgb == (255, 0, 0)
    assert sum("clamped" in w for w in scene.warnings) >= 4
