"""Objects from a photo: Claude lists the interactive objects in view (structured output).

The reply is validated object by object (pydantic); an invalid entry is dropped with a note.
Names then label the scan's clusters (:func:`match_clusters`: image position of the projected
cluster centroid, size and colour, one-to-one by the Hungarian method) or, with no scan, become
the object list.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator
from scipy.optimize import linear_sum_assignment

from realsim import llm
from realsim.cache import DiskCache
from realsim.errors import InputError
from realsim.understanding.calls import CallLog, encode_image, image_block, tool_call
from realsim.understanding.prompts import PHOTO_PROMPT, load_prompt
from realsim.understanding.sanitize import clean_text, safe_label

PHOTO_SUFFIXES = (".jpg", ".jpeg", ".png", ".webp", ".bmp")
PHOTO_TOOL = "report_objects"
MAX_OBJECTS = 30
PHOTO_SCHEMA: dict[str, Any] = {
    "type": "object",
    "properties": {
        "objects": {
            "type": "array",
            "maxItems": MAX_OBJECTS,
            "description": "Every object a robot arm could pick, push or open; not walls, floors or the table itself.",
            "items": {
                "type": "object",
                "properties": {
                    "name": {"type": "string", "description": "short specific name, e.g. 'red mug'"},
                    "label": {"type": "string", "description": "generic category in one or two words, e.g. 'mug', 'cereal box'"},
                    "size_m": {"type": "array", "items": {"type": "number"}, "minItems": 3, "maxItems": 3,
                               "description": "rough width, depth, height in metres"},
                    "color": {"type": "string", "description": "dominant colour name"},
                    "rgb": {"type": "array", "items": {"type": "integer", "minimum": 0, "maximum": 255}, "minItems": 3, "maxItems": 3,
                            "description": "dominant colour as 0-255 RGB"},
                    "x": {"type": "number", "minimum": 0, "maximum": 1, "description": "object centre, fraction of the image width from the left"},
                    "y": {"type": "number", "minimum": 0, "maximum": 1, "description": "object centre, fraction of the image height from the top"},
                },
                "required": ["name", "label", "size_m", "color", "x", "y"],
            },
        }
    },
    "required": ["objects"],
}

COLOURS = {
    "red": (0.8, 0.1, 0.1), "green": (0.1, 0.6, 0.2), "blue": (0.1, 0.2, 0.8), "yellow": (0.9, 0.8, 0.1),
    "orange": (0.95, 0.5, 0.1), "white": (0.92, 0.92, 0.92), "black": (0.08, 0.08, 0.08), "gray": (0.5, 0.5, 0.5),
    "grey": (0.5, 0.5, 0.5), "brown": (0.45, 0.3, 0.15), "pink": (0.95, 0.55, 0.7), "purple": (0.5, 0.2, 0.6),
    "silver": (0.75, 0.75, 0.78), "beige": (0.85, 0.78, 0.62), "gold": (0.85, 0.7, 0.2),
}


class PhotoObject(BaseModel):
    """One object Claude saw, validated and bounded."""

    model_config = ConfigDict(extra="ignore")

    name: str = Field(min_length=1, max_length=200)
    label: str = Field(min_length=1, max_length=200)
    size_m: tuple[float, float, float]
    color: str = Field(default="", max_length=200)
    rgb: tuple[int, int, int] | None = None
    x: float = Field(ge=0.0, le=1.0)
    y: float = Field(ge=0.0, le=1.0)

    @field_validator("name", "color")
    @classmethod
    def _text(cls, v: str) -> str:
        return clean_text(v, 60)

    @field_validator("label")
    @classmethod
    def _label(cls, v: str) -> str:
        return safe_label(v)

    @field_validator("size_m")
    @classmethod
    def _size(cls, v: tuple[float, float, float]) -> tuple[float, float, float]:
        if not all(np.isfinite(v)) or min(v) <= 0.002 or max(v) > 5.0:
            raise ValueError("sizes must be within 2 mm .. 5 m")
        return v

    @field_validator("rgb")
    @classmethod
    def _rgb(cls, v: tuple[int, int, int] | None) -> tuple[int, int, int] | None:
        if v is not None and not all(0 <= c <= 255 for c in v):
            raise ValueError("rgb must be 0..255")
        return v

    def rgb01(self) -> np.ndarray | None:
        if self.rgb is not None:
            return np.asarray(self.rgb, float) / 255.0
        for word in reversed(self.color.lower().split()):
            if word in COLOURS:
                return np.asarray(COLOURS[word], float)
        return None


@dataclass
class PhotoResult:
    """What a photo shows: its objects, and notes on what could not be used."""

    objects: list[PhotoObject]
    notes: list[str]


def find_photo(source: Path) -> Path | None:
    """``photo.*`` in a capture folder (first by name), or None."""
    if not source.is_dir():
        return None
    hits = sorted(p for p in source.glob("photo.*") if p.suffix.lower() in PHOTO_SUFFIXES)
    return hits[0] if hits else None


def read_photo(path: Path) -> tuple[bytes, str]:
    """The photo, re-encoded for the API (JPEG, longest side <= 1568 px). InputError if unreadable."""
    try:
        return encode_image(Path(path).read_bytes())
    except FileNotFoundError:
        raise InputError(f"{path}: no such photo") from None
    except OSError as exc:
        raise InputError(f"{path}: not a readable image ({exc}); use a JPEG or PNG photo") from None


def label_photo(path: Path, *, settings: llm.LLMSettings, log: CallLog, cache: DiskCache) -> PhotoResult:
    """The objects Claude finds in the photo. Raises LLMError when the call fails."""
    image, media_type = read_photo(path)
    version, system = load_prompt(PHOTO_PROMPT)
    content = [image_block(image, media_type), {"type": "text", "text": "List the objects in this photo with report_objects."}]
    raw = tool_call(prompt_name=PHOTO_PROMPT, prompt_version=version, system=system, content=content, tool_name=PHOTO_TOOL,
                    schema=PHOTO_SCHEMA, settings=settings, log=log, cache=cache)
    items = raw.get("objects")
    if not isinstance(items, list):
        raise llm.LLMError("the photo reply has no 'objects' list")
    objects, notes = [], []
    for i, item in enumerate(items[:MAX_OBJECTS]):
        try:
            objects.append(PhotoObject.model_validate(item))
        except ValidationError as exc:
            notes.append(f"photo object {i}: dropped ({clean_text(exc.errors()[0].get('msg', exc), 120)})")
    return PhotoResult(objects, notes)


def _size_distance(a: np.ndarray, b: np.ndarray) -> float:
    a = np.sort(np.maximum(np.asarray(a, float), 1e-3))
    b = np.sort(np.maximum(np.asarray(b, float), 1e-3))
    return float(np.sqrt(np.mean(np.log(a / b) ** 2)))


def match_clusters(
    sizes: list[np.ndarray],
    image_xy: list[np.ndarray | None],
    colours: list[np.ndarray | None],
    photo: list[PhotoObject],
    *,
    max_image_distance: float = 0.15,
    max_cost: float = 2.0,
) -> dict[int, int]:
    """cluster index -> photo object index, one-to-one, minimizing position + size + colour cost.

    Position (normalized image distance, weight 4) dominates when the cluster projects into the
    photo; a pair further apart than ``max_image_distance`` never matches. Size is the RMS log
    ratio of sorted extents (weight 1), colour the RGB distance (weight 0.5).
    """
    if not sizes or not photo:
        return {}
    big = 1e6
    cost = np.zeros((len(sizes), len(photo)))
    for i, (size, xy, col) in enumerate(zip(sizes, image_xy, colours)):
        for j, p in enumerate(photo):
            c = _size_distance(size, np.asarray(p.size_m))
            if xy is not None and np.all(np.isfinite(xy)):
                d = float(np.hypot(xy[0] - p.x, xy[1] - p.y))
                c += 4.0 * d if d <= max_image_distance else big
            pc = p.rgb01()
            if col is not None and pc is not None:
                c += 0.5 * float(np.linalg.norm(np.asarray(col, float) - pc)) / np.sqrt(3)
            cost[i, j] = c
    rows, cols = linear_sum_assignment(cost)
    return {int(r): int(c) for r, c in zip(rows, cols) if cost[r, c] <= max_cost}
