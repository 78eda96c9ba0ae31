"""Bodies at rest, checked in MuJoCo: the orientation a scan rests in on a flat support, and
whether a body stacked on another stays where it was put.

A real capture shows a scene at rest, so the generator's truth must be one too. Each check is a
short, deterministic MuJoCo simulation of the true mesh's convex hull (exact for contact with a
plane; for a stacked body, its underside is what touches): on a plane for a body standing on
furniture, and on convex tiles of the base's upward-facing surface (ray cast from above, so its
curves are kept) for a stacked one. The simulation only decides the orientation and
whether the body stays; the caller then puts the body exactly on its support (no gap).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import mujoco
import numpy as np
import trimesh
from scipy.spatial.transform import Rotation

from realsim.synth.meshes import load_ycb, raycaster


@dataclass(frozen=True)
class RestParams:
    """How bodies are brought to rest and what counts as stable."""

    timestep: float = 0.004  # s
    settle_time: float = 1.0  # s of simulated time per check (and per extension while a body still moves)
    max_settle_time: float = 6.0  # s: a body still moving after this is not at rest
    friction: float = 0.5  # sliding friction of every contact (cardboard, plastic on wood)
    rolling_friction: float = 0.0005  # m: rolling resistance (condim 6), so round bodies come to rest as real ones do
    density: float = 500.0  # kg/m^3 of a body whose mass is not given (only shapes matter for its own rest)
    rest_speed: float = 0.005  # m/s (and rad/s): a body slower than this at the end is at rest
    stack_margin: float = 0.005  # m: a stacked body's centre of mass at least this far inside its contacts' polygon
    stack_min_lift: float = 0.01  # m: a stacked body whose lowest point ends lower than this over the table fell off
    surface_cell: float = 0.003  # m: grid spacing of the base's upward surface
    tile_size: float = 0.015  # m: the base's surface is this many metres across per convex tile
    max_hull_vertices: int = -1  # a body's hull in the simulation (MuJoCo's maxhullvert, -1: all)
    contact_tolerance: float = 0.0005  # m: vertices this close (vertically) to the other body touch it
    stack_tries: int = 8  # seeded placements simulated on the base before the body is put on the support instead
    stack_set_downs: int = 40  # seeded set-downs on the base (fitting its top or not) before the body goes on the support
    base_max_turn: float = 1.0  # degrees: a base turning more than this under the stacked body's weight does not hold it


PARAMS = RestParams()


def _hull_spec(spec: mujoco.MjSpec, hulls: list[trimesh.Trimesh], params: RestParams,
               masses: list[float] | None = None) -> mujoco.MjsBody:
    """A free body holding ``hulls`` (vertices in the body frame = world at the start), each of its
    mass in ``masses`` (kg) or of one density."""
    spec.option.timestep = params.timestep
    body = spec.worldbody.add_body(name="body")
    body.add_freejoint()
    for k, hull in enumerate(hulls):
        spec.add_mesh(name=f"hull{k}", uservert=hull.vertices.ravel().tolist(), userface=hull.faces.ravel().tolist(), maxhullvert=params.max_hull_vertices)
        geom = body.add_geom(type=mujoco.mjtGeom.mjGEOM_MESH, meshname=f"hull{k}", density=params.density,
                             friction=[params.friction, 0.005, params.rolling_friction], condim=6)
        if masses is not None:
            geom.mass = masses[k]
    return body


def _settle(spec: mujoco.MjSpec, params: RestParams) -> tuple[mujoco.MjModel, mujoco.MjData]:
    """Simulate ``settle_time``, then on in steps as long while the body still moves (faster than
    ``rest_speed`` at the end of a step, or it moved during it), up to ``max_settle_time``: a body
    rocking slowly on a round side is not at rest yet."""
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    steps = int(round(params.settle_time / params.timestep))
    mujoco.mj_step(model, data, steps)
    while data.time + params.settle_time <= params.max_settle_time + 1e-9:
        before = data.qpos.copy()
        mujoco.mj_step(model, data, steps)
        if np.abs(data.qvel).max() <= params.rest_speed and _moved(before, data.qpos) <= params.rest_speed * params.settle_time:
            break  # still at the end and where it was a step before (not at the turn of a rocking motion)
    mujoco.mj_forward(model, data)
    return model, data


def _moved(before: np.ndarray, after: np.ndarray) -> float:
    """How far a free body moved: its translation (m) or its turn (rad), the larger."""
    turn = Rotation.from_quat(np.roll(before[3:7], -1)).inv() * Rotation.from_quat(np.roll(after[3:7], -1))
    return float(max(np.linalg.norm(after[:3] - before[:3]), turn.magnitude()))


def _rotation_of(data: mujoco.MjData) -> np.ndarray:
    """The free body's rotation since the start (body frame = world frame at the start)."""
    w, x, y, z = data.qpos[3:7]
    return np.asarray(Rotation.from_quat([x, y, z, w]).as_matrix())


