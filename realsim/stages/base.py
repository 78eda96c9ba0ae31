"""A stage: a named step ``(Scene, Params) -> Scene`` with its parameter dataclass and the Scene
fields an earlier stage must have filled (checked before it runs, never skipped)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

from realsim.errors import InputError
from realsim.scene import Scene

NEEDS_HINT = {
    "points": "it runs on a scanned point cloud or mesh (use the scan pipeline with a scan capture)",
    "planes": "list 'planes' (scans) or 'objects'/'text' (declared supports) before it",
    "spec": "list 'compose' before it",
}


@dataclass(frozen=True)
class Stage:
    """A named step: its function, its parameter dataclass, and the Scene fields it needs."""

    name: str
    run: Callable[[Scene, Any], Scene]
    params: type
    needs: tuple[str, ...] = ()  # Scene fields an earlier stage must have filled

    def check(self, scene: Scene, pipeline: str) -> None:
        """InputError when an earlier stage has not filled what this one needs."""
        for attr in self.needs:
            value = getattr(scene, attr)
            if value is None or (hasattr(value, "__len__") and len(value) == 0):
                raise InputError(f"pipeline {pipeline}: stage {self.name!r} needs the scene's {attr}, which no earlier stage "
                                 f"produced; {NEEDS_HINT.get(attr, 'check the order of the stages')}")
