"""An optional text-to-3D service behind a small interface (off unless configured).

A backend turns a label and description into a mesh file; realsim then treats that file like any
scanned object mesh. None is registered by default: a deployment registers its own with
:func:`register_backend` and selects it with the ``text`` stage's ``text_to_3d`` parameter (or
``REALSIM_TEXT_TO_3D``). Procedural CSG models are used whenever no backend is selected, or when
the backend fails.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Callable, Protocol, runtime_checkable

from realsim.errors import InputError


@runtime_checkable
class TextTo3D(Protocol):
    """A text-to-3D service: ``generate`` writes a mesh (OBJ/GLB/PLY, metres, Z or Y up) and returns its path."""

    name: str

    def generate(self, label: str, description: str, dest: Path, seed: int) -> Path: ...


_REGISTRY: dict[str, Callable[[], TextTo3D]] = {}


def register_backend(name: str, factory: Callable[[], TextTo3D]) -> None:
    """Make a backend selectable by name."""
    _REGISTRY[name] = factory


def available_backends() -> list[str]:
    """The names of the registered text-to-3D backends."""
    return sorted(_REGISTRY)


def get_backend(name: str | None = None) -> TextTo3D | None:
    """The selected backend (``name`` or ``$REALSIM_TEXT_TO_3D``), or None when none is configured."""
    name = name or os.environ.get("REALSIM_TEXT_TO_3D") or None
    if not name:
        return None
    if name not in _REGISTRY:
        known = ", ".join(available_backends()) or "none registered"
        raise InputError(f"unknown text-to-3D backend {name!r} ({known}); unset REALSIM_TEXT_TO_3D to use procedural models")
    return _REGISTRY[name]()
