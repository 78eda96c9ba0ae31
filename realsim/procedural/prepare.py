"""A generated part as a :class:`~realsim.assets.PreparedObject`: its own convex pieces, no CoACD.

Procedural shapes are assembled from convex pieces, so the collision hulls are known exactly
(cavities stay open by construction) and preparing a part takes milliseconds; mass properties
come from the watertight solid the same way as for a mesh file.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from realsim.assets.decompose import make_hull
from realsim.assets.params import AssetParams
from realsim.assets.prepare import OPEN_CAVITY_RATIO, PreparedObject, _inertia_for
from realsim.physics.size_table import lookup
from realsim.procedural.generate import Part

SOURCE_PREFIX = "procedural"  # PreparedObject.source of generated parts: procedural/<label>


def prepare_part(part: Part, params: AssetParams = AssetParams()) -> PreparedObject:
    """The part ready for MJCF: visual = its solid, hulls = its convex pieces (thickened when flat)."""
    solid = part.mesh
    hulls = [h for h in (make_hull(p, params.min_hull_thickness, params.max_hull_vertices) for p in part.hulls) if h is not None]
    if not hulls:
        raise ValueError(f"{part.label}: no valid collision piece")
    hull_volume = float(solid.convex_hull.volume)
    open_cavity = hull_volume > 0 and solid.volume / hull_volume < OPEN_CAVITY_RATIO
    com, inertia, model = _inertia_for(solid, part.label, open_cavity)
    m = lookup(part.label)
    return PreparedObject(
        label=part.label, source=Path(SOURCE_PREFIX) / part.label.replace(" ", "_"), visual=solid.copy(), texture_png=None,
        rgba=(*(float(c) for c in part.color), 1.0), color=np.asarray(part.color, float), hulls=hulls, volume=float(solid.volume), size=np.asarray(solid.extents, float),
        com=com, inertia_unit_mass=inertia, scale_applied=1.0, solid=solid, surface_area=float(solid.area),
        convex_hull_volume=hull_volume, solid_method="procedural", inertia_model=model,
        decomposition={"method": "procedural", "hulls": len(hulls)}, category=m.category.name if m else None,
    )
