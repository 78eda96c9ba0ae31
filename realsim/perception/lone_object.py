"""Whether a mesh file given alone is one object (an asset) rather than a scene."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import numpy as np

from realsim.perception.formats import MESH_SUFFIXES, is_point_cloud_ply
from realsim.perception.resolution import PLAUSIBLE_EXTENT, UNIT_SCALE

OBJECT_EXTENT = (0.01, 0.6)  # m: an object is this large


def is_lone_object(path: Path) -> bool:
    """A mesh file that is one object (a scanned or generated asset), converted like a capture
    holding it in ``objects/``: 1-60 cm across in metres (a scene holds a support wider than what
    stands on it), or, when metres fit neither, 1-60 cm in millimetres and one closed body (an STL
    of a 19 cm bottle, not a 1.9 m scene in centimetres: scans of scenes are open surfaces or
    several bodies)."""
    if not path.is_file() or path.suffix.lower() not in MESH_SUFFIXES or (path.suffix.lower() == ".ply" and is_point_cloud_ply(path)):
        return False
    extent, one_body = _mesh_shape(str(path), path.stat().st_mtime_ns)

    def fits(unit: str, size: tuple[float, float]) -> bool:
        return size[0] <= extent * UNIT_SCALE[unit] <= size[1]

    scene_size = (OBJECT_EXTENT[1], PLAUSIBLE_EXTENT[1])
    if fits("m", OBJECT_EXTENT) or fits("m", scene_size):
        return fits("m", OBJECT_EXTENT)
    return one_body and (fits("cm", OBJECT_EXTENT) or fits("mm", OBJECT_EXTENT))


@lru_cache(maxsize=16)
def _mesh_shape(path: str, mtime_ns: int) -> tuple[float, bool]:
    """(largest bounding-box side, whether it is one closed body) of a mesh file; (0, False) when it
    cannot be read (the scan path reports why). One body: after welding seams, a connected part
    holds >= 99.5 % of the area and >= 99 % of the edges join exactly two faces."""
    import trimesh

    try:
        mesh = trimesh.load(path, force="mesh", process=False)
        bounds = mesh.bounds
        if bounds is None or not np.all(np.isfinite(bounds)) or len(mesh.faces) == 0:
            return 0.0, False
        extent = float(np.max(bounds[1] - bounds[0]))
        mesh.merge_vertices(merge_tex=True, merge_norm=True)
        _, uses = np.unique(np.sort(mesh.edges, axis=1), axis=0, return_counts=True)
        parts = trimesh.graph.connected_component_labels(mesh.face_adjacency, node_count=len(mesh.faces))
        area = np.bincount(parts, weights=mesh.area_faces)
    except Exception:  # unreadable or absurd geometry: not an object (the scan path says what is wrong)
        return 0.0, False
    return extent, bool((uses == 2).mean() >= 0.99 and area.max() >= 0.995 * area.sum())
