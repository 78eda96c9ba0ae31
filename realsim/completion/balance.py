"""A completed body stands as it stood: its base must hold its centre of mass.

An object the camera saw standing still rests on a base whose polygon contains its centre of mass.
A completed shape whose base was extruded only under part of it (the camera saw the support past a
leaning box's lower edge, a body cut apart from its neighbour) can have its centre of mass outside
that polygon, and tips over while the scene settles. Its hidden underside is completed down to the
support under the centre of mass, so the base holds it again.
"""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from realsim.completion.hull import trimesh_hull
from realsim.geometry import inside_convex_polygon
from realsim.scene import SceneObject

BASE_BAND = 0.002  # m: vertices this close to the lowest point form the base
FOOT_SLACK = 1.25  # a foot reaches this many margins from the centre of mass (its own volume moves that centre)


def centre_of_mass(pieces: list[trimesh.Trimesh]) -> np.ndarray:
    """Centre of mass of convex pieces of one uniform density (overlaps counted twice)."""
    volumes = np.array([max(p.volume, 0.0) for p in pieces])
    centres = np.array([p.center_mass for p in pieces])
    return np.asarray(volumes @ centres / max(volumes.sum(), 1e-12))


def base_polygon(pieces: list[trimesh.Trimesh]) -> np.ndarray | None:
    """Counter-clockwise convex polygon (xy) of the vertices within ``BASE_BAND`` of the lowest one."""
    verts = np.vstack([p.vertices for p in pieces])
    low = verts[verts[:, 2] <= verts[:, 2].min() + BASE_BAND, :2]
    try:
        return np.asarray(low[ConvexHull(low).vertices])
    except (QhullError, ValueError):
        return None


def brace(obj: SceneObject, margin: float, rounds: int = 4) -> bool:
    """Extend ``obj``'s lowest piece under its centre of mass when its base polygon does not contain
    it (``margin`` inside); True when it was extended. Object frame: the base lies at its lowest z.
    The foot is an octagon whose sides lie ``FOOT_SLACK`` margins from the centre of mass (a wider
    foot fills a narrow body's underside: a lying marker's 19 mm section on a 2 cm disc); the volume
    it adds moves the centre of mass, so it is grown again about the new one, at most ``rounds`` times."""
    pieces = obj.collision
    if not pieces:
        return False
    grew = False
    for _ in range(rounds):
        com = centre_of_mass(pieces)
        polygon = base_polygon(pieces)
        if polygon is None or bool(inside_convex_polygon(com[None, :2], polygon, -margin)[0]):
            break
        pieces = _footed(pieces, com, margin)
        grew = True
    if not grew:
        return False
    single = obj.visual is obj.collision[0] and len(obj.collision) == 1
    obj.collision = pieces
    if single:
        obj.visual = pieces[0]
    obj.size = np.ptp(np.vstack([p.vertices for p in obj.collision]), axis=0)
    obj.notes.append("its hidden underside completed down to the support under its centre of mass (it stood still)")
    return True


def _footed(pieces: list[trimesh.Trimesh], com: np.ndarray, margin: float) -> list[trimesh.Trimesh]:
    """``pieces`` with the lowest one nearest ``com`` grown down to an octagonal foot about it whose
    sides lie ``FOOT_SLACK * margin`` from it."""
    z0 = float(min(p.vertices[:, 2].min() for p in pieces))
    lowest = [float(np.linalg.norm(p.vertices[p.vertices[:, 2] <= z0 + BASE_BAND, :2].mean(axis=0) - com[:2]))
              if (p.vertices[:, 2] <= z0 + BASE_BAND).any() else np.inf for p in pieces]
    k = int(np.argmin(lowest))
    t = np.linspace(0.0, 2 * np.pi, 8, endpoint=False)
    reach = FOOT_SLACK * margin / np.cos(np.pi / 8)
    foot = np.column_stack([com[0] + reach * np.cos(t), com[1] + reach * np.sin(t), np.full(8, z0)])
    grown = trimesh_hull(np.vstack([pieces[k].vertices, foot]))
    return [grown if i == k else p for i, p in enumerate(pieces)]
