"""What the robot and the goal checks read from a MuJoCo scene: object surfaces and contacts.

:class:`SceneGeometry` works on any compiled model (with or without the Panda): the movable
objects are the free bodies, an object is its body and every body attached below it (a hinged
lid, a drawer), its surface is sampled from its collision geoms once (body frame, cached) and
moved with the live pose, and :meth:`SceneGeometry.touching` says what an object rests against
("world" for static geometry such as the table, another object's name, "robot").
"""

from __future__ import annotations

from collections.abc import Iterable

import mujoco
import numpy as np

from realsim.robot.grasps import body_surface

COLLISION_GROUPS = np.array([0, 0, 0, 1, 0, 0], dtype=np.uint8)
WORLD = "world"
ROBOT = "robot"
CONTACT_DISTANCE = 0.002  # m: geoms closer than this touch
GRAZE = 0.002  # m: a planned arm pose may graze an object this deep (its collision hull's own error), no more


class SceneGeometry:
    """Live object geometry of ``model``/``data``; ``robot_bodies`` are reported as "robot"."""

    def __init__(self, model: mujoco.MjModel, data: mujoco.MjData, robot_bodies: Iterable[int] = ()):
        self.model, self.data = model, data
        self.robot_bodies = set(robot_bodies)
        self._surfaces: dict[int, tuple[np.ndarray, np.ndarray]] = {}
        self._scratch: mujoco.MjData | None = None
        root = model.body_rootid
        self._root_name = {b: (WORLD if root[b] == 0 else model.body(int(root[b])).name) for b in range(model.nbody)}

    # --- objects ------------------------------------------------------------------------------
    def object_names(self) -> list[str]:
        """Names of the free bodies (the movable objects), in model order."""
        m = self.model
        return [m.body(m.jnt_bodyid[j]).name for j in range(m.njnt) if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]

    def body(self, name: str) -> int:
        try:
            return self.model.body(name).id
        except KeyError:
            raise KeyError(f"no body named '{name}'; objects: {', '.join(self.object_names())}") from None

    def subtree(self, b: int) -> list[int]:
        """Body ``b`` and the bodies attached below it: one object to the hand."""
        out = [b]
        for c in range(b + 1, self.model.nbody):  # depth-first order: children follow parents
            if self.model.body_parentid[c] in out:
                out.append(c)
        return out

    def surface(self, b: int) -> tuple[np.ndarray, np.ndarray]:
        """Body-frame surface samples and outward normals of body ``b``'s collision geoms."""
        if b not in self._surfaces:
            self._surfaces[b] = body_surface(self.model, b)
        return self._surfaces[b]

    def body_points(self, b: int) -> np.ndarray:
        return self.surface(b)[0] @ self.data.xmat[b].reshape(3, 3).T + self.data.xpos[b]

    def points(self, name: str) -> np.ndarray:
        """World-frame surface samples of an object (live pose, attached parts included)."""
        return np.vstack([self.body_points(b) for b in self.subtree(self.body(name))])

    def normals(self, name: str) -> np.ndarray:
        """World-frame outward normals matching :meth:`points`."""
        return np.vstack([self.surface(b)[1] @ self.data.xmat[b].reshape(3, 3).T for b in self.subtree(self.body(name))])

    def owner(self, body: int) -> str:
        """What a body belongs to: "robot", "world" (static geometry) or the object's root body name."""
        if body in self.robot_bodies:
            return ROBOT
        return self._root_name[body]

    def touching(self, name: str) -> set[str]:
        """Owners of every geom in contact with object ``name`` (see :meth:`owner`)."""
        parts = set(self.subtree(self.body(name)))
        out: set[str] = set()
        d = self._collide()  # on a scratch copy: MuJoCo computes no contacts for sleeping bodies
        for i in range(d.ncon):
            c = d.contact[i]
            if c.dist > CONTACT_DISTANCE:
                continue
            b1, b2 = int(self.model.geom_bodyid[c.geom1]), int(self.model.geom_bodyid[c.geom2])
            if b1 in parts and b2 not in parts:
                out.add(self.owner(b2))
            elif b2 in parts and b1 not in parts:
                out.add(self.owner(b1))
        return out

    def _scratch_data(self) -> mujoco.MjData:
        if self._scratch is None:
            self._scratch = mujoco.MjData(self.model)
        return self._scratch

    def _collide(self) -> mujoco.MjData:
        """The live state's contacts, computed on a scratch copy (every body awake)."""
        d = self._scratch_data()
        d.qpos[:] = self.data.qpos
        mujoco.mj_kinematics(self.model, d)
        mujoco.mj_collision(self.model, d)
        return d

    # --- free space ---------------------------------------------------------------------------
    def surface_below(self, xy: np.ndarray, z_from: float, exclude: str | None = None, static_only: bool = False) -> float:
        """z of the first collision surface below (xy, z_from), ignoring the robot and ``exclude``
        (and, with ``static_only``, every movable object: the table or floor under them)."""
        exclude_body = self.body(exclude) if exclude else -1
        hits = [self._ray_down(np.array([xy[0] + dx, xy[1] + dy, z_from]), exclude_body, static_only)
                for dx, dy in ((0, 0), (0.01, 0), (-0.01, 0), (0, 0.01), (0, -0.01))]
        best = max(hits)
        return float(best) if np.isfinite(best) else 0.0

    def surfaces_below(self, xys: np.ndarray, z_from: float, exclude: str | None = None) -> np.ndarray:
        """z of the first collision surface straight below each of ``xys`` from ``z_from``, one ray
        each, ignoring the robot and ``exclude``; -inf where there is none."""
        exclude_body = self.body(exclude) if exclude else -1
        return np.array([self._ray_down(np.array([x, y, z_from]), exclude_body, False) for x, y in np.asarray(xys)[:, :2]])

    def _ray_down(self, start: np.ndarray, exclude_body: int, static_only: bool) -> float:
        """z where a ray straight down from ``start`` first meets a collision geom that is not the
        robot's (nor a movable object's, with ``static_only``); -inf when it meets none."""
        geomid = np.zeros(1, np.int32)
        for _ in range(4):
            d = mujoco.mj_ray(self.model, self.data, start, np.array([0, 0, -1.0]), COLLISION_GROUPS, 1, exclude_body, geomid)
            if d < 0:
                return -np.inf
            hit = int(self.model.geom_bodyid[geomid[0]])
            if hit in self.robot_bodies or (static_only and self.owner(hit) != WORLD):
                start = start - np.array([0, 0, d + 1e-4])
                continue
            return float(start[2] - d)
        return -np.inf

    def robot_hits(self, qadr: np.ndarray, q_arm: np.ndarray, ignore: Iterable[str] = (), hand_may_touch: Iterable[str] = (),
                   hand_bodies: Iterable[int] = (), shifted: dict[str, np.ndarray] | None = None,
                   carried: dict[str, tuple[np.ndarray, np.ndarray]] | None = None, world_bodies: Iterable[int] = ()) -> set[str]:
        """Objects the robot would touch with its arm at joints ``q_arm`` (everything else as now):
        a kinematic check on a scratch copy of the state, nothing moves. ``ignore``: objects that
        may touch any link (the held one); ``hand_may_touch``: objects only the hand and fingers
        (``hand_bodies``) may touch (what is being pushed); ``shifted``: objects displaced by an xyz
        offset (where a pushed object will be by then); ``carried``: objects moved with the hand to
        a world (position, quaternion) and checked like a link (the held object); ``world_bodies``:
        robot bodies whose contact with static geometry counts too (reported as "world")."""
        d = self._scratch_data()
        d.qpos[:] = self.data.qpos
        d.qpos[qadr] = q_arm
        for name, offset in (shifted or {}).items():
            adr = self.model.jnt_qposadr[self.model.body_jntadr[self.body(name)]]
            d.qpos[adr:adr + 3] += offset
        arm = set(self.robot_bodies)
        for name, (pos, quat) in (carried or {}).items():
            adr = self.model.jnt_qposadr[self.model.body_jntadr[self.body(name)]]
            d.qpos[adr:adr + 3], d.qpos[adr + 3:adr + 7] = pos, quat
            arm |= set(self.subtree(self.body(name)))
        mujoco.mj_kinematics(self.model, d)
        mujoco.mj_collision(self.model, d)
        ignore, hand_ok, hand, to_world = set(ignore) - set(carried or {}), set(hand_may_touch), set(hand_bodies), set(world_bodies)
        out: set[str] = set()
        for i in range(d.ncon):
            c = d.contact[i]
            if c.dist > -GRAZE:
                continue
            b1, b2 = int(self.model.geom_bodyid[c.geom1]), int(self.model.geom_bodyid[c.geom2])
            for rb, ob in ((b1, b2), (b2, b1)):
                if rb in arm and ob not in arm:
                    owner = self.owner(ob)
                    if (owner == WORLD and rb not in to_world) or owner in ignore or (owner in hand_ok and rb in hand):
                        continue
                    out.add(owner)
        return out

    def tallest(self, skip: str | None = None, default: float = 0.0) -> float:
        """Highest point of every object but ``skip``."""
        tops = [self.points(n)[:, 2].max() for n in self.object_names() if n != skip]
        return float(max(tops)) if tops else default
