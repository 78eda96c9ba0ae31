"""Single CSG solids of a few families by height and diameter (for geometry tests and tools).

The object families themselves, with their collision pieces and sites, are in
:mod:`realsim.procedural.families`; these return just the watertight solid.
"""

from __future__ import annotations

from manifold3d import Manifold

from realsim.procedural import families as f
from realsim.procedural.parts import to_trimesh

__all__ = ["bowl", "box", "can", "jar", "mug", "to_trimesh"]


def mug(height: float, diameter: float) -> Manifold:
    """A mug solid of the given height and body diameter (m)."""
    return f.mug_hd(height, diameter).solid


def bowl(height: float, diameter: float) -> Manifold:
    """A bowl solid of the given height and rim diameter (m)."""
    return f.bowl_hd(height, diameter).solid


def can(height: float, diameter: float) -> Manifold:
    """A can solid of the given height and diameter (m)."""
    return f.can((height, diameter, diameter)).solid


def jar(height: float, diameter: float) -> Manifold:
    """A jar solid of the given height and diameter (m)."""
    return f.jar((height, diameter, diameter)).solid


def box(x: float, y: float, z: float) -> Manifold:
    """A box solid of the given extents (m)."""
    return f.box_((x, y, z)).solid
