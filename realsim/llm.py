"""The one module that talks to Claude, through the official ``anthropic`` SDK.

Configuration: the key comes from ``ANTHROPIC_API_KEY``, the endpoint from the SDK's own
``ANTHROPIC_BASE_URL`` (or :attr:`LLMSettings.base_url`), the model from ``REALSIM_MODEL`` (or
:attr:`LLMSettings.model`). Retries on 408/409/429/5xx/529 and connection errors, with the
SDK's exponential backoff honouring ``retry-after``, are the SDK's own (``max_retries``); so is
the per-request timeout. Every SDK failure is mapped to :class:`LLMError` with a one-line
message. Token usage and an estimated cost are accumulated in :class:`Usage` records.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from realsim.errors import RealsimError

if TYPE_CHECKING:  # the SDK is imported when Claude is called: it takes ~1.5 s, and most runs are offline
    import anthropic

DEFAULT_MODEL = "claude-sonnet-4-6"  # current Sonnet; the SDK flags claude-sonnet-4-5 as deprecated
DEFAULT_TIMEOUT_S = 60.0
DEFAULT_MAX_RETRIES = 3
DEFAULT_MAX_TOKENS = 2048

# USD per million (input, output) tokens, by model-name prefix; first match wins. Estimates.
_PRICES: tuple[tuple[str, float, float], ...] = (
    ("claude-opus-4-0", 15.0, 75.0),
    ("claude-opus-4-1", 15.0, 75.0),
    ("claude-opus-5-5", 4.0, 20.0),
    ("claude-opus", 5.0, 25.0),
    ("claude-sonnet-5", 2.0, 10.0),
    ("claude-sonnet", 3.0, 15.0),
    ("claude-haiku-5-5", 0.10, 0.50),
    ("claude-haiku", 1.0, 5.0),
    ("claude-fable", 10.0, 50.0),
)
_FALLBACK_PRICE = (3.0, 15.0)


class LLMError(RealsimError):
    """Claude could not answer (network, timeout, rate limit, overload, bad reply): exit code 1."""

    exit_code = 1


class LLMConfigError(LLMError):
    """The LLM is misconfigured (no key, key rejected, unknown model): exit code 2."""

    exit_code = 2


def _env_float(name: str, default: float) -> float:
    raw = os.environ.get(name)
    if not raw:
        return default
    try:
        return float(raw)
    except ValueError as exc:
        raise LLMConfigError(f"{name}={raw!r} is not a number") from exc


@dataclass(frozen=True)
class LLMSettings:
    """Which model, how long to wait, how often to retry.

    Defaults read ``REALSIM_MODEL``, ``REALSIM_LLM_TIMEOUT`` (s) and ``REALSIM_LLM_MAX_RETRIES``.
    ``base_url`` and ``api_key`` default to ``ANTHROPIC_BASE_URL`` and ``ANTHROPIC_API_KEY`` as
    they are when the settings are made.
    """

    model: str = field(default_factory=lambda: os.environ.get("REALSIM_MODEL") or DEFAULT_MODEL)
    timeout_s: float = field(default_factory=lambda: _env_float("REALSIM_LLM_TIMEOUT", DEFAULT_TIMEOUT_S))
    max_retries: int = field(default_factory=lambda: int(_env_float("REALSIM_LLM_MAX_RETRIES", DEFAULT_MAX_RETRIES)))
    max_tokens: int = DEFAULT_MAX_TOKENS
    temperature: float | None = None  # None: the model default (some models reject the parameter)
    # read once, when the settings are made: calls still running after a deadline keep talking
    # to the endpoint of the conversion that started them
    base_url: str | None = field(default_factory=lambda: os.environ.get("ANTHROPIC_BASE_URL") or None)
    api_key: str | None = field(default_factory=lambda: os.environ.get("ANTHROPIC_API_KEY") or None)

    def key(self) -> str | None:
        return self.api_key or os.environ.get("ANTHROPIC_API_KEY") or None


@dataclass
class Usage:
    """Calls, tokens and an estimated cost (USD), summed over the calls it was passed to."""

    calls: int = 0
    input_tokens: int = 0
    output_tokens: int = 0
    cost_usd: float = 0.0

    def add(self, other: Usage) -> None:
        self.calls += other.calls
        self.input_tokens += other.input_tokens
        self.output_tokens += other.output_tokens
        self.cost_usd += other.cost_usd

    def summary(self) -> str:
        return (
            f"{self.calls} LLM call(s), {self.input_tokens} input + {self.output_tokens} output tokens, "
            f"~${self.cost_usd:.4f}"
        )


SESSION_USAGE = Usage()
"""Usage of every call made in this process."""


def estimate_cost(model: str, input_tokens: int, output_tokens: int) -> float:
    """Estimated USD cost of one call (list prices by model family; an estimate, not a bill)."""
    price_in, price_out = next(((pi, po) for prefix, pi, po in _PRICES if model.startswith(prefix)), _FALLBACK_PRICE)
    return (input_tokens * price_in + output_tokens * price_out) / 1e6


def available(settings: LLMSettings | None = None) -> bool:
    """True when an API key is configured (``ANTHROPIC_API_KEY`` or ``settings.api_key``)."""
    return (settings or LLMSettings()).key() is not None


Messages = str | Sequence[dict[str, Any]]


def _normalize(messages: Messages) -> list[dict[str, Any]]:
    if isinstance(messages, str):
        return [{"role": "user", "content": messages}]
    return [dict(m) for m in messages]


def _client(settings: LLMSettings) -> anthropic.Anthropic:
    import anthropic

    key = settings.key()
    if key is None:
        raise LLMConfigError("no ANTHROPIC_API_KEY set; set it to use Claude, or use the offline planner/tables")
    return anthropic.Anthropic(
        api_key=key,
        base_url=settings.base_url,
        timeout=settings.timeout_s,
        max_retries=settings.max_retries,
    )


def _one_line(text: object, limit: int = 200) -> str:
    s = " ".join(str(text).split())
    return s if len(s) <= limit else s[: limit - 3] + "..."


def _map_error(exc: Exception, settings: LLMSettings) -> LLMError:
    import anthropic

    retries = f"after {settings.max_retries} retr{'y' if settings.max_retries == 1 else 'ies'}"
    if isinstance(exc, anthropic.APITimeoutError):
        return LLMError(f"Claude API timed out ({settings.timeout_s:g} s per request, {retries}); retry later or raise REALSIM_LLM_TIMEOUT")
    if isinstance(exc, anthropic.APIConnectionError):
        return LLMError(f"cannot reach the Claude API ({_one_line(exc)}); check the network or ANTHROPIC_BASE_URL")
    if isinstance(exc, anthropic.AuthenticationError):
        return LLMConfigError("the Claude API rejected ANTHROPIC_API_KEY (401); check the key")
    if isinstance(exc, anthropic.PermissionDeniedError):
        return LLMConfigError(f"the Claude API denied access (403): {_api_message(exc)}")
    if isinstance(exc, anthropic.NotFoundError):
        return LLMConfigError(f"the Claude API answered 404 for model {settings.model!r}: {_api_message(exc)}; set REALSIM_MODEL")
    if isinstance(exc, anthropic.RateLimitError):
        return LLMError(f"Claude API rate limit (429) {retries}: {_api_message(exc)}; retry later")
    if isinstance(exc, anthropic.APIStatusError) and exc.status_code == 529:
        return LLMError(f"Claude API overloaded (529) {retries}; retry later")
    if isinstance(exc, anthropic.APIStatusError) and exc.status_code >= 500:
        return LLMError(f"Claude API server error ({exc.status_code}) {retries}: {_api_message(exc)}; retry later")
    if isinstance(exc, anthropic.APIStatusError):
        return LLMError(f"Claude API refused the request ({exc.status_code}): {_api_message(exc)}")
    return LLMError(f"unusable reply from the Claude API ({type(exc).__name__}: {_one_line(exc)})")


def _api_message(exc: anthropic.APIStatusError) -> str:
    body = exc.body
    if isinstance(body, dict):
        err = body.get("error")
        if isinstance(err, dict) and err.get("message"):
            return _one_line(err["message"])
    return _one_line(exc.message)


def _create(settings: LLMSettings, usage: Usage | None, **kwargs: Any) -> Any:
    import anthropic

    params: dict[str, Any] = {"model": settings.model, "max_tokens": settings.max_tokens, **kwargs}
    if settings.temperature is not None:
        params.setdefault("temperature", settings.temperature)
    client = _client(settings)
    try:
        message = client.messages.create(**params)
    except anthropic.AnthropicError as exc:
        raise _map_error(exc, settings) from exc
    except (ValueError, TypeError, KeyError) as exc:  # malformed JSON body
        raise _map_error(exc, settings) from exc
    finally:
        client.close()
    content = getattr(message, "content", None)
    if not isinstance(content, list):
        what = "a message without content" if hasattr(message, "model_dump") else _one_line(message, 80)
        raise LLMError(f"unusable reply from the Claude API ({what})")
    one = Usage(calls=1)
    raw_usage = getattr(message, "usage", None)
    one.input_tokens = int(getattr(raw_usage, "input_tokens", 0) or 0)
    one.output_tokens = int(getattr(raw_usage, "output_tokens", 0) or 0)
    one.cost_usd = estimate_cost(settings.model, one.input_tokens, one.output_tokens)
    SESSION_USAGE.add(one)
    if usage is not None:
        usage.add(one)
    return message


def complete_text(
    system: str,
    messages: Messages,
    *,
    settings: LLMSettings | None = None,
    usage: Usage | None = None,
    max_tokens: int | None = None,
) -> str:
    """Claude's text reply (all text blocks joined) to ``messages`` under ``system``."""
    s = settings or LLMSettings()
    extra = {"max_tokens": max_tokens} if max_tokens else {}
    message = _create(s, usage, system=system, messages=_normalize(messages), **extra)
    texts = [getattr(b, "text", "") for b in message.content if getattr(b, "type", None) == "text"]
    if not any(texts):
        raise LLMError(f"the Claude reply held no text (stop_reason={getattr(message, 'stop_reason', None)})")
    return "".join(texts)


