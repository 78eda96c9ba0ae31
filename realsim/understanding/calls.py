"""Cached structured-output calls to Claude (tool use), with usage accounting.

A reply is stored on disk under the hash of everything that determines it: the prompt version
and text, the messages (images included, as base64), the tool schema and the model. A rerun of
the same conversion therefore makes no call and gets the same answer. Failed calls are not
cached; they raise :class:`realsim.llm.LLMError` for the caller to fall back on.
"""

from __future__ import annotations

import base64
import io
import threading
from dataclasses import dataclass, field
from typing import Any

from realsim import llm
from realsim.cache import DiskCache, cache_key

CACHE_STAGE = "claude-tool-1"


@dataclass
class CallLog:
    """Calls made, cache hits, failures and usage of one conversion (thread-safe)."""

    usage: llm.Usage = field(default_factory=llm.Usage)
    cache_hits: int = 0
    failures: list[str] = field(default_factory=list)
    model: str = ""
    prompts: dict[str, str] = field(default_factory=dict)  # prompt file -> version
    _lock: threading.Lock = field(default_factory=threading.Lock, repr=False)

    def record(self) -> dict[str, Any]:
        """The ``llm`` section of the conversion report."""
        return {
            "model": self.model,
            "calls": self.usage.calls,
            "cache_hits": self.cache_hits,
            "input_tokens": self.usage.input_tokens,
            "output_tokens": self.usage.output_tokens,
            "cost_usd": round(self.usage.cost_usd, 6),
            "failures": list(self.failures),
            "prompts": dict(sorted(self.prompts.items())),
        }

    def summary(self) -> str:
        return f"{self.usage.summary()}, {self.cache_hits} cached, {len(self.failures)} failed"


def image_block(png_or_jpeg: bytes, media_type: str = "image/png") -> dict[str, Any]:
    """A Messages-API base64 image content block."""
    return {"type": "image", "source": {"type": "base64", "media_type": media_type, "data": base64.b64encode(png_or_jpeg).decode("ascii")}}


def encode_image(data: bytes, max_side: int = 1568) -> tuple[bytes, str]:
    """Re-encode an image file's bytes (any PIL format) as PNG/JPEG, longest side <= ``max_side``."""
    from PIL import Image

    with Image.open(io.BytesIO(data)) as im:
        im.load()
        img = im.convert("RGB")
    if max(img.size) > max_side:
        scale = max_side / max(img.size)
        img = img.resize((max(1, round(img.width * scale)), max(1, round(img.height * scale))), Image.Resampling.LANCZOS)
    out = io.BytesIO()
    img.save(out, format="JPEG", quality=90)
    return out.getvalue(), "image/jpeg"


def tool_call(
    *,
    prompt_name: str,
    prompt_version: str,
    system: str,
    content: list[dict[str, Any]],
    tool_name: str,
    schema: dict[str, Any],
    settings: llm.LLMSettings,
    log: CallLog,
    cache: DiskCache,
    max_tokens: int | None = None,
) -> dict[str, Any]:
    """The tool input Claude returns for one user turn, from the cache when possible."""
    messages = [{"role": "user", "content": content}]
    key = cache_key(CACHE_STAGE, params={"prompt": [prompt_name, prompt_version, system], "messages": messages,
                                         "tool": [tool_name, schema], "model": settings.model, "max_tokens": max_tokens})
    with log._lock:
        log.prompts[prompt_name] = prompt_version
        log.model = settings.model
    cached = cache.get(key)
    if isinstance(cached, dict):
        with log._lock:
            log.cache_hits += 1
        return cached
    one = llm.Usage()
    try:
        data = llm.complete_tool(system, messages, tool_name, schema, settings=settings, usage=one, max_tokens=max_tokens)
    finally:
        with log._lock:
            log.usage.add(one)
    cache.put(key, data)
    return data
