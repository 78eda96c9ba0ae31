"""A 3 cm ball dropped on fixed convex pieces standing on a floor plane (MuJoCo): where it rests."""

from __future__ import annotations

import mujoco
import numpy as np
import trimesh


def drop_ball(pieces: list[trimesh.Trimesh], start: np.ndarray, floor_z: float = 0.0, seconds: float = 3.0,
              radius: float = 0.015) -> np.ndarray:
    """The ball's centre after ``seconds`` of simulated time, released at rest from ``start`` above
    the ``pieces`` (world frame, fixed) on a plane at ``floor_z``."""
    spec = mujoco.MjSpec()
    spec.option.timestep = 0.002
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[1, 1, 0.1], pos=[0, 0, floor_z])
    for i, piece in enumerate(pieces):
        spec.add_mesh(name=f"p{i}", uservert=piece.vertices.ravel().tolist(), userface=piece.faces.ravel().tolist())
        spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_MESH, meshname=f"p{i}")
    ball = spec.worldbody.add_body(name="ball", pos=[float(x) for x in start])
    ball.add_freejoint()
    ball.add_geom(type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[radius, 0, 0], density=1000)
    model = spec.compile()
    data = mujoco.MjData(model)
    for _ in range(int(round(seconds / model.opt.timestep))):
        mujoco.mj_step(model, data)
    return np.array(data.body("ball").xpos)
