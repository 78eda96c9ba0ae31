"""Round objects: circles fitted to the visible arc of a footprint, upright cylinders."""

from __future__ import annotations

import numpy as np
import trimesh

from realsim.completion.circles import arc_coverage_deg, fit_circle
from realsim.completion.params import CompletionParams


def complete_cylinder(points: np.ndarray, base_z: float, top_z: float, params: CompletionParams) -> tuple[trimesh.Trimesh, np.ndarray] | None:
    """An upright cylinder (world frame) when the footprint is a circular arc, else None."""
    side = points[points[:, 2] < top_z - 0.25 * (top_z - base_z)]
    xy = (side if len(side) >= params.min_points else points)[:, :2]
    centre, radius, rms = fit_circle(xy)
    if radius > params.cylinder_max_radius or rms > params.cylinder_max_rms * radius:
        return None
    if arc_coverage_deg(xy, centre) < params.cylinder_min_arc_deg:
        return None
    height = top_z - base_z
    mesh = trimesh.creation.cylinder(radius=radius, height=height, sections=params.cylinder_sections)
    mesh.apply_translation([centre[0], centre[1], base_z + height / 2])
    return mesh, np.array([centre[0], centre[1], base_z])
