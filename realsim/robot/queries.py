"""World queries: objects' surface points, surfaces below, contacts, zones, what is in the way."""

from __future__ import annotations

import mujoco
import numpy as np

from realsim.robot.arm import Arm

__all__ = ["WorldQueries", "box_centre", "box_centre_3d"]


def box_centre(pts: np.ndarray) -> np.ndarray:
    """xy centre of the points' bounding box."""
    centre: np.ndarray = (pts[:, :2].min(axis=0) + pts[:, :2].max(axis=0)) / 2
    return centre


def box_centre_3d(pts: np.ndarray) -> np.ndarray:
    """Centre of the points' bounding box: where goals measure an object."""
    centre: np.ndarray = (pts.min(axis=0) + pts.max(axis=0)) / 2
    return centre


class WorldQueries(Arm):
    """Reading the scene around the arm (ray casts and points from :class:`SceneGeometry`, contacts)."""

    def object_names(self) -> list[str]:
        """Names of the free bodies (the movable objects), in model order."""
        return self.geometry.object_names()

    def object_pose(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """Live (position, quaternion w,x,y,z) of a body."""
        b = self._body(name)
        return self.data.xpos[b].copy(), self.data.xquat[b].copy()

    def _body(self, name: str) -> int:
        """Body id of ``name``."""
        return self.geometry.body(name)

    def _subtree(self, b: int) -> list[int]:
        """Body ``b`` and the bodies attached below it."""
        return self.geometry.subtree(b)

    def _world_points(self, b: int) -> np.ndarray:
        """World-frame surface samples of body ``b``'s own geoms."""
        return self.geometry.body_points(b)

    def object_points(self, name: str) -> np.ndarray:
        """World-frame surface samples of an object's collision geometry (live pose, attached parts included)."""
        return self.geometry.points(name)

    def object_normals(self, name: str) -> np.ndarray:
        """World-frame outward normals matching :meth:`object_points`."""
        return self.geometry.normals(name)

    def surface_below(self, xy: np.ndarray, z_from: float, exclude: str | None = None) -> float:
        """z of the first collision surface below (xy, z_from), ignoring the robot and ``exclude``."""
        return self.geometry.surface_below(xy, z_from, exclude)

    def _tallest(self, skip: str | None = None) -> float:
        """z of the highest object point (``skip`` left out)."""
        return self.geometry.tallest(skip, default=float(self.base_pos[2]))

    def _contacts_with(self, name: str) -> set[int]:
        """Robot finger bodies touching object ``name`` (or a part attached to it)."""
        parts = set(self._subtree(self._body(name)))
        out: set[int] = set()
        for i in range(self.data.ncon):
            c = self.data.contact[i]
            b1, b2 = self.model.geom_bodyid[c.geom1], self.model.geom_bodyid[c.geom2]
            if b1 in parts and b2 in self.finger_bodies:
                out.add(int(b2))
            elif b2 in parts and b1 in self.finger_bodies:
                out.add(int(b1))
        return out

    def holding(self, name: str) -> bool:
        """Both fingers touch ``name`` and the gripper is not closed on nothing."""
        return len(self._contacts_with(name)) == 2 and self.gripper_opening() > self.params.arm.holding_min_opening

    def _held_below(self) -> float:
        """How far the held object reaches below the tcp (0 when nothing is held)."""
        if not self.held:
            return 0.0
        pos, _ = self.tcp_pose()
        return max(0.0, float(pos[2] - self.object_points(self.held)[:, 2].min()))

    def _owner_of_xy(self, obj: str, xy: np.ndarray, above: float) -> str:
        """The object (not ``obj``) with a surface point nearest ``xy``."""
        best = min(((float(np.min(np.linalg.norm(p[p[:, 2] > above, :2] - xy, axis=1))) if (p[:, 2] > above).any() else np.inf, n)
                    for n in self.object_names() if n != obj for p in [self.object_points(n)]), default=(np.inf, "another object"))
        return best[1]

    def _others(self, obj: str, skip: frozenset[str] | set[str] = frozenset(), above: float = -np.inf) -> np.ndarray:
        """xy of every other object's surface points higher than ``above`` (what a release must clear)."""
        pts = [self.object_points(n) for n in self.object_names() if n != obj and n not in skip]
        pts = [p[p[:, 2] > above, :2] for p in pts]
        return np.vstack(pts) if pts else np.zeros((0, 2))

    def _zone(self, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """(centre xy, half extents, xy rotation) of a zone geom or site named ``name``, else None."""
        m, d = self.model, self.data
        for kind in (mujoco.mjtObj.mjOBJ_GEOM, mujoco.mjtObj.mjOBJ_SITE):
            i = mujoco.mj_name2id(m, kind, name)
            if i >= 0:
                if kind == mujoco.mjtObj.mjOBJ_GEOM:
                    pos, mat, size = d.geom_xpos[i], d.geom_xmat[i].reshape(3, 3), m.geom_size[i]
                else:
                    pos, mat, size = d.site_xpos[i], d.site_xmat[i].reshape(3, 3), m.site_size[i]
                return pos[:2].copy(), np.asarray(size[:2], float).copy(), mat[:2, :2].copy()
        return None

    def _centre_xy(self, obj: str) -> np.ndarray:
        """xy centre of ``obj``'s bounding box."""
        return box_centre(self.object_points(obj))

    def _up(self, obj: str) -> np.ndarray:
        """The world direction of ``obj``'s body z axis."""
        mujoco.mj_kinematics(self.model, self.data)
        up: np.ndarray = self.data.xmat[self._body(obj)].reshape(3, 3)[:, 2].copy()
        return up
