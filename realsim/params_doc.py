"""Every stage parameter, documented from the parameter dataclasses themselves: name (as
``--set stage.param``), type, default and the comment written beside it in the source."""

from __future__ import annotations

import dataclasses
import inspect
import re
from dataclasses import dataclass
from typing import Any

_FIELD_LINE = re.compile(r"^\s+(\w+)\s*:\s*[^=#]+(?:=[^#]*)?(?:#\s*(?P<doc>.*))?$")


@dataclass(frozen=True)
class ParamDoc:
    """One parameter: its dotted name, type, default and description."""

    name: str
    type: str
    default: Any
    doc: str


def _comments(cls: type) -> dict[str, str]:
    """Field name -> the comment on its line in the class source ('' when none or no source)."""
    try:
        lines = inspect.getsourcelines(cls)[0]
    except (OSError, TypeError):
        return {}
    out: dict[str, str] = {}
    for line in lines:
        m = _FIELD_LINE.match(line.rstrip())
        if m:
            out.setdefault(m.group(1), (m.group("doc") or "").strip())
    return out


def param_docs(cls: type, prefix: str) -> list[ParamDoc]:
    """Every field of a parameter dataclass (nested dataclasses flattened with dots)."""
    comments = _comments(cls)
    docs: list[ParamDoc] = []
    defaults = cls()
    for f in dataclasses.fields(cls):
        if f.name.startswith("_"):
            continue
        value = getattr(defaults, f.name)
        name = f"{prefix}.{f.name}"
        if dataclasses.is_dataclass(value) and not isinstance(value, type):
            docs += param_docs(type(value), name)
            continue
        kind = f.type if isinstance(f.type, str) else getattr(f.type, "__name__", str(f.type))
        docs.append(ParamDoc(name, kind, value, comments.get(f.name, "")))
    return docs


def stage_param_docs(stages: list[str] | None = None) -> list[ParamDoc]:
    """The parameters of the named stages (all registered stages by default), in pipeline order."""
    from realsim.stages import STAGES

    names = stages or list(STAGES)
    return [doc for name in names for doc in param_docs(STAGES[name].params, name)]
