"""Optional: parse a description with Claude (structured tool output), validated with pydantic.

Used only when an API key is configured; any failure or an invalid reply falls back to the
offline parser, with a note in the scene's warnings.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field, ValidationError

from realsim.text.parser import COLORS, SIZES, SUPPORTS, ObjectRequest, SceneRequest, parse_description


# The prompt lives here rather than in prompts/ only because this helper's scope excludes that folder.
SYSTEM = """You turn a short English description of a tabletop or room scene into a list of objects for a
physics simulation. Report every physical object the description asks for (not the support it
stands on) with how many there are, its colour word if one is given, and its size word if one is
given ("small", "large", ...). Use short common English names ("mug", "soda can", "cereal box",
"drawer cabinet"). The support is "table", "counter", "floor" or "shelf" ("table" when none is said).
Call the tool exactly once."""


class _Obj(BaseModel):
    label: str = Field(min_length=1, max_length=60)
    count: int = Field(ge=1, le=20)
    color: str = ""
    size: str = ""


class _Reply(BaseModel):
    support: Literal["table", "counter", "floor", "shelf"] = "table"
    objects: list[_Obj] = Field(min_length=1, max_length=30)


SCHEMA = {
    "type": "object",
    "properties": {
        "support": {"type": "string", "enum": ["table", "counter", "floor", "shelf"]},
        "objects": {"type": "array", "items": {"type": "object", "properties": {
            "label": {"type": "string"}, "count": {"type": "integer", "minimum": 1},
            "color": {"type": "string"}, "size": {"type": "string"}}, "required": ["label", "count"]}},
    },
    "required": ["support", "objects"],
}


def parse_with_claude(text: str) -> SceneRequest:
    """Claude's reading of ``text``, or the offline parser's when Claude fails or answers badly."""
    from realsim import llm

    offline = parse_description(text)
    if not llm.available():
        return offline
    try:
        raw = llm.complete_tool(SYSTEM, text, "scene_objects", SCHEMA, description="the objects and support of the scene", max_tokens=1024)
        reply = _Reply.model_validate(raw)
    except (llm.LLMError, ValidationError) as exc:
        offline.notes.append(f"Claude could not parse the description ({type(exc).__name__}); used the offline parser")
        return offline
    kind, height, size = SUPPORTS[reply.support]
    objects = [ObjectRequest(label=o.label.lower().strip(), count=o.count,
                             color=o.color.lower() if o.color.lower() in COLORS else "",
                             size=o.size.lower() if o.size.lower() in SIZES else "") for o in reply.objects]
    return SceneRequest(support=kind, support_height=height, support_size=size, objects=objects, text=text, parser="claude")