@functools.lru_cache(maxsize=128)
def _rest_rotation_cached(path: str, rot_bytes: bytes, params: RestParams) -> bytes:
    rot = np.frombuffer(rot_bytes).reshape(4, 4)
    mesh = load_ycb(path).copy()
    mesh.apply_transform(rot)
    hull = mesh.convex_hull.copy()
    hull.apply_translation(-hull.center_mass)
    hull.apply_translation([0.0, 0.0, -hull.bounds[0, 2]])  # lowest point on the plane z = 0
    spec = mujoco.MjSpec()
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[1.0, 1.0, 0.1], friction=[params.friction, 0.005, params.rolling_friction])
    _hull_spec(spec, [hull], params)
    _, data = _settle(spec, params)
    out = np.eye(4)
    out[:3, :3] = _rotation_of(data) @ rot[:3, :3]
    return out.tobytes()


def rest_rotation(path: str, rot: np.ndarray, params: RestParams = PARAMS) -> np.ndarray:
    """The rotation (4x4) the scan at ``path``, first turned by ``rot``, rests in on a flat support
    (its hull let fall from ``rot`` onto a plane). A body's rest does not depend on its yaw, so one
    simulation serves every placement (cached per scan and rotation)."""
    return np.frombuffer(_rest_rotation_cached(path, np.ascontiguousarray(rot, float).tobytes(), params)).reshape(4, 4).copy()


def _surface_tiles(spec: mujoco.MjSpec, base: trimesh.Trimesh, floor_z: float, params: RestParams) -> None:
    """``base``'s upward-facing surface (ray cast from above on a ``surface_cell`` grid) as static
    convex tiles, each the hull of its surface points and their feet on the support at ``floor_z``
    (so a dip narrower than a tile is bridged), over a plane at ``floor_z``."""
    import open3d as o3d

    friction = [params.friction, 0.005, params.rolling_friction]
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[0.0, 0.0, 0.1], pos=[0.0, 0.0, floor_z], friction=friction)
    lo, hi = base.bounds[0, :2], base.bounds[1, :2]
    n = np.ceil((hi - lo) / params.surface_cell).astype(int) + 1
    gx, gy = np.meshgrid(np.linspace(lo[0], hi[0], n[0]), np.linspace(lo[1], hi[1], n[1]), indexing="ij")
    top = float(base.bounds[1, 2]) + 1.0
    rays = np.zeros((gx.size, 6), np.float32)
    rays[:, 0], rays[:, 1], rays[:, 2], rays[:, 5] = gx.ravel(), gy.ravel(), top, -1.0
    t = raycaster(base).cast_rays(o3d.core.Tensor(rays))["t_hit"].numpy().reshape(gx.shape)
    per_tile = max(1, int(round(params.tile_size / params.surface_cell)))
    for i in range(0, n[0] - 1, per_tile):
        for j in range(0, n[1] - 1, per_tile):
            block = np.s_[i:i + per_tile + 1, j:j + per_tile + 1]  # neighbouring tiles share their edge
            hit = np.isfinite(t[block])
            if hit.sum() < 3:
                continue
            surface = np.column_stack([gx[block][hit], gy[block][hit], top - t[block][hit]])
            feet = surface.copy()
            feet[:, 2] = floor_z
            points = np.vstack([surface, feet])
            if np.ptp(points[:, 0]) < 1e-6 or np.ptp(points[:, 1]) < 1e-6:
                continue
            name = f"tile_{i}_{j}"
            spec.add_mesh(name=name, uservert=points.ravel().tolist())
            spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_MESH, meshname=name, friction=friction)


def support_margin(contacts_xy: np.ndarray, point_xy: np.ndarray, line_width: float) -> float:
    """How far ``point_xy`` lies inside the polygon of ``contacts_xy`` (negative: outside; no
    contacts: -inf). Contacts narrower than ``line_width`` across are a line (a round body lying
    on a flat: it rests, rolling is neutral), and the margin is along the line, the point within
    ``line_width`` / 2 of it."""
    if len(contacts_xy) == 0:
        return -np.inf
    centre = contacts_xy.mean(axis=0)
    _, _, axes = np.linalg.svd(contacts_xy - centre, full_matrices=False) if len(contacts_xy) > 1 else (0, 0, np.eye(2))
    local = (contacts_xy - centre) @ axes.T
    p = (point_xy - centre) @ axes.T
    if local[:, 1].max() - local[:, 1].min() < line_width:
        if abs(p[1]) > line_width / 2:
            return -np.inf
        return float(min(p[0] - local[:, 0].min(), local[:, 0].max() - p[0]))
    from scipy.spatial import ConvexHull

    hull = ConvexHull(contacts_xy)
    normals, offsets = hull.equations[:, :2], hull.equations[:, 2]  # n . p + d <= 0 inside, |n| = 1
    return float(-np.max(normals @ point_xy + offsets))


