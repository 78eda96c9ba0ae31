"""Complete single-view object scans into solids that rest on their support.

A camera sees one side of an object. Each segmented cluster becomes a closed convex shape whose
base lies on what the object stands on: the support plane, or the top of the object under it.
Round footprints become upright cylinders fitted to the visible arc; anything else becomes the
convex hull of the observed points and their projection onto the base (the visible hull
extruded down). The observed points are kept for the visual mesh colour.

For a camera view the line of sight to every observed pixel is empty space: a completed shape
is voxelized and every voxel the camera saw through (it projects to a pixel whose captured depth
lies farther away) is carved off, so no completed object covers a pixel where the camera saw
something behind it.

Modules: ``view`` (the depth image and its free space), ``carving``, ``revolution`` (round objects),
``containers`` (open round containers, hollow), ``mirror``, ``extrusion`` (the last resort),
``neighbours``, ``stacking`` and ``stage`` (the pipeline stage).
"""

from __future__ import annotations

from realsim.completion.carving import carve_free_space
from realsim.completion.circles import fit_circle
from realsim.completion.containers import ContainerParams, OpenContainer, complete_open_container, round_rim
from realsim.completion.extrusion import complete_hull
from realsim.completion.mirror import mirror_hidden_half
from realsim.completion.neighbours import clip_convex
from realsim.completion.params import CompletionParams
from realsim.completion.revolution import complete_cylinder
from realsim.completion.stage import complete_objects
from realsim.completion.view import DepthView

__all__ = [
    "CompletionParams", "ContainerParams", "DepthView", "OpenContainer", "carve_free_space", "clip_convex", "complete_cylinder",
    "complete_hull", "complete_objects", "complete_open_container", "fit_circle", "mirror_hidden_half", "round_rim",
]
