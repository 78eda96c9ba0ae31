"""Which side of a captured mesh's faces is outside.

Exporters disagree on winding, and a mesh written with every face turned over reads as a world of
undersides: the table top faces down and is dropped as an underside, what faces up is the table's
underside, and no object stands on anything. Winding is an exporter's choice for the whole file, so
the whole mesh is turned or kept, read from its geometry:

- where it has closed bodies (their edges shared by two faces), their signed volumes summed about
  each body's centre are positive (tiny fragments weigh what they hold, next to nothing);
- a mesh of open surfaces only (a scanner's single-sided skin) is seen from the free space the
  scanner stood in, and nothing is seen from below the lowest broad level surface (the floor, or
  the table top of a tabletop scan): that surface faces up.
"""

from __future__ import annotations

from typing import Any

import numpy as np

CLOSED_EDGE_SHARE = 0.95  # a body with this share of its face edges shared by two faces is closed
LEVEL_COS = float(np.cos(np.radians(10.0)))  # a face within 10 degrees of level
LOWEST_BAND = 0.02  # m above the lowest level surface that still belongs to it
LOWEST_QUANTILE = 0.01  # of level area: the lowest surface's height, robust to a stray triangle


def is_turned(mesh: Any, up: np.ndarray, metres_per_unit: float) -> bool:
    """Whether ``mesh``'s faces are wound inward (``up``: world +Z in the mesh's coordinates, a
    unit vector; ``metres_per_unit``: the mesh's scale). A mesh whose winding is inconsistent is
    left as it is (its sides cannot be told)."""
    import trimesh

    faces = np.asarray(mesh.faces)
    n_faces = len(faces)
    if n_faces == 0 or not mesh.is_winding_consistent:
        return False
    adjacency = np.asarray(mesh.face_adjacency)
    body = trimesh.graph.connected_component_labels(adjacency, node_count=n_faces)
    n_bodies = int(body.max()) + 1
    paired = np.bincount(body[adjacency.ravel()], minlength=n_bodies)  # face edges shared by two faces
    closed = paired >= CLOSED_EDGE_SHARE * 3 * np.bincount(body, minlength=n_bodies)
    tris = np.asarray(mesh.triangles)
    if closed.any():
        centre = np.zeros((n_bodies, 3))
        np.add.at(centre, body, tris.mean(axis=1))
        centre /= np.maximum(np.bincount(body, minlength=n_bodies), 1)[:, None]
        rel = tris - centre[body][:, None, :]
        volume = np.bincount(body, np.einsum("ij,ij->i", rel[:, 0], np.cross(rel[:, 1], rel[:, 2])), minlength=n_bodies)
        return bool(volume[closed].sum() < 0)
    facing = np.asarray(mesh.face_normals) @ up
    level = np.abs(facing) >= LEVEL_COS
    if not level.any():
        return False
    area = np.asarray(mesh.area_faces)[level]
    height = tris[level].mean(axis=1) @ up * metres_per_unit
    order = np.argsort(height, kind="stable")
    cumulative = np.cumsum(area[order])
    lowest = height[order][np.searchsorted(cumulative, LOWEST_QUANTILE * cumulative[-1])]
    band = height <= lowest + LOWEST_BAND
    return bool(np.sum(area[band] * np.sign(facing[level][band])) < 0)


def with_outward_faces(mesh: Any, up: np.ndarray, metres_per_unit: float) -> tuple[Any, bool]:
    """``mesh`` wound outward (a turned copy, or the same object) and whether it was turned."""
    if not is_turned(mesh, up, metres_per_unit):
        return mesh, False
    out = mesh.copy()
    out.faces = np.ascontiguousarray(np.asarray(out.faces)[:, ::-1])  # normals follow (Trimesh.invert keeps stale cached ones)
    return out, True