def stacked_rest(top: trimesh.Trimesh, base: trimesh.Trimesh, floor_z: float,
                 params: RestParams = PARAMS) -> np.ndarray | None:
    """Let ``top`` (a world mesh just touching ``base`` from above) settle on ``base`` (static,
    its upward surface; the support it stands on at ``floor_z``). The rigid motion (4x4) that
    brings ``top`` to its rest on ``base``, or None when it does not rest there: it fell off or
    still moves. (Whether it rests with margin: :func:`support_polygon_margin` on the exact pose.)"""
    hull = top.convex_hull.copy()
    com = hull.center_mass
    hull.apply_translation(-com)
    spec = mujoco.MjSpec()
    _surface_tiles(spec, base, floor_z, params)
    body = _hull_spec(spec, [hull], params)
    body.pos = com.tolist()
    model, data = _settle(spec, params)
    if np.abs(data.qvel).max() > params.rest_speed:
        return None
    motion = np.eye(4)
    motion[:3, :3] = _rotation_of(data)
    motion[:3, 3] = data.qpos[:3] - motion[:3, :3] @ com
    moved = top.vertices @ motion[:3, :3].T + motion[:3, 3]
    if moved[:, 2].min() < floor_z + params.stack_min_lift:
        return None
    return motion


def _heights_over(points: np.ndarray, surface: trimesh.Trimesh, down: bool) -> np.ndarray:
    """Height of each point over ``surface`` straight below it (``down``) or under it straight
    above (not ``down``); nan where the vertical line misses the surface."""
    import open3d as o3d

    rays = np.zeros((len(points), 6), np.float32)
    rays[:, :2] = points[:, :2]
    start = surface.bounds[1, 2] + 1.0 if down else surface.bounds[0, 2] - 1.0
    rays[:, 2], rays[:, 5] = start, -1.0 if down else 1.0
    t = raycaster(surface).cast_rays(o3d.core.Tensor(rays))["t_hit"].numpy().astype(float)
    hit = start - t if down else start + t
    return np.where(np.isfinite(t), points[:, 2] - hit if down else hit - points[:, 2], np.nan)


def support_polygon_margin(top: trimesh.Trimesh, base: trimesh.Trimesh, params: RestParams = PARAMS) -> float:
    """How far ``top``'s centre of mass (its hull's) lies inside the polygon of its contacts with
    ``base`` under it: the vertices of either within ``params.contact_tolerance`` of the closest
    approach between them (measured vertically)."""
    up = _heights_over(top.vertices, base, down=True)
    below = _heights_over(base.vertices, top, down=False)
    if np.isnan(up).all() and np.isnan(below).all():
        return -np.inf
    closest = np.nanmin(np.concatenate([up, below]))
    touching = np.vstack([top.vertices[up <= closest + params.contact_tolerance], base.vertices[below <= closest + params.contact_tolerance]])
    return support_margin(touching[:, :2], top.convex_hull.center_mass[:2], 2 * params.stack_margin)


def base_holds(base: trimesh.Trimesh, top: trimesh.Trimesh, floor_z: float, masses: tuple[float, float],
               params: RestParams = PARAMS) -> bool:
    """Whether ``base`` (a world mesh on the support at ``floor_z``) stays at rest with ``top`` resting
    on it: the two hulls (``masses`` kg: base, top) as one body let settle on the support, and the
    base turns at most ``params.base_max_turn`` degrees (a lying round body with the weight off its
    contact line rolls, one with a heavy load high over it rolls over; a box with it past its edge tips)."""
    hulls = [base.convex_hull.copy(), top.convex_hull.copy()]
    com = (hulls[0].center_mass * masses[0] + hulls[1].center_mass * masses[1]) / sum(masses)
    for hull in hulls:
        hull.apply_translation(-com)
    spec = mujoco.MjSpec()
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[0.0, 0.0, 0.1], pos=[0.0, 0.0, floor_z],
                            friction=[params.friction, 0.005, params.rolling_friction])
    _hull_spec(spec, hulls, params, list(masses)).pos = com.tolist()
    _, data = _settle(spec, params)
    turn = np.degrees(Rotation.from_matrix(_rotation_of(data)).magnitude())
    return bool(turn <= params.base_max_turn and np.abs(data.qvel).max() <= params.rest_speed)
