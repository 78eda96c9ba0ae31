"""Complete single-view object scans into solids that rest on their support.

A camera sees one side of an object. Each segmented cluster becomes a closed shape (one convex
piece, or several when the body is not convex) whose base lies on what the object stands on: the
support plane, or the top of the object under it. The shape the evidence supports is chosen:
round bodies (each height band a circle about one axis, a silhouette as wide as the circle) are a
cylinder or their visible profile revolved; open round containers are hollow with the scanned
wall; other bodies are their visible hull extruded down, mirrored about the occluding contour when
the camera saw their front half, in slabs when long and bent. The observed points are kept for the
visual mesh colour.

For a camera view the line of sight to every observed pixel is empty space: a completed shape
is voxelized and every voxel the camera saw through (it projects to a pixel whose captured depth
lies farther away) is carved off; a shape much seen through is kept as convex tiles of what is
left, so no completed object covers a pixel where the camera saw something behind it.

Modules: ``view`` (the depth image and its free space), ``carving`` (carved hulls, tiles),
``circles``, ``revolution`` (round bodies), ``containers`` (open round containers, hollow),
``mirror``, ``extrusion`` (hulls and slabs), ``hull`` (Qhull meshes), ``neighbours``, ``stacking``
and ``stage`` (the pipeline stage).
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
from realsim.completion.stage import complete_and_begin_meshes, complete_objects
from realsim.completion.view import DepthView

__all__ = [
    "CompletionParams", "ContainerParams", "DepthView", "OpenContainer", "carve_free_space", "clip_convex", "complete_cylinder",
    "complete_and_begin_meshes", "complete_hull", "complete_objects", "complete_open_container", "fit_circle", "mirror_hidden_half", "round_rim",
]
