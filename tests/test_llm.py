"""realsim.llm through the real anthropic SDK against the local Messages-API server."""

from __future__ import annotations

import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from anthropic_server import MessagesServer, text  # noqa: E402

from realsim import llm  # noqa: E402


@pytest.fixture
def server(monkeypatch: pytest.MonkeyPatch) -> Iterator[MessagesServer]:
    # a conversion that passed its manifest deadline leaves its calls running (they still cost and
    # count); in a test worker they may belong to an earlier test: let them end before counting
    for thread in threading.enumerate():
        if thread.name.startswith("claude-manifest"):
            thread.join(timeout=60)
    with MessagesServer() as srv:
        monkeypatch.setenv("ANTHROPIC_API_KEY", "sk-test-local")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", srv.base_url)  # the SDK's own variable
        monkeypatch.delenv("REALSIM_MODEL", raising=False)
        yield srv


def fast(**kw: object) -> llm.LLMSettings:
    return llm.LLMSettings(**{"timeout_s": 5.0, "max_retries": 2, **kw})  # type: ignore[arg-type]


def test_available_follows_the_key(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    assert not llm.available()
    with pytest.raises(llm.LLMConfigError, match="ANTHROPIC_API_KEY"):
        llm.complete_text("s", "hi")
    monkeypatch.setenv("ANTHROPIC_API_KEY", "k")
    assert llm.available()


def test_model_setting(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("REALSIM_MODEL", raising=False)
    assert llm.LLMSettings().model == llm.DEFAULT_MODEL
    monkeypatch.setenv("REALSIM_MODEL", "claude-haiku-4-5")
    assert llm.LLMSettings().model == "claude-haiku-4-5"
    assert llm.LLMSettings(model="claude-opus-4-5").model == "claude-opus-4-5"
    monkeypatch.setenv("REALSIM_LLM_TIMEOUT", "abc")
    with pytest.raises(llm.LLMConfigError, match="REALSIM_LLM_TIMEOUT"):
        llm.LLMSettings()


def test_complete_text_and_usage(server: MessagesServer) -> None:
    server.push_text("hello there", input_tokens=1000, output_tokens=200)
    usage = llm.Usage()
    before = llm.SESSION_USAGE.calls
    assert llm.complete_text("be brief", "hi", settings=fast(model="claude-sonnet-4-6"), usage=usage) == "hello there"
    assert (usage.calls, usage.input_tokens, usage.output_tokens) == (1, 1000, 200)
    assert usage.cost_usd == pytest.approx((1000 * 3 + 200 * 15) / 1e6)
    assert llm.SESSION_USAGE.calls == before + 1
    assert "1 LLM call(s)" in usage.summary()
    req = server.requests[0]
    assert req["system"] == "be brief" and req["messages"] == [{"role": "user", "content": "hi"}]
    assert req["model"] == "claude-sonnet-4-6" and "temperature" not in req


def test_complete_tool_forces_the_tool(server: MessagesServer) -> None:
    schema = {"type": "object", "properties": {"mass": {"type": "number"}}, "required": ["mass"]}
    server.push_tool("report_mass", {"mass": 0.31})
    out = llm.complete_tool("sys", [{"role": "user", "content": "mass?"}], "report_mass", schema, settings=fast())
    assert out == {"mass": 0.31}
    req = server.requests[0]
    assert req["tool_choice"] == {"type": "tool", "name": "report_mass"}
    assert req["tools"][0]["name"] == "report_mass" and req["tools"][0]["input_schema"] == schema


def test_complete_tool_without_tool_call_is_an_error(server: MessagesServer) -> None:
    server.push_text("I'd rather talk")
    with pytest.raises(llm.LLMError, match="did not call the tool report_mass"):
        llm.complete_tool("sys", "x", "report_mass", {"type": "object"}, settings=fast())


@pytest.mark.parametrize("status", [429, 500, 529])
def test_retryable_errors_are_retried_by_the_sdk(server: MessagesServer, status: int) -> None:
    server.push_error(status)
    server.push_text("ok")
    assert llm.complete_text("s", "x", settings=fast()) == "ok"
    assert server.calls == 2


@pytest.mark.parametrize(
    ("status", "needle", "code"),
    [(429, "rate limit (429) after 2 retries", 1), (529, "overloaded (529)", 1), (500, "server error (500)", 1)],
)
def test_exhausted_retries_map_to_one_line_errors(server: MessagesServer, status: int, needle: str, code: int) -> None:
    for _ in range(3):
        server.push_error(status)
    with pytest.raises(llm.LLMError) as info:
        llm.complete_text("s", "x", settings=fast())
    assert needle in str(info.value) and "\n" not in str(info.value)
    assert info.value.exit_code == code
    assert server.calls == 3


@pytest.mark.parametrize(("status", "needle"), [(401, "rejected ANTHROPIC_API_KEY"), (404, "REALSIM_MODEL"), (400, r"refused the request \(400\): bad thing")])
def test_client_errors_are_not_retried(server: MessagesServer, status: int, needle: str) -> None:
    server.push_error(status, "bad thing")
    with pytest.raises(llm.LLMError, match=needle) as info:
        llm.complete_text("s", "x", settings=fast())
    assert server.calls == 1
    assert info.value.exit_code == (1 if status == 400 else 2)


def test_timeout(server: MessagesServer) -> None:
    server.push_delay(2.0, text("too late"))
    t0 = time.monotonic()
    with pytest.raises(llm.LLMError, match="timed out"):
        llm.complete_text("s", "x", settings=fast(timeout_s=0.3, max_retries=0))
    assert time.monotonic() - t0 < 1.5


@pytest.mark.parametrize("body", [b"{not json", b'{"type": "message"}', b"[]"])
def test_malformed_body(server: MessagesServer, body: bytes) -> None:
    server.push_raw(200, body)
    with pytest.raises(llm.LLMError, match="unusable reply"):
        llm.complete_text("s", "x", settings=fast())


def test_unreachable_endpoint(monkeypatch: pytest.MonkeyPatch) -> None:
    srv = MessagesServer()
    url = srv.base_url
    srv.stop()  # nothing listens there any more
    monkeypatch.setenv("ANTHROPIC_API_KEY", "k")
    with pytest.raises(llm.LLMError, match="cannot reach the Claude API"):
        llm.complete_text("s", "x", settings=fast(base_url=url, max_retries=0))


def test_cost_estimates() -> None:
    assert llm.estimate_cost("claude-haiku-4-5", 1_000_000, 0) == pytest.approx(1.0)
    assert llm.estimate_cost("claude-opus-4-5", 0, 1_000_000) == pytest.approx(25.0)
    assert llm.estimate_cost("some-unknown-model", 1_000_000, 0) == pytest.approx(3.0)
