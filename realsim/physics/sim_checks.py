"""Small MuJoCo experiments that check a prepared object behaves: drop on a table, ball in a cup."""

from __future__ import annotations

from typing import TYPE_CHECKING

import mujoco
import numpy as np
import trimesh

if TYPE_CHECKING:
    from realsim.assets.prepare import PreparedObject
    from realsim.physics.manifest import ObjectManifest


def _add_hulls(spec: mujoco.MjSpec, body, hulls: list[trimesh.Trimesh], prefix: str, friction=(1.0, 0.005, 0.0001), solref=(0.02, 1.0)) -> None:
    for i, h in enumerate(hulls):
        name = f"{prefix}_hull{i}"
        mesh = spec.add_mesh()
        mesh.name = name
        mesh.uservert = np.asarray(h.vertices, float).ravel().tolist()
        mesh.userface = np.asarray(h.faces, int).ravel().tolist()
        geom = body.add_geom()
        geom.type = mujoco.mjtGeom.mjGEOM_MESH
        geom.meshname = name
        geom.group = 3
        geom.friction = list(friction)
        geom.solref = list(solref)
        geom.condim = 4


def _base_spec(timestep: float = 0.002) -> mujoco.MjSpec:
    spec = mujoco.MjSpec()
    spec.option.timestep = timestep
    spec.option.gravity = [0, 0, -9.81]
    floor = spec.worldbody.add_geom()
    floor.type = mujoco.mjtGeom.mjGEOM_PLANE
    floor.size = [2, 2, 0.1]
    floor.friction = [0.8, 0.005, 0.0001]
    return spec


def _set_inertial(body, manifest: "ObjectManifest") -> None:
    body.explicitinertial = True
    body.mass = manifest.mass_kg
    body.ipos = list(manifest.com)
    body.fullinertia = manifest.fullinertia()


def drop_test(prepared: "PreparedObject", manifest: "ObjectManifest", height: float = 0.01, settle_s: float = 3.0) -> dict:
    """Drop the object (as oriented in its frame) from ``height`` onto a table; report how it rests.

    Returns sinking (m, deepest penetration of a hull vertex below the table), drift (m, xy motion
    during the last second), tilt (deg), max speed and whether the state stayed finite.
    """
    spec = _base_spec()
    body = spec.worldbody.add_body()
    body.name = "obj"
    body.pos = [0, 0, height]
    body.add_freejoint()
    _set_inertial(body, manifest)
    _add_hulls(spec, body, prepared.hulls, "obj", manifest.friction, manifest.solref)
    model = spec.compile()
    data = mujoco.MjData(model)
    verts = np.vstack([h.vertices for h in prepared.hulls])
    steps = int(settle_s / model.opt.timestep)
    mark = steps - int(1.0 / model.opt.timestep)
    max_speed, pos_mark = 0.0, None
    finite = True
    for k in range(steps):
        mujoco.mj_step(model, data)
        if not np.isfinite(data.qpos).all():
            finite = False
            break
        if k > int(0.3 / model.opt.timestep):
            max_speed = max(max_speed, float(np.linalg.norm(data.qvel[:3])))
        if k == mark:
            pos_mark = data.qpos[:3].copy()
    pos, quat = data.qpos[:3].copy(), data.qpos[3:7].copy()
    R = np.zeros(9)
    mujoco.mju_quat2Mat(R, quat)
    R = R.reshape(3, 3)
    world = verts @ R.T + pos
    tilt = float(np.degrees(np.arccos(np.clip(R[2, 2], -1, 1))))
    return {
        "finite": finite,
        "sinking": float(max(0.0, -world[:, 2].min())) if finite else float("inf"),
        "drift": float(np.linalg.norm((pos - pos_mark)[:2])) if finite and pos_mark is not None else float("inf"),
        "tilt_deg": tilt,
        "max_speed_after_impact": max_speed,
        "final_speed": float(np.linalg.norm(data.qvel[:3])) if finite else float("inf"),
    }


def _top_heights(mesh: trimesh.Trimesh, xy: np.ndarray) -> np.ndarray:
    """z of the highest surface above each xy (NaN where there is none): a vertical ray cast."""
    tri = mesh.triangles
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    v0, v1 = b[:, :2] - a[:, :2], c[:, :2] - a[:, :2]
    den = v0[:, 0] * v1[:, 1] - v1[:, 0] * v0[:, 1]
    ok = np.abs(den) > 1e-14
    a, b, c, v0, v1, den = a[ok], b[ok], c[ok], v0[ok], v1[ok], den[ok]
    out = np.full(len(xy), np.nan)
    for i, p in enumerate(xy):
        w = p - a[:, :2]
        u = (w[:, 0] * v1[:, 1] - v1[:, 0] * w[:, 1]) / den
        v = (v0[:, 0] * w[:, 1] - w[:, 0] * v0[:, 1]) / den
        hit = (u >= 0) & (v >= 0) & (u + v <= 1)
        if hit.any():
            zz = a[hit, 2] + u[hit] * (b[hit, 2] - a[hit, 2]) + v[hit] * (c[hit, 2] - a[hit, 2])
            out[i] = zz.max()
    return out


def cavity_point(prepared: "PreparedObject", grid: int = 25) -> tuple[np.ndarray, float] | None:
    """(xy above the deepest open cavity, cavity floor z) by casting rays down onto the solid."""
    solid = prepared.solid
    lo, hi = solid.bounds
    xs = np.linspace(lo[0], hi[0], grid)[1:-1]
    ys = np.linspace(lo[1], hi[1], grid)[1:-1]
    X, Y = np.meshgrid(xs, ys)
    origins = np.stack([X.ravel(), Y.ravel()], axis=1)
    z = _top_heights(solid, origins)
    if np.all(np.isnan(z)):
        return None
    deep = np.where(z < hi[2] - 0.3 * (hi[2] - lo[2]))[0]
    if len(deep) == 0:
        return None
    xy = np.median(origins[deep, :2], axis=0)
    return xy, float(np.nanmin(z[deep]))


def ball_in_container_test(prepared: "PreparedObject", radius: float = 0.015, settle_s: float = 2.0, mass: float = 0.01) -> dict:
    """Drop a ball into the container's cavity (container fixed on the table); does it stay in?"""
    spec = _base_spec()
    cont = spec.worldbody.add_body()
    cont.name = "container"
    _add_hulls(spec, cont, prepared.hulls, "c")
    found = cavity_point(prepared)
    top = float(prepared.size[2])
    xy = found[0] if found else np.zeros(2)
    ball = spec.worldbody.add_body()
    ball.name = "ball"
    ball.pos = [float(xy[0]), float(xy[1]), top + radius + 0.02]
    ball.add_freejoint()
    g = ball.add_geom()
    g.type = mujoco.mjtGeom.mjGEOM_SPHERE
    g.size = [radius, 0, 0]
    g.mass = mass
    model = spec.compile()
    data = mujoco.MjData(model)
    for _ in range(int(settle_s / model.opt.timestep)):
        mujoco.mj_step(model, data)
    p = data.qpos[-7:-4].copy()
    lo, hi = prepared.solid.bounds
    inside_xy = bool(np.all(p[:2] > lo[:2]) and np.all(p[:2] < hi[:2]))
    inside = bool(np.isfinite(p).all() and inside_xy and p[2] < top and p[2] > radius * 0.5 + 0.001)
    return {"inside": inside, "ball_pos": p.tolist(), "cavity_found": found is not None, "top": top}
