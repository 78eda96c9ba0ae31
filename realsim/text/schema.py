"""The typed scene description every scene source produces: offline parser, Claude, photo.

A :class:`SceneSpec` lists the supports (floor, table, counter, desk, shelf, with heights) and the
objects, each with a count, attributes (colour, size word, material) and where it is: ``on`` a
support or another object, ``inside`` a container, ``stacked`` (its instances on each other),
in a ``row``, and ``relations`` to other objects (next to, left of, right of, behind, in front
of). Directions are as seen from the front edge of the support (where a viewer, the camera of a
photo, or the robot stands): left is -x, right +x, behind +y, in front -y.

:func:`json_schema` is the tool schema sent to Claude (the same model validates its reply);
:func:`clamp` brings values into range and says what it changed.
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator

SupportKind = Literal["table", "counter", "desk", "shelf", "floor"]
RelationKind = Literal["next_to", "left_of", "right_of", "behind", "in_front_of"]
# (height m, [width, depth] m) of each support kind
SUPPORT_DEFAULTS: dict[str, tuple[float, tuple[float, float]]] = {
    "table": (0.75, (1.2, 0.8)), "desk": (0.75, (1.4, 0.7)), "counter": (0.9, (1.8, 0.65)), "shelf": (1.0, (1.0, 0.4)),
    "floor": (0.0, (2.0, 2.0)),
}
MAX_COUNT = 24
SIZE_WORDS = ("tiny", "small", "little", "mini", "medium", "big", "large", "huge", "tall", "giant", "short", "long", "wide", "thin")


class SupportSpec(BaseModel):
    """A surface objects stand on."""

    model_config = ConfigDict(extra="ignore")
    id: str = Field(min_length=1, max_length=40, description="unique id, e.g. 'table', 'floor', 'shelf'")
    kind: SupportKind
    height_m: float | None = Field(default=None, description="height of the top surface above the floor (m)")
    size_m: tuple[float, float] | None = Field(default=None, description="width (left-right) and depth (front-back) in m")


class RelationSpec(BaseModel):
    """A spatial relation to another object."""

    model_config = ConfigDict(extra="ignore")
    relation: RelationKind
    target: str = Field(min_length=1, max_length=60, description="id of the other object")


class ObjectSpec(BaseModel):
    """One kind of object: how many, what it looks like and where it is."""

    model_config = ConfigDict(extra="ignore")
    id: str = Field(min_length=1, max_length=60, description="unique id, e.g. 'mug', 'red_mug', 'book'")
    label: str = Field(min_length=1, max_length=60, description="generic category in one or two words: 'mug', 'frying pan', 'book'")
    name: str = Field(default="", max_length=60, description="what a person calls it, e.g. 'coffee mug', 'red bowl'")
    count: int = Field(default=1, description="how many of them")
    color: str = Field(default="", max_length=30, description="colour word, e.g. 'red'")
    rgb: tuple[int, int, int] | None = Field(default=None, description="colour as 0-255 RGB, when seen")
    size: str = Field(default="", max_length=20, description="size word: small, large, tall, ... or empty")
    size_m: tuple[float, float, float] | None = Field(default=None, description="width, depth, height in m, when known")
    material: str = Field(default="", max_length=30, description="material word, e.g. 'wooden', 'glass'")
    on: str | None = Field(default=None, description="id of the support or object it rests on")
    inside: str | None = Field(default=None, description="id of the container it is in")
    stacked: bool = Field(default=False, description="its instances are stacked on each other")
    row: bool = Field(default=False, description="its instances stand in a row")
    relations: list[RelationSpec] = Field(default_factory=list)
    position: tuple[float, float] | None = Field(
        default=None, description="where on its support: x from left (0) to right (1), y from front (0) to back (1)")

    @field_validator("label", "name", "color", "size", "material", "id")
    @classmethod
    def _lower(cls, v: str) -> str:
        return " ".join(v.lower().split())

    @property
    def display(self) -> str:
        return self.name or self.label


class SceneSpec(BaseModel):
    """The scene: supports and objects (see the module doc)."""

    model_config = ConfigDict(extra="ignore")
    supports: list[SupportSpec] = Field(default_factory=list)
    objects: list[ObjectSpec] = Field(default_factory=list)
    warnings: list[str] = Field(default_factory=list, description="anything that could not be represented")

    def total(self) -> int:
        return sum(o.count for o in self.objects)

    def object(self, ident: str) -> ObjectSpec | None:
        return next((o for o in self.objects if o.id == ident), None)

    def support(self, ident: str) -> SupportSpec | None:
        return next((s for s in self.supports if s.id == ident), None)


def _inline(schema: dict[str, Any], defs: dict[str, Any]) -> Any:
    if isinstance(schema, dict):
        if "$ref" in schema:
            return _inline(defs[schema["$ref"].split("/")[-1]], defs)
        return {k: _inline(v, defs) for k, v in schema.items() if k not in ("$defs", "title", "default")}
    if isinstance(schema, list):
        return [_inline(v, defs) for v in schema]
    return schema


def json_schema() -> dict[str, Any]:
    """The tool input schema for :class:`SceneSpec` (references inlined)."""
    raw = SceneSpec.model_json_schema()
    return _inline(raw, raw.get("$defs", {}))


def _clip(value: float, lo: float, hi: float, what: str, notes: list[str]) -> float:
    if value < lo or value > hi:
        clipped = min(max(value, lo), hi)
        notes.append(f"{what} {value:g} out of range: clamped to {clipped:g}")
        return clipped
    return value


def clamp(spec: SceneSpec) -> tuple[SceneSpec, list[str]]:
    """Values brought into range (counts, heights, sizes, positions, colours), dangling ids
    dropped; returns the new spec and one note per change."""
    notes: list[str] = []
    spec = spec.model_copy(deep=True)
    seen: set[str] = set()
    for s in spec.supports:
        if s.height_m is not None:
            s.height_m = 0.0 if s.kind == "floor" else _clip(s.height_m, 0.2, 2.0, f"support {s.id} height", notes)
        if s.size_m is not None:
            s.size_m = tuple(_clip(v, 0.3, 4.0, f"support {s.id} size", notes) for v in s.size_m)  # type: ignore[assignment]
        seen.add(s.id)
    for o in spec.objects:
        while o.id in seen:
            o.id += "_2"
        seen.add(o.id)
    for o in spec.objects:
        o.count = int(_clip(o.count, 1, MAX_COUNT, f"{o.id} count", notes))
        if o.size_m is not None:
            o.size_m = tuple(_clip(v, 0.005, 2.5, f"{o.id} size", notes) for v in o.size_m)  # type: ignore[assignment]
        if o.position is not None:
            o.position = tuple(_clip(v, 0.0, 1.0, f"{o.id} position", notes) for v in o.position)  # type: ignore[assignment]
        if o.rgb is not None:
            o.rgb = tuple(int(_clip(v, 0, 255, f"{o.id} rgb", notes)) for v in o.rgb)  # type: ignore[assignment]
        if o.size and o.size not in SIZE_WORDS:
            notes.append(f"{o.id}: size word {o.size!r} unknown: ignored")
            o.size = ""
        for attr in ("on", "inside"):
            target = getattr(o, attr)
            if target is not None and (target not in seen or target == o.id):
                notes.append(f"{o.id}: {attr} {target!r} names nothing in the scene: dropped")
                setattr(o, attr, None)
        kept = []
        for r in o.relations:
            if r.target in seen and r.target != o.id and spec.support(r.target) is None:
                kept.append(r)
            else:
                notes.append(f"{o.id}: {r.relation} {r.target!r} names no other object: dropped")
        o.relations = kept
    return spec, notes
