"""A scripted stand-in for the Anthropic Messages API on 127.0.0.1, for tests.

Start it, queue replies, point the real SDK at ``server.base_url`` (``ANTHROPIC_BASE_URL``)::

    with MessagesServer() as server:
        server.push_text("hello")
        server.push_error(429)                # then a rate-limit error body
        server.push_tool("make_manifest", {"mass": 0.3})
        server.push_delay(2.0, text("late"))  # answer after 2 s (trigger a client timeout)
        server.push_raw(200, b"{not json")    # malformed body

Each POST /v1/messages pops the next reply; with an empty queue it answers 500 with an error
body saying so. Every request body is recorded in ``server.requests`` (parsed JSON).
"""

from __future__ import annotations

import json
import threading
import time
from collections import deque
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any

ERROR_TYPES = {
    400: "invalid_request_error",
    401: "authentication_error",
    403: "permission_error",
    404: "not_found_error",
    413: "request_too_large",
    429: "rate_limit_error",
    500: "api_error",
    529: "overloaded_error",
}


@dataclass
class Reply:
    """One scripted HTTP answer."""

    status: int = 200
    body: bytes = b""
    headers: dict[str, str] = field(default_factory=dict)
    delay_s: float = 0.0


def message(content: list[dict[str, Any]], *, stop_reason: str = "end_turn", input_tokens: int = 100,
            output_tokens: int = 50, model: str = "claude-test") -> dict[str, Any]:
    """A Messages API ``message`` object."""
    return {
        "id": f"msg_{time.monotonic_ns()}",
        "type": "message",
        "role": "assistant",
        "model": model,
        "content": content,
        "stop_reason": stop_reason,
        "stop_sequence": None,
        "usage": {"input_tokens": input_tokens, "output_tokens": output_tokens},
    }


def text(content: str, **kw: Any) -> Reply:
    return json_reply(message([{"type": "text", "text": content}], **kw))


def tool_use(name: str, data: dict[str, Any], **kw: Any) -> Reply:
    block = {"type": "tool_use", "id": f"toolu_{time.monotonic_ns()}", "name": name, "input": data}
    return json_reply(message([block], stop_reason="tool_use", **kw))


def error(status: int, msg: str = "", *, retry_after_ms: int | None = 1) -> Reply:
    """An API error with the official body shape; ``retry-after-ms`` keeps SDK backoff short."""
    etype = ERROR_TYPES.get(status, "api_error")
    body = {"type": "error", "error": {"type": etype, "message": msg or etype.replace("_", " ")}}
    headers = {} if retry_after_ms is None else {"retry-after-ms": str(retry_after_ms)}
    return json_reply(body, status=status, headers=headers)


def json_reply(obj: Any, *, status: int = 200, headers: dict[str, str] | None = None) -> Reply:
    return Reply(status=status, body=json.dumps(obj).encode(), headers=dict(headers or {}))


class _Server(ThreadingHTTPServer):
    request_queue_size = 128  # many concurrent manifest calls on a loaded machine: no refused connections


class MessagesServer:
    """A threaded HTTP server on a free 127.0.0.1 port answering from a queue of :class:`Reply`."""

    def __init__(self) -> None:
        self.replies: deque[Reply] = deque()
        self.requests: list[dict[str, Any]] = []
        self.headers: list[dict[str, str]] = []
        self._lock = threading.Lock()
        self._httpd = _Server(("127.0.0.1", 0), self._handler())
        self._httpd.daemon_threads = True
        self._thread = threading.Thread(target=self._httpd.serve_forever, kwargs={"poll_interval": 0.02}, daemon=True)

    @property
    def base_url(self) -> str:
        host, port = self._httpd.server_address[:2]
        return f"http://{host}:{port}"

    def start(self) -> MessagesServer:
        self._thread.start()
        return self

    def stop(self) -> None:
        if self._thread.is_alive():
            self._httpd.shutdown()
        self._httpd.server_close()

    def __enter__(self) -> MessagesServer:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()

    # scripting -------------------------------------------------------------------------
    def push(self, *replies: Reply) -> None:
        with self._lock:
            self.replies.extend(replies)

    def push_text(self, content: str, **kw: Any) -> None:
        self.push(text(content, **kw))

    def push_tool(self, name: str, data: dict[str, Any], **kw: Any) -> None:
        self.push(tool_use(name, data, **kw))

    def push_error(self, status: int, msg: str = "", **kw: Any) -> None:
        self.push(error(status, msg, **kw))

    def push_delay(self, seconds: float, reply: Reply) -> None:
        self.push(Reply(reply.status, reply.body, reply.headers, delay_s=seconds))

    def push_raw(self, status: int, body: bytes, content_type: str = "application/json") -> None:
        self.push(Reply(status, body, {"content-type": content_type}))

    @property
    def calls(self) -> int:
        return len(self.requests)

    @property
    def distinct_calls(self) -> int:
        """Requests with different bodies: the SDK's transport retries of one call count once."""
        return len({json.dumps(r, sort_keys=True) for r in self.requests})

    # http ------------------------------------------------------------------------------
    def _next(self) -> Reply:
        with self._lock:
            if self.replies:
                return self.replies.popleft()
        return error(500, "test server: no scripted reply left", retry_after_ms=None)

    def _handler(self) -> type[BaseHTTPRequestHandler]:
        server = self

        class Handler(BaseHTTPRequestHandler):
            protocol_version = "HTTP/1.1"

            def log_message(self, *args: Any) -> None:  # quiet
                pass

            def do_POST(self) -> None:  # noqa: N802
                length = int(self.headers.get("content-length") or 0)
                raw = self.rfile.read(length)
                if self.path.rstrip("/").split("?")[0] != "/v1/messages":
                    self._send(error(404, f"no route {self.path}", retry_after_ms=None))
                    return
                try:
                    body = json.loads(raw or b"{}")
                except ValueError:
                    body = {"_raw": raw.decode(errors="replace")}
                with server._lock:
                    server.requests.append(body)
                    server.headers.append({k.lower(): v for k, v in self.headers.items()})
                reply = server._next()
                if reply.delay_s:
                    time.sleep(reply.delay_s)
                self._send(reply)

            def _send(self, reply: Reply) -> None:
                try:
                    self.send_response(reply.status)
                    headers = {"content-type": "application/json", **reply.headers}
                    for k, v in headers.items():
                        self.send_header(k, v)
                    self.send_header("content-length", str(len(reply.body)))
                    self.end_headers()
                    self.wfile.write(reply.body)
                except (BrokenPipeError, ConnectionResetError):  # client gave up (timeout)
                    pass

        return Handler
