"""The Claude planner through the real anthropic SDK against the local Messages-API server."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from anthropic_server import MessagesServer, text  # noqa: E402
from test_planner_rules import OBJECTS  # noqa: E402

from realsim import llm  # noqa: E402
from realsim.planner import ClaudePlanner, Inside, PlanningError, RulePlanner, make_planner  # noqa: E402
from realsim.planner.claude import extract_code, system_prompt  # noqa: E402

GOOD = "Here is the program:\n```python\nplace_in(\"obj1_mug\", \"obj2_bowl\")\n```\nDone."
BAD = "```python\nimport os\nplace_in(\"obj1_mug\", \"obj2_bowl\")\n```"


@pytest.fixture
def server(monkeypatch: pytest.MonkeyPatch) -> Iterator[MessagesServer]:
    with MessagesServer() as srv:
        monkeypatch.setenv("ANTHROPIC_API_KEY", "sk-test-local")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", srv.base_url)
        yield srv


def planner(**kw: float) -> ClaudePlanner:
    return ClaudePlanner(settings=llm.LLMSettings(timeout_s=kw.get("timeout", 5.0), max_retries=int(kw.get("retries", 2))))


def test_good_reply(server: MessagesServer) -> None:
    server.push_text(GOOD, input_tokens=1500, output_tokens=40)
    plan = planner().plan("put the mug in the bowl", OBJECTS)
    assert plan.program == 'place_in("obj1_mug", "obj2_bowl")\n'
    assert plan.goals == [Inside("obj1_mug", "obj2_bowl")]
    assert plan.planner == "claude"
    assert (plan.usage.calls, plan.usage.input_tokens, plan.usage.output_tokens) == (1, 1500, 40)
    req = server.requests[0]
    version, system = system_prompt()
    assert req["system"] == system and version.startswith("planner-system-")
    user = req["messages"][0]["content"]
    assert "obj1_mug: red mug (also: cup, coffee mug)" in user and "at (0.500, 0.100, 0.050) m" in user
    assert "[leftmost" not in user.split("obj1_mug")[1].split("\n")[0]  # only one mug: no order words
    assert "obj3_soup_can: red tomato soup can" in user and "forward +0.40 m" in user
    assert user.endswith("Command: put the mug in the bowl")
    assert any("prompt planner-system-" in n for n in plan.notes)


def test_system_prompt_documents_every_primitive() -> None:
    from realsim.planner.sandbox import PRIMITIVES

    _, system = system_prompt()
    assert "{primitives}" not in system
    for name in PRIMITIVES:
        assert f"`{name}(" in system, name
    assert "metres" in system and "(w, x, y, z)" in system


def test_invalid_code_is_repaired_once(server: MessagesServer) -> None:
    server.push_text(BAD)
    server.push_text(GOOD)
    plan = planner().plan("put the mug in the bowl", OBJECTS)
    assert plan.program == 'place_in("obj1_mug", "obj2_bowl")\n'
    assert plan.usage.calls == 2
    second = server.requests[1]["messages"]
    assert [m["role"] for m in second] == ["user", "assistant", "user"]
    assert second[1]["content"] == BAD
    assert "line 1: import is not allowed" in second[2]["content"]
    assert any("attempt 1 rejected" in n for n in plan.notes)


def test_invalid_code_twice_fails_the_task(server: MessagesServer) -> None:
    server.push_text(BAD)
    server.push_text(BAD)
    with pytest.raises(PlanningError, match="rejected 2 time") as info:
        planner().plan("put the mug in the bowl", OBJECTS)
    assert info.value.exit_code == 1
    assert server.calls == 2


def test_rate_limit_then_success(server: MessagesServer) -> None:
    server.push_error(429, "slow down")
    server.push_text(GOOD)
    plan = planner().plan("put the mug in the bowl", OBJECTS)
    assert plan.program.startswith("place_in(")
    assert server.calls == 2


def test_overloaded_then_success(server: MessagesServer) -> None:
    server.push_error(529)
    server.push_error(500)
    server.push_text(GOOD)
    assert planner().plan("put the mug in the bowl", OBJECTS).program.startswith("place_in(")
    assert server.calls == 3


def test_timeout(server: MessagesServer) -> None:
    server.push_delay(2.0, text(GOOD))
    with pytest.raises(llm.LLMError, match="timed out"):
        planner(timeout=0.3, retries=0).plan("put the mug in the bowl", OBJECTS)


def test_malformed_body(server: MessagesServer) -> None:
    server.push_raw(200, b'{"id": "msg_1", "type": "message", "content": [')
    with pytest.raises(llm.LLMError, match="unusable reply"):
        planner().plan("put the mug in the bowl", OBJECTS)


def test_free_form_command_has_unknown_goal(server: MessagesServer) -> None:
    server.push_text("```python\nfor name in object_names():\n    push(name, 'left', 0.02)\n```")
    plan = planner().plan("tidy up a little by nudging everything", OBJECTS)
    assert plan.goals == []
    assert any("goal unknown" in n for n in plan.notes)


def test_extract_code_variants() -> None:
    assert extract_code("```py\ngo_home()\n```") == "go_home()\n"
    assert extract_code("text\n```python\ngo_home()\n") == "go_home()\n"
    assert extract_code("go_home()") == "go_home()\n"
    assert extract_code("```\nopen_gripper()\n```\n```python\ngo_home()\n```") == "open_gripper()\n"


def test_make_planner_picks_by_key(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    assert isinstance(make_planner(), RulePlanner)
    monkeypatch.setenv("ANTHROPIC_API_KEY", "k")
    assert isinstance(make_planner(), ClaudePlanner)
    assert isinstance(make_planner("rules"), RulePlanner)