def complete_tool(
    system: str,
    messages: Messages,
    tool_name: str,
    input_schema: dict[str, Any],
    *,
    description: str = "",
    settings: LLMSettings | None = None,
    usage: Usage | None = None,
    max_tokens: int | None = None,
) -> dict[str, Any]:
    """Structured output: force Claude to call ``tool_name`` and return the tool's input dict.

    ``input_schema`` is a JSON schema (``type: object``); the caller validates the result (e.g.
    with pydantic), since the API does not guarantee conformance.
    """
    s = settings or LLMSettings()
    tool = {"name": tool_name, "description": description or f"Report the result as {tool_name}.", "input_schema": input_schema}
    extra = {"max_tokens": max_tokens} if max_tokens else {}
    message = _create(
        s,
        usage,
        system=system,
        messages=_normalize(messages),
        tools=[tool],
        tool_choice={"type": "tool", "name": tool_name},
        **extra,
    )
    for block in message.content:
        if getattr(block, "type", None) == "tool_use" and getattr(block, "name", None) == tool_name:
            data = getattr(block, "input", None)
            if isinstance(data, dict):
                return data
            raise LLMError(f"the Claude reply's {tool_name} input is not an object")
    raise LLMError(f"the Claude reply did not call the tool {tool_name} (stop_reason={getattr(message, 'stop_reason', None)})")
