"""Whether a mesh file given alone is one object (an asset) rather than a scene."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

from realsim.perception.formats import MESH_SUFFIXES, is_point_cloud_ply, read_mesh_file
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
    stamp = path.stat().st_mtime_ns
    extent = _mesh_extent(str(path), stamp)

    def fits(unit: str, size: tuple[float, float]) -> bool:
        return size[0] <= extent * UNIT_SCALE[unit] <= size[1]

    scene_size = (OBJECT_EXTENT[1], PLAUSIBLE_EXTENT[1])
    if fits("m", OBJECT_EXTENT) or fits("m", scene_size):
        return fits("m", OBJECT_EXTENT)
    if not (fits("cm", OBJECT_EXTENT) or fits("mm", OBJECT_EXTENT)):
        return False
    return _one_closed_body(str(path), stamp)  # the costly check, only when the size alone cannot tell


def _load(path: str) -> Any:
    return read_mesh_file(Path(path))


@lru_cache(maxsize=16)
def _mesh_extent(path: str, mtime_ns: int) -> float:
    """The largest bounding-box side of a mesh file; 0 when it has no faces or cannot be read (the scan path reports why)."""
    try:
        mesh = _load(path)
        bounds = mesh.bounds
    except Exception:  # unreadable or absurd geometry: not an object (the scan path says what is wrong)
        return 0.0
    if bounds is None or not np.all(np.isfinite(bounds)) or len(getattr(mesh, "faces", ())) == 0:
        return 0.0
    return float(np.max(bounds[1] - bounds[0]))


@lru_cache(maxsize=16)
def _one_closed_body(path: str, mtime_ns: int) -> bool:
    """Whether a mesh file is one closed body: after welding seams, a connected part holds >= 99.5 %
    of the area and >= 99 % of the edges join exactly two faces. False when it cannot be read."""
    import trimesh

    try:
        loaded = _load(path)
        if len(loaded.faces) == 0:
            return False
        mesh = trimesh.Trimesh(loaded.vertices, loaded.faces, process=False)  # the shared read stays as it was
        mesh.merge_vertices()  # seams welded by position alone (a bare mesh has no uv or normals to keep apart)
        _, uses = np.unique(np.sort(mesh.edges, axis=1), axis=0, return_counts=True)
        parts = trimesh.graph.connected_component_labels(mesh.face_adjacency, node_count=len(mesh.faces))
        area = np.bincount(parts, weights=mesh.area_faces)
    except Exception:  # unreadable or absurd geometry: not an object
        return False
    return bool((uses == 2).mean() >= 0.99 and area.max() >= 0.995 * area.sum())
