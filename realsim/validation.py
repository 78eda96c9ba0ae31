"""Checks at the door: every user value is typed, finite and in range before any heavy work.

Stage parameters (``--set stage.param=value`` and pipeline YAML) are validated against their
dataclass's type hints with pydantic; a value of the wrong type, a NaN or infinity, or a
non-positive value for a parameter whose default is positive (a length, a count, a time) is an
:class:`~realsim.errors.InputError` naming the parameter. Unknown names get the closest valid one.
"""

from __future__ import annotations

import dataclasses
import difflib
import math
import typing
from typing import Any, Iterable

from pydantic import PydanticSchemaGenerationError, TypeAdapter, ValidationError

from realsim.errors import InputError

MAX_SEED = 2**32 - 1


def did_you_mean(name: str, options: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` for the closest of ``options``, or an empty string."""
    close = difflib.get_close_matches(name, list(options), n=1, cutoff=0.6)
    return f" (did you mean {close[0]!r}?)" if close else ""


def unknown_names(given: Iterable[str], valid: Iterable[str], where: str) -> None:
    """Raise InputError for the first name in ``given`` that is not in ``valid``."""
    valid = sorted(valid)
    for name in given:
        if name not in valid:
            raise InputError(f"{where}: unknown name {name!r}{did_you_mean(name, valid)}; valid: {', '.join(valid)}")


def _all_finite(value: Any) -> bool:
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, (list, tuple)):
        return all(_all_finite(v) for v in value)
    if isinstance(value, dict):
        return all(_all_finite(v) for v in value.values())
    return True


def check_param(cls: type, name: str, value: Any, default: Any, where: str | None = None) -> Any:
    """``value`` converted to the type of ``cls.name`` and checked (finite; positive when the default is).

    ``where`` names the parameter in messages (``planes.distance_threshold``); default ``Class.name``.
    """
    shown = f"{where or cls.__name__}.{name}"
    try:
        adapter = TypeAdapter(typing.get_type_hints(cls)[name])
    except (PydanticSchemaGenerationError, NameError, TypeError):  # an arbitrary type: no schema to check
        return value
    try:
        converted = adapter.validate_python(value)
    except ValidationError as exc:
        first = exc.errors()[0]
        item = f" (item {'.'.join(str(p) for p in first['loc'])})" if first["loc"] else ""
        raise InputError(f"{shown} = {value!r}: {first['msg'].lower()}{item}") from None
    if not _all_finite(converted):
        raise InputError(f"{shown} = {value!r}: must be a finite number")
    is_number = isinstance(converted, (int, float)) and not isinstance(converted, bool)
    default_positive = isinstance(default, (int, float)) and not isinstance(default, bool) and default > 0
    if is_number and default_positive and (converted <= 0 if isinstance(default, float) else converted < 0):
        raise InputError(f"{shown} = {value!r}: must be {'positive' if isinstance(default, float) else '>= 0'} "
                         f"(default {default})")
    return converted


def build_params(cls: type, overrides: dict[str, Any], where: str | None = None) -> Any:
    """``cls()`` with ``overrides`` applied and validated (nested dataclasses from nested mappings);
    ``where`` (``planes``) names the parameters in messages."""
    default = cls()
    if not overrides:
        return default
    if not isinstance(overrides, dict):
        raise InputError(f"{where or cls.__name__}: expected a mapping of parameters, got {overrides!r}")
    fields = {f.name for f in dataclasses.fields(cls)}
    unknown_names(overrides, fields, f"parameters of {where or cls.__name__}")
    values = {}
    for key, value in overrides.items():
        current = getattr(default, key)
        if dataclasses.is_dataclass(current) and isinstance(value, dict):
            values[key] = build_params(type(current), value, f"{where or cls.__name__}.{key}")
        else:
            values[key] = check_param(cls, key, value, current, where)
    return dataclasses.replace(default, **values)


def check_seed(seed: Any) -> int:
    """A seed is an integer in [0, 2**32 - 1]."""
    if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed <= MAX_SEED:
        raise InputError(f"--seed {seed!r}: must be an integer from 0 to {MAX_SEED}")
    return seed
