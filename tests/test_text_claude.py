"""Descriptions read by Claude (local Messages server, real SDK) in the offline parser's schema."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Iterator

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from anthropic_server import MessagesServer  # noqa: E402

from realsim.pipeline import run_pipeline  # noqa: E402
from realsim.text.claude import SCENE_TOOL, parse_with_claude  # noqa: E402
from realsim.text.schema import json_schema  # noqa: E402

TEXT = "a stack of two books on the desk with a coffee mug on top, and a basket of apples on the floor"
REPLY = {
    "supports": [{"id": "desk", "kind": "desk", "height_m": 0.74, "size_m": [1.4, 0.7]}, {"id": "floor", "kind": "floor"}],
    "objects": [
        {"id": "book", "label": "book", "count": 2, "on": "desk", "stacked": True},
        {"id": "mug", "label": "mug", "name": "coffee mug", "count": 1, "on": "book", "color": "red"},
        {"id": "basket", "label": "basket", "count": 1, "on": "floor"},
        {"id": "apple", "label": "apple", "count": 3, "inside": "basket"},
    ],
}


@pytest.fixture
def server(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Iterator[MessagesServer]:
    with MessagesServer() as srv:
        monkeypatch.setenv("ANTHROPIC_API_KEY", "sk-test-local")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", srv.base_url)
        monkeypatch.setenv("REALSIM_CACHE", str(tmp_path / "cache"))
        monkeypatch.setenv("REALSIM_LLM_MAX_RETRIES", "0")
        yield srv


def test_same_schema_and_the_scene_it_builds(server: MessagesServer) -> None:
    server.push_tool(SCENE_TOOL, REPLY)
    scene = run_pipeline(None, overrides={"load": {"text": TEXT}, "robot": {"enabled": False}})
    req = server.requests[0]
    assert req["tools"][0]["input_schema"] == json_schema() and req["tool_choice"]["name"] == SCENE_TOOL
    assert req["messages"][0]["content"][0]["text"] == TEXT
    labels = sorted(o.label for o in scene.objects)
    assert labels == ["apple"] * 3 + ["basket", "book", "book", "coffee mug"]
    mug = next(o for o in scene.objects if o.label == "coffee mug")
    assert mug.resting_on is not None and mug.color[0] > 0.7
    desk = next(p for p in scene.planes if p.kind == "desk")
    assert desk.height == pytest.approx(0.74)


def test_invalid_reply_repaired_once(server: MessagesServer) -> None:
    server.push_tool(SCENE_TOOL, {"objects": [{"id": "book", "count": "two"}]})
    server.push_tool(SCENE_TOOL, REPLY)
    spec = parse_with_claude(TEXT)
    assert server.calls == 2 and [o.id for o in spec.objects] == ["book", "mug", "basket", "apple"]


def test_failure_falls_back_to_the_offline_parser(server: MessagesServer) -> None:
    server.push_error(529)
    spec = parse_with_claude(TEXT)
    assert any("offline parser" in w for w in spec.warnings)
    assert {o.label: o.count for o in spec.objects} == {"book": 2, "coffee mug": 1, "basket": 1, "apple": 3}
