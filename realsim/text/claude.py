"""A scene description from Claude: one structured call (tool use) answered in the
:class:`~realsim.text.schema.SceneSpec` schema, validated, repaired once.

:func:`request_scene` is shared by the text path (the description in, :func:`parse_with_claude`)
and the photo path (an image in, :mod:`realsim.understanding.photo_scene`). Calls are cached on
disk (:func:`realsim.understanding.calls.tool_call`); rate limits, overload and timeouts are
retried by the SDK and then raise :class:`realsim.llm.LLMError`. A reply that fails validation
is sent back once with the errors; a second invalid reply raises LLMError.
"""

from __future__ import annotations

import json
from typing import Any

from pydantic import ValidationError

from realsim import llm
from realsim.cache import DiskCache
from realsim.resources import load_prompt
from realsim.text.parser import parse_scene
from realsim.text.schema import SceneSpec, json_schema

SCENE_TOOL = "report_scene"
TEXT_PROMPT = "scene_text.md"


def _errors(exc: ValidationError, limit: int = 8) -> str:
    return "; ".join(f"{'.'.join(str(p) for p in e['loc'])}: {e['msg']}" for e in exc.errors()[:limit])


class _ValidOnly:
    """A cache view that hands back only replies that validate (an invalid one is asked again)."""

    def __init__(self, cache: DiskCache) -> None:
        self.cache = cache

    def get(self, key: str) -> Any | None:
        value = self.cache.get(key)
        try:
            SceneSpec.model_validate(value)
        except ValidationError:
            return None
        return value

    def put(self, key: str, value: Any) -> None:
        self.cache.put(key, value)


def request_scene(content: list[dict[str, Any]], prompt_name: str, *, settings: llm.LLMSettings | None = None,
                  cache: DiskCache | None = None, log: Any = None) -> SceneSpec:
    """Claude's scene for one user turn (text and/or image blocks), validated; one repair turn."""
    from realsim.understanding.calls import CallLog, tool_call

    settings = settings or llm.LLMSettings()
    cache = _ValidOnly(cache if cache is not None else DiskCache())  # type: ignore[assignment]
    log = log if log is not None else CallLog()
    version, system = load_prompt(prompt_name)
    schema = json_schema()
    raw = tool_call(prompt_name=prompt_name, prompt_version=version, system=system, content=content, tool_name=SCENE_TOOL,
                    schema=schema, settings=settings, log=log, cache=cache)
    try:
        return SceneSpec.model_validate(raw)
    except ValidationError as exc:
        problems = _errors(exc)
    repair = content + [{"type": "text", "text": (
        "Your previous report_scene input was invalid: " + problems + ". It was: " + json.dumps(raw)[:4000]
        + " Call report_scene again with a corrected, complete scene.")}]
    raw = tool_call(prompt_name=prompt_name, prompt_version=version, system=system, content=repair, tool_name=SCENE_TOOL,
                    schema=schema, settings=settings, log=log, cache=cache)
    try:
        return SceneSpec.model_validate(raw)
    except ValidationError as exc:
        raise llm.LLMError(f"Claude's scene description failed validation twice ({_errors(exc, 3)})") from None


def parse_with_claude(text: str, settings: llm.LLMSettings | None = None, cache: DiskCache | None = None) -> SceneSpec:
    """Claude's reading of ``text``, or the offline parser's (with a warning) when Claude fails."""
    if not llm.available(settings):
        return parse_scene(text)
    try:
        spec = request_scene([{"type": "text", "text": text}], TEXT_PROMPT, settings=settings, cache=cache)
    except llm.LLMError as exc:
        spec = parse_scene(text)
        spec.warnings.append(f"Claude could not read the description ({exc}); used the offline parser")
        return spec
    if not spec.objects:
        spec = parse_scene(text)
        spec.warnings.append("Claude found no objects in the description; used the offline parser")
    return spec
