"""The typed schema of ``capture.yaml``: every key checked before any work.

Unknown keys are rejected with the closest valid name; numbers must be finite and physically
plausible (support heights 0-3 m, support sides 5 cm - 10 m).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any, Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from realsim.errors import InputError
from realsim.validation import did_you_mean

Positive = Annotated[float, Field(gt=0.0, allow_inf_nan=False)]
Height = Annotated[float, Field(ge=0.0, le=3.0, allow_inf_nan=False)]  # metres above the floor


NAMED_ONLY_UNITS = {"in": 0.0254, "ft": 0.3048}  # m per unit: CAD and US apps; detection never guesses them (an inch scene looks like a cm one)


class DeclaredSupport(BaseModel):
    """``support:`` the table object meshes are placed on (no scan)."""

    model_config = ConfigDict(extra="forbid")

    size: tuple[float, float] = (1.2, 0.8)
    height: Height = 0.75
    center: tuple[float, float] = (0.0, 0.0)
    yaw: float = Field(default=0.0, allow_inf_nan=False)
    kind: Literal["table", "counter", "desk", "shelf", "floor"] = "table"

    @field_validator("size")
    @classmethod
    def _plausible_size(cls, value: tuple[float, float]) -> tuple[float, float]:
        if not all(math.isfinite(v) and 0.05 <= v <= 10.0 for v in value):
            raise ValueError("each side must be between 0.05 and 10 m")
        return value

    @field_validator("center")
    @classmethod
    def _finite_center(cls, value: tuple[float, float]) -> tuple[float, float]:
        if not all(math.isfinite(v) for v in value):
            raise ValueError("must be finite")
        return value


class CameraIntrinsics(BaseModel):
    """``camera:`` pinhole intrinsics of an organized capture (pixels), or its vertical field of view."""

    model_config = ConfigDict(extra="forbid")

    fx: Positive | None = None
    fy: Positive | None = None
    cx: float | None = Field(default=None, allow_inf_nan=False)
    cy: float | None = Field(default=None, allow_inf_nan=False)
    fovy_deg: float | None = Field(default=None, gt=1.0, lt=179.0, allow_inf_nan=False)


class CaptureConfig(BaseModel):
    """Everything ``capture.yaml`` may say about a capture."""

    model_config = ConfigDict(extra="forbid")

    units: Literal["m", "cm", "mm", "in", "ft"] | None = None
    up: Literal["+x", "-x", "+y", "-y", "+z", "-z"] | None = None
    support_height: Height | None = None
    support: DeclaredSupport | None = None
    labels: dict[int | str, str] = {}
    text: str | None = None
    camera: CameraIntrinsics | None = None
    sensor: str | None = None  # free text: what made the capture

    @field_validator("labels")
    @classmethod
    def _named(cls, value: dict[int | str, str]) -> dict[int | str, str]:
        for key, name in value.items():
            if not str(name).strip():
                raise ValueError(f"label {key!r} has an empty name")
        return value


def _one_line(exc: ValidationError, where: str) -> str:
    """The first problem of a validation error as one line a user can act on."""
    err = exc.errors()[0]
    loc = ".".join(p if isinstance(p, str) and p.isprintable() and p.strip() == p and p else repr(p) for p in err["loc"])
    if err["type"] == "extra_forbidden":
        nested: dict[str, type[BaseModel]] = {"support": DeclaredSupport, "camera": CameraIntrinsics}
        model = nested[str(err["loc"][0])] if len(err["loc"]) > 1 else CaptureConfig
        valid = list(model.model_fields)
        return f"{where}: unknown key {loc!r}{did_you_mean(str(err['loc'][-1]), valid)}; valid keys: {', '.join(valid)}"
    got = err.get("input")
    shown = "" if isinstance(got, (dict, list)) and len(str(got)) > 60 else f" (got {got!r})"
    return f"{where}: {loc}: {err['msg'].lower()}{shown}"


def parse_capture_config(data: Any, where: str = "capture.yaml") -> CaptureConfig:
    """Validate a loaded ``capture.yaml`` mapping; InputError with one line on the first problem."""
    if data is None:
        return CaptureConfig()
    if not isinstance(data, dict):
        raise InputError(f"{where}: expected a mapping of settings (units, up, support_height, support, labels, text)")
    try:
        return CaptureConfig.model_validate(data)
    except ValidationError as exc:
        raise InputError(_one_line(exc, where)) from None


def read_capture_config(folder: Path) -> CaptureConfig:
    """The validated ``capture.yaml`` of a capture folder (all defaults when absent)."""
    path = folder / "capture.yaml"
    if not path.exists():
        return CaptureConfig()
    try:
        data = yaml.safe_load(path.read_text(errors="replace"))
    except yaml.YAMLError as exc:
        raise InputError(f"{path}: invalid YAML ({str(exc).splitlines()[0]})") from None
    return parse_capture_config(data, str(path))
