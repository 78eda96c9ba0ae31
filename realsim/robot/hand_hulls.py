"""A cheap first test of a hand pose: the convex collision geoms rigid with the tcp (the hand, the
open fingers, the last link) against the other objects' surface samples, before any IK.

MuJoCo collides a mesh geom as its convex hull, so a neighbour's surface point deeper than
:data:`GRAZE` inside one of these hulls (in the tcp frame of the pose) is a contact the full check
would find at any arm posture: such a pose can be dropped without solving for one. Each hull is
swept back along the approach over the pre-grasp distance (the sweep of a convex body along a
segment is the hull of its two ends), covering the straight final approach as well. A point
missed between samples only leaves the pose to the full check.
"""

from __future__ import annotations

from collections.abc import Iterable

import mujoco
import numpy as np
from scipy.spatial import ConvexHull

from realsim.robot.world import GRAZE

__all__ = ["HandHulls"]

_BOX_CORNERS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], float)


def _geom_vertices(model: mujoco.MjModel, g: int) -> np.ndarray | None:
    """Vertices of geom ``g`` in its own frame whose hull lies within the geom (meshes, boxes); None for other shapes."""
    if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH:
        m = model.geom_dataid[g]
        return np.asarray(model.mesh_vert[model.mesh_vertadr[m]: model.mesh_vertadr[m] + model.mesh_vertnum[m]], float)
    if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX:
        return _BOX_CORNERS * model.geom_size[g]
    return None


class HandHulls:
    """Hulls (halfspace equations, tcp frame) of the colliding geoms of ``bodies`` with the arm at
    ``qpos`` (the fingers open), each swept ``sweep`` m back along the tcp's approach axis (z)."""

    def __init__(self, model: mujoco.MjModel, qpos: np.ndarray, tcp_site: int, bodies: Iterable[int], sweep: float) -> None:
        data = mujoco.MjData(model)
        data.qpos[:] = qpos
        mujoco.mj_kinematics(model, data)
        p_tcp, r_tcp = data.site_xpos[tcp_site], data.site_xmat[tcp_site].reshape(3, 3)
        back = np.array([0.0, 0.0, -sweep])
        self.equations: list[np.ndarray] = []
        self.boxes: list[tuple[np.ndarray, np.ndarray]] = []  # each hull's bounds in the tcp frame: the faces are tested only within
        for g in range(model.ngeom):
            if int(model.geom_bodyid[g]) not in set(bodies) or not (model.geom_contype[g] or model.geom_conaffinity[g]):
                continue
            v = _geom_vertices(model, g)
            if v is None:
                continue
            world = v @ data.geom_xmat[g].reshape(3, 3).T + data.geom_xpos[g]
            local = (world - p_tcp) @ r_tcp
            swept = np.vstack([local, local + back])
            self.equations.append(ConvexHull(swept).equations)
            self.boxes.append((swept.min(axis=0), swept.max(axis=0)))
        order = np.argsort([-np.prod(hi - lo) for lo, hi in self.boxes])
        self.equations, self.boxes = [self.equations[i] for i in order], [self.boxes[i] for i in order]
        self.bounds = (np.min([b[0] for b in self.boxes], axis=0), np.max([b[1] for b in self.boxes], axis=0)) if self.boxes else (np.zeros(3), np.zeros(3))

    @property
    def reach(self) -> float:
        """No hull reaches further than this from the tcp (m)."""
        lo, hi = self.bounds
        return float(np.linalg.norm(np.maximum(np.abs(lo), np.abs(hi))))

    def touched(self, pos: np.ndarray, rot: np.ndarray, clouds: dict[str, np.ndarray]) -> set[str]:
        """The names of ``clouds`` (world surface samples per object) lying deeper than :data:`GRAZE`
        inside a hull with the tcp at (``pos``, ``rot``)."""
        names = [n for n in clouds if len(clouds[n])]
        if not names:
            return set()
        lo, hi = self.bounds
        out: set[str] = set()
        for name in names:
            local = (clouds[name] - pos) @ rot
            local = local[np.all((local > lo) & (local < hi), axis=1)]
            for eq, (b_lo, b_hi) in zip(self.equations, self.boxes, strict=True):  # the largest first: most hits end at once
                inside = local[np.all((local > b_lo) & (local < b_hi), axis=1)]
                if len(inside) and np.any((inside @ eq[:, :3].T + eq[:, 3]).max(axis=1) < -GRAZE):
                    out.add(name)
                    break
        return out
