"""Two-pass physics manifests with Claude.

Pass one (``prompts/manifest_record.md``) sends the object's name, a thumbnail of its mesh, its
measured dimensions and the scene context, and asks for a record of explicit metrics: material,
wall thickness, hollow or solid, fill, surface finish, parts and joints, each with a reason.
Pass two (``prompts/manifest_values.md``) turns that record into manifest values. Both are tool
calls with a JSON schema, validated with pydantic.

Every value is checked on its own (type and range, then plausibility: density of the solid
volume or of a hollow shell between 20 and 20000 kg/m^3, friction in [0.05, 2], restitution in
[0, 1], hinge/slide only for an object with parts); a value that fails keeps the offline
estimate and ``sources`` says ``"fallback"`` for it, with a note why. Accepted values say
``"claude"``. Inertia is the geometry's, scaled to the final mass.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from realsim import llm
from realsim.assets import PreparedObject
from realsim.cache import DiskCache
from realsim.physics import ObjectManifest, estimate_manifest, solref_from_restitution
from realsim.physics.manifest import GRIPPER_OPENING
from realsim.physics.size_table import load_materials, lookup
from realsim.understanding.calls import CallLog, image_block, tool_call
from realsim.understanding.prompts import RECORD_PROMPT, VALUES_PROMPT, load_prompt
from realsim.understanding.sanitize import clean_text, safe_label

RECORD_TOOL = "record_object_metrics"
VALUES_TOOL = "make_physics_manifest"
DENSITY_RANGE = (20.0, 20000.0)  # kg/m^3
FRICTION_RANGE = (0.05, 2.0)
MIN_SHELL = 0.0002  # m, thinnest wall considered (can stock)
CLAUDE_FIELDS = ("mass_kg", "friction", "restitution", "joint_type", "hollow", "material_class")

_REASON = {"type": "string", "description": "one sentence: why"}
RECORD_SCHEMA: dict[str, Any] = {
    "type": "object",
    "properties": {
        "material": {"type": "string", "description": "main material of the walls/body, e.g. ceramic, cardboard, steel"},
        "material_reason": _REASON,
        "hollow": {"type": "boolean", "description": "true if the body is a shell around an empty or filled cavity"},
        "hollow_reason": _REASON,
        "wall_thickness_mm": {"type": ["number", "null"], "description": "wall thickness for hollow objects, null if solid"},
        "fill": {"type": "string", "enum": ["empty", "partial", "full", "solid", "unknown"], "description": "what is inside"},
        "fill_fraction": {"type": ["number", "null"], "minimum": 0, "maximum": 1},
        "contents": {"type": "string", "description": "what fills it (e.g. 'dry crackers', 'liquid soap'), empty if nothing"},
        "surface_finish": {"type": "string", "description": "e.g. glazed, matte paperboard, rubberized, brushed metal"},
        "parts": {
            "type": "array",
            "maxItems": 12,
            "description": "rigid parts; one entry for a single rigid object; joint = how the part moves relative to the main part",
            "items": {
                "type": "object",
                "properties": {"name": {"type": "string"}, "joint": {"type": "string", "enum": ["none", "hinge", "slide", "fixed"]}, "reason": _REASON},
                "required": ["name", "joint"],
            },
        },
        "notes": {"type": "string"},
    },
    "required": ["material", "material_reason", "hollow", "fill", "surface_finish", "parts"],
}

VALUES_SCHEMA: dict[str, Any] = {
    "type": "object",
    "properties": {
        "mass_kg": {"type": "number", "description": "total mass in kg including contents"},
        "friction": {"type": "number", "description": "sliding friction coefficient against a dry wooden table"},
        "restitution": {"type": "number", "description": "coefficient of restitution for a drop on a hard floor, 0..1"},
        "joint_type": {"type": "string", "enum": ["free", "hinge", "slide", "fixed"],
                       "description": "free: moves as one rigid body; fixed: immovable; hinge/slide: the object is an articulated fixture"},
        "joint_axis": {"type": ["array", "null"], "items": {"type": "number"}, "minItems": 3, "maxItems": 3},
        "joint_range": {"type": ["array", "null"], "items": {"type": "number"}, "minItems": 2, "maxItems": 2},
        "hollow": {"type": "boolean"},
        "material_class": {"type": "string", "description": "one key of the material table given in the instructions"},
        "reasons": {"type": "object", "additionalProperties": {"type": "string"}, "description": "field name -> why"},
    },
    "required": ["mass_kg", "friction", "restitution", "joint_type", "hollow", "material_class", "reasons"],
}


class Part(BaseModel):
    """One part of an object as Claude describes it: its name and the joint that moves it."""

    model_config = ConfigDict(extra="ignore")
    name: str = Field(default="part", max_length=200)
    joint: Literal["none", "hinge", "slide", "fixed"] = "none"
    reason: str = ""

    @field_validator("name", "reason")
    @classmethod
    def _t(cls, v: str) -> str:
        return clean_text(v, 120)


class MetricsRecord(BaseModel):
    """Pass one: explicit metrics of one object, with reasons."""

    model_config = ConfigDict(extra="ignore")
    material: str = Field(min_length=1, max_length=200)
    material_reason: str = ""
    hollow: bool
    hollow_reason: str = ""
    wall_thickness_mm: float | None = Field(default=None, gt=0, le=300)
    fill: Literal["empty", "partial", "full", "solid", "unknown"] = "unknown"
    fill_fraction: float | None = Field(default=None, ge=0, le=1)
    contents: str = ""
    surface_finish: str = ""
    parts: list[Part] = Field(default_factory=list, max_length=12)
    notes: str = ""

    @field_validator("material", "material_reason", "hollow_reason", "contents", "surface_finish", "notes")
    @classmethod
    def _t(cls, v: str) -> str:
        return clean_text(v, 200)


class ManifestValues(BaseModel):
    """Pass two: candidate manifest values, each optional so each is validated on its own."""

    model_config = ConfigDict(extra="ignore")
    mass_kg: float | None = Field(default=None, gt=0, le=10000)
    friction: float | None = Field(default=None, ge=FRICTION_RANGE[0], le=FRICTION_RANGE[1])
    restitution: float | None = Field(default=None, ge=0, le=1)
    joint_type: Literal["free", "hinge", "slide", "fixed"] | None = None
    joint_axis: tuple[float, float, float] | None = None
    joint_range: tuple[float, float] | None = None
    hollow: bool | None = None
    material_class: str | None = Field(default=None, max_length=60)


@dataclass
class ClaudeManifest:
    """The merged manifest, the pass-one record and what was rejected."""

    manifest: ObjectManifest
    record: MetricsRecord | None = None
    rejected: dict[str, str] = field(default_factory=dict)
    error: str | None = None


def describe(prepared: PreparedObject) -> str:
    """Measured geometry, as the prompt states it."""
    s = np.asarray(prepared.size, float) * 1000
    return (
        f"measured size x, y, z: {s[0]:.0f} x {s[1]:.0f} x {s[2]:.0f} mm (z up); "
        f"closed volume {prepared.volume * 1e6:.1f} cm^3; convex hull volume {prepared.convex_hull_volume * 1e6:.1f} cm^3; "
        f"surface area {prepared.surface_area * 1e4:.0f} cm^2; convex parts in the collision model: {len(prepared.hulls)}; "
        f"the mesh shows an open cavity: {'yes' if prepared.open_cavity else 'no'}"
    )


def _offline_summary(m: ObjectManifest) -> str:
    return json.dumps({"category": m.category, "mass_kg": round(m.mass_kg, 4), "friction": m.friction[0], "restitution": m.restitution,
                       "joint_type": m.joint_type, "hollow": m.hollow, "material_class": m.material_class}, sort_keys=True)


def _field_value(name: str, value: Any) -> tuple[Any, str | None]:
    """(validated value, None) or (None, reason) for one pass-two field."""
    try:
        return getattr(ManifestValues.model_validate({name: value}), name), None
    except ValidationError as exc:
        err = exc.errors()[0]
        return None, clean_text(f"{err.get('msg', 'invalid')} (got {value!r})", 160)


def _inertia(prepared: PreparedObject, mass: float) -> tuple[float, ...]:
    I = np.asarray(prepared.inertia_unit_mass, float) * mass
    I = 0.5 * (I + I.T)
    w, R = np.linalg.eigh(I)
    w = np.maximum(w, max(w.max() * 1e-3, 1e-9))
    I = R @ np.diag(w) @ R.T
    return (float(I[0, 0]), float(I[1, 1]), float(I[2, 2]), float(I[0, 1]), float(I[0, 2]), float(I[1, 2]))


def plausible_mass(prepared: PreparedObject, mass: float, hollow: bool, wall_m: float | None) -> str | None:
    """None when ``mass`` fits a density in DENSITY_RANGE of the solid volume or (hollow) of a shell."""
    lo, hi = DENSITY_RANGE
    V = max(prepared.volume, 1e-9)
    if lo <= mass / V <= hi:
        return None
    if hollow:
        shell = min(max(wall_m or 0.002, MIN_SHELL) * max(prepared.surface_area, 1e-9), V)
        if lo <= mass / shell <= hi and mass <= hi * V:
            return None
    return f"implies {mass / V:.0f} kg/m^3 of the {V * 1e6:.0f} cm^3 solid volume" + (" (or of a shell)" if hollow else "") + f", outside {lo:g}-{hi:g}"


def merge(prepared: PreparedObject, offline: ObjectManifest, record: MetricsRecord, raw: dict[str, Any]) -> tuple[ObjectManifest, dict[str, str]]:
    """Offline manifest updated with every pass-two value that validates; (manifest, rejected)."""
    rejected: dict[str, str] = {}
    values: dict[str, Any] = {}
    for name in ("mass_kg", "friction", "restitution", "joint_type", "joint_axis", "joint_range", "hollow", "material_class"):
        if name not in raw or raw[name] is None:
            if name in CLAUDE_FIELDS:
                rejected[name] = "missing from the reply"
            continue
        v, why = _field_value(name, raw[name])
        if why is not None:
            rejected[name] = why
        else:
            values[name] = v
    hollow = values.get("hollow", record.hollow)
    wall = record.wall_thickness_mm / 1000 if record.wall_thickness_mm else None
    if "mass_kg" in values:
        why = plausible_mass(prepared, values["mass_kg"], bool(hollow), wall)
        if why:
            rejected["mass_kg"] = f"{values.pop('mass_kg'):.4g} kg {why}"
    if "material_class" in values:
        mat = safe_label(values["material_class"], 40, "")
        if mat not in load_materials():
            rejected["material_class"] = f"unknown material {clean_text(values.pop('material_class'), 40)!r}"
        else:
            values["material_class"] = mat
    mass = values.get("mass_kg", offline.mass_kg)
    size = np.asarray(prepared.size, float)
    joint = values.get("joint_type")
    axis, rng = offline.joint_axis, offline.joint_range
    if joint in ("hinge", "slide"):
        moving = [p for p in record.parts if p.joint == joint]
        table = lookup(prepared.label)
        table_joint = table.category.joint if table and table.category.joint else None
        axis_v, rng_v = values.get("joint_axis"), values.get("joint_range")
        if len(record.parts) < 2 or not moving:
            rejected["joint_type"] = f"{joint} needs an object with parts and a {joint} between them (record lists {len(record.parts)} part(s))"
        elif len(prepared.hulls) < 2:
            rejected["joint_type"] = f"{joint} needs a mesh of several parts (the collision model is one convex piece)"
        else:
            if axis_v is not None and np.linalg.norm(axis_v) > 1e-6:
                axis = tuple(float(x) for x in np.asarray(axis_v) / np.linalg.norm(axis_v))
            elif table_joint and table_joint.get("type") == joint:
                axis = tuple(float(x) for x in table_joint["axis"])
            else:
                axis = None
            limit = 2 * np.pi if joint == "hinge" else 2.0
            if rng_v is not None and rng_v[0] < rng_v[1] and max(abs(rng_v[0]), abs(rng_v[1])) <= limit:
                rng = (float(rng_v[0]), float(rng_v[1]))
            elif table_joint and table_joint.get("type") == joint:
                rng = tuple(float(x) for x in table_joint["range"])
            else:
                rng = None
            if axis is None or rng is None:
                rejected["joint_type"] = f"{joint} without a valid axis and range"
        if "joint_type" in rejected:
            values.pop("joint_type")
            axis, rng = offline.joint_axis, offline.joint_range
    elif joint == "fixed" and not (mass >= 10.0 or size.max() >= 0.6):
        rejected["joint_type"] = f"fixed is for furniture or heavy objects ({mass:.3g} kg, largest extent {size.max():.2f} m)"
        values.pop("joint_type")
    elif joint == "free":
        axis, rng = None, None
    joint_type = values.get("joint_type", offline.joint_type)

    sources = dict(offline.sources)
    for name in CLAUDE_FIELDS:
        if name in values:
            sources[name] = "claude"
        elif name in rejected:
            sources[name] = "fallback"
    friction = (values["friction"], *offline.friction[1:]) if "friction" in values else offline.friction
    restitution = values.get("restitution", offline.restitution)
    sources["solref"] = sources.get("restitution", "table")
    inertia = _inertia(prepared, mass) if mass != offline.mass_kg else offline.inertia
    graspable = bool(np.sort(size)[0] <= GRIPPER_OPENING and mass <= 3.0 and joint_type == "free")
    notes = list(offline.notes)
    notes.append(f"claude record: {record.material} ({record.material_reason}); hollow={record.hollow}; fill={record.fill}; "
                 f"finish={record.surface_finish}; parts={[p.name for p in record.parts][:6]}")
    for name, why in sorted(rejected.items()):
        notes.append(f"claude {name} rejected: {why}; offline estimate kept")
    merged = offline.model_copy(update={
        "mass_kg": float(mass), "friction": tuple(float(f) for f in friction), "restitution": float(restitution),
        "solref": solref_from_restitution(float(restitution)), "inertia": inertia, "joint_type": joint_type,
        "joint_axis": axis if joint_type in ("hinge", "slide") else None, "joint_range": rng if joint_type in ("hinge", "slide") else None,
        "hollow": bool(values.get("hollow", offline.hollow)), "material_class": values.get("material_class", offline.material_class),
        "is_graspable": graspable, "is_pushable": bool(joint_type == "free" and mass <= 10.0), "is_openable": joint_type in ("hinge", "slide"),
        "notes": notes, "sources": sources,
    })
    return ObjectManifest.model_validate(merged.model_dump()), rejected


def fallback_manifest(offline: ObjectManifest, reason: str) -> ObjectManifest:
    """The offline manifest, marked as a fallback for every value Claude should have given."""
    sources = dict(offline.sources)
    for name in CLAUDE_FIELDS:
        sources[name] = "fallback"
    return offline.model_copy(update={"sources": sources, "notes": [*offline.notes, f"claude manifest failed ({reason}); offline estimate used"]})


def claude_manifest(
    prepared: PreparedObject,
    *,
    name: str,
    context: str,
    thumbnail_png: bytes | None,
    settings: llm.LLMSettings,
    log: CallLog,
    cache: DiskCache,
    offline: ObjectManifest | None = None,
) -> ClaudeManifest:
    """Both passes for one object; never raises (a failure returns the offline manifest, noted)."""
    offline = offline or estimate_manifest(prepared)
    try:
        v1, system1 = load_prompt(RECORD_PROMPT)
        text = f"Object: {clean_text(name, 80)} (label: {clean_text(prepared.label, 60)})\n{describe(prepared)}\nScene: {clean_text(context, 600)}"
        if thumbnail_png:
            content = [image_block(thumbnail_png), {"type": "text", "text": text + "\nThe image is a rendering of the object's mesh in its mean colour."}]
        else:
            content = [{"type": "text", "text": text + "\n(No image available.)"}]
        raw1 = tool_call(prompt_name=RECORD_PROMPT, prompt_version=v1, system=system1, content=content, tool_name=RECORD_TOOL,
                         schema=RECORD_SCHEMA, settings=settings, log=log, cache=cache)
        try:
            record = MetricsRecord.model_validate(raw1)
        except ValidationError as exc:
            err = exc.errors()[0]
            raise llm.LLMError(f"pass one record invalid: {'.'.join(str(x) for x in err.get('loc', ()))}: {err.get('msg')}") from None
        v2, system2 = load_prompt(VALUES_PROMPT)
        materials = ", ".join(sorted(load_materials()))
        text2 = (f"Object: {clean_text(name, 80)} (label: {clean_text(prepared.label, 60)})\n{describe(prepared)}\n"
                 f"Record of explicit metrics (pass one):\n{record.model_dump_json()}\n"
                 f"Offline estimate from tables (for reference only): {_offline_summary(offline)}\n"
                 f"material_class must be one of: {materials}")
        raw2 = tool_call(prompt_name=VALUES_PROMPT, prompt_version=v2, system=system2, content=[{"type": "text", "text": text2}],
                         tool_name=VALUES_TOOL, schema=VALUES_SCHEMA, settings=settings, log=log, cache=cache)
        manifest, rejected = merge(prepared, offline, record, raw2)
        manifest.notes.append(f"claude manifest: prompts {v1}, {v2}; model {settings.model}")
        return ClaudeManifest(manifest, record, rejected)
    except llm.LLMError as exc:
        reason = clean_text(str(exc), 200)
        return ClaudeManifest(fallback_manifest(offline, reason), error=reason)
