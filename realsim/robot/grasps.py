"""Grasp candidates from an object's collision geometry.

The object's collision hulls are sampled into a surface point cloud (world frame). Candidates:

- top-down grasps with the closing axis along the principal axes of the object's footprint
  (and the diagonals), at a depth below the top the fingers can reach;
- side grasps approaching horizontally from the robot, closing across the object;
- rim grasps for open containers (mugs, bowls): top-down on the wall, closing radially.

A candidate is kept only when everything between the finger pads' sweep fits in the hand's
opening (80 mm minus a margin). Candidates are ranked by a score preferring a comfortable width,
a grasp point near the object's centre and a top-down approach.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np
import trimesh

from realsim.robot.ik import mat_to_quat
from realsim.robot.model import GRIPPER_MAX_OPENING

MAX_WIDTH = GRIPPER_MAX_OPENING - 0.008  # widest graspable cross-section (m)
MAX_WIDTH_FLAT = GRIPPER_MAX_OPENING - 0.004  # between two flat parallel faces, approached from above (m)
COS_FLAT = float(np.cos(np.radians(8.0)))  # "flat and parallel": contact normals within 8 degrees
FINGER_HALF_WIDTH = 0.012  # half the finger's extent across the closing axis (m)
FINGER_BELOW_TCP = 0.011  # fingertip bottom below the tcp (m)
PALM_BEHIND_TCP = 0.045  # palm / hand body this far behind the tcp along the approach (m)
RIM_DEPTH = 0.03  # tcp this far below the rim: about 2 cm of pad on the wall
RIM_CAVITY_GAP = 0.005  # an empty radial gap this wide inside the wall means an open cavity (m)
RIM_MAX_WALL = 0.025  # the wall band between the pads, including its curvature across the pads (m)
RIM_MIN_WALLS = 6  # of the 8 directions that must find a thin wall around a cavity
RIM_SCORE = 1.1  # an open container is held by its wall: a pinch across it squeezes two thin walls
DOWN = np.array([0.0, 0.0, -1.0])  # the approach of top-down grasps
COS_FRICTION_CONE = float(np.cos(np.radians(35.0)))  # pad contact normals within 35 degrees of the closing axis


@dataclass
class GraspCandidate:
    """A tcp pose to close the hand at."""

    kind: str  # "top" | "side" | "rim"
    pos: np.ndarray  # (3,) tcp position, world
    rot: np.ndarray  # (3, 3) tcp orientation, world: columns x, y (closing axis), z (approach)
    width: float  # object width between the fingers (m)
    score: float

    @property
    def quat(self) -> np.ndarray:
        return mat_to_quat(self.rot)

    @property
    def approach(self) -> np.ndarray:
        return self.rot[:, 2].copy()


def frame_from(approach: np.ndarray, closing: np.ndarray) -> np.ndarray:
    """Rotation with z = approach and y = closing (orthogonalized), x = y cross z."""
    z = approach / np.linalg.norm(approach)
    y = closing - z * (closing @ z)
    y /= np.linalg.norm(y)
    return np.column_stack([np.cross(y, z), y, z])


def rotate_about(axis: np.ndarray, angle: float) -> np.ndarray:
    axis = axis / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def body_surface(model: mujoco.MjModel, body_id: int, count: int = 4000) -> tuple[np.ndarray, np.ndarray]:
    """Surface samples and their outward unit normals for a body's colliding geoms, body frame."""
    pts, nrm = [], []
    geoms = [g for g in range(model.ngeom) if model.geom_bodyid[g] == body_id and (model.geom_contype[g] or model.geom_conaffinity[g])]
    for g in geoms:
        t = model.geom_type[g]
        size = model.geom_size[g]
        if t == mujoco.mjtGeom.mjGEOM_MESH:
            m = model.geom_dataid[g]
            va, vn = model.mesh_vertadr[m], model.mesh_vertnum[m]
            fa, fn = model.mesh_faceadr[m], model.mesh_facenum[m]
            mesh = trimesh.Trimesh(model.mesh_vert[va : va + vn], model.mesh_face[fa : fa + fn], process=False)
            mesh.fix_normals()
        elif t == mujoco.mjtGeom.mjGEOM_BOX:
            mesh = trimesh.creation.box(extents=2 * size)
        elif t == mujoco.mjtGeom.mjGEOM_CYLINDER:
            mesh = trimesh.creation.cylinder(radius=size[0], height=2 * size[1], sections=32)
        elif t == mujoco.mjtGeom.mjGEOM_SPHERE:
            mesh = trimesh.creation.icosphere(subdivisions=2, radius=size[0])
        elif t == mujoco.mjtGeom.mjGEOM_CAPSULE:
            mesh = trimesh.creation.capsule(height=2 * size[1], radius=size[0])
        else:
            aabb = model.geom_aabb[g]
            mesh = trimesh.creation.box(extents=2 * aabb[3:], transform=trimesh.transformations.translation_matrix(aabb[:3]))
        n = max(200, int(count / max(len(geoms), 1)))
        samples, faces = trimesh.sample.sample_surface(mesh, n, seed=0)
        samples = np.vstack([samples, mesh.vertices])
        normals = np.vstack([mesh.face_normals[faces], mesh.vertex_normals])
        mat = np.zeros(9)
        mujoco.mju_quat2Mat(mat, model.geom_quat[g])
        rot = mat.reshape(3, 3)
        pts.append(samples @ rot.T + model.geom_pos[g])
        nrm.append(normals @ rot.T)
    if not pts:
        return np.zeros((0, 3)), np.zeros((0, 3))
    return np.vstack(pts), np.vstack(nrm)


def antipodal(normals: np.ndarray | None, between: np.ndarray, proj_c: np.ndarray, closing: np.ndarray, approach: np.ndarray | None,
              cos_cone: float = COS_FRICTION_CONE, flat: bool = False, band: float = 0.004) -> bool:
    """Whether the surface the two pads would touch faces them (within the cone ``cos_cone``).

    The contact patches are the points of ``between`` within ``band`` of each extreme of
    ``proj_c`` (their coordinate along ``closing``). Normals are taken without their component
    along the fingers (``approach``): a shoulder sloping along the fingers is fine, an
    off-centre chord of a round body is not (the pads would slide off it); with ``approach`` None
    the whole normal counts (a handle: an edge sloping along the fingers is no pad contact). The patch's mean
    normal must lie in the cone; with ``flat``, nine in ten of its normals must (a flat face,
    not a curve). Without normals nothing can be checked (True).
    """
    if normals is None:
        return True
    c = proj_c[between]
    for extreme, sign in ((c.min(), -1.0), (c.max(), 1.0)):
        patch = np.flatnonzero(between)[np.abs(c - extreme) < band]
        n = normals[patch]
        if approach is not None:
            n = n - np.outer(n @ approach, approach)  # the part of each normal a pad can push against
        length = np.linalg.norm(n, axis=1)
        side = length > 0.5  # faces, not caps seen edge-on from the pad
        if not side.any():
            return False
        unit = n[side] / length[side, None]
        if flat:
            cosines = sign * (unit @ closing)
            if np.quantile(cosines, 0.1) < cos_cone:
                return False
            continue
        mean = unit.mean(axis=0)
        norm = np.linalg.norm(mean)
        if norm < 1e-9 or sign * float(mean @ closing) / norm < cos_cone:
            return False
    return True


def top_down_candidates(pts: np.ndarray, surface_z: float, prefer_yaw: float = 0.0, depth: float = 0.03, height_offset: float = 0.0,
                        normals: np.ndarray | None = None) -> list[GraspCandidate]:
    """Top-down grasps closing along the footprint's principal axes and diagonals, at several
    slices across the object (so L-shaped or thin-bladed objects are pinched where they are thin).
    With ``normals``, only slices whose contact patches face the pads are kept."""
    xy = pts[:, :2]
    centre_xy = xy.mean(axis=0)
    dirs = np.pi * np.arange(36) / 36
    widths = [np.ptp(xy @ np.array([np.cos(a), np.sin(a)])) for a in dirs]
    phi0 = float(dirs[int(np.argmin(widths))])  # the footprint's narrowest direction (min-width, robust for squares)
    angles = [phi0, phi0 + np.pi / 2, phi0 + np.pi / 4, phi0 - np.pi / 4]
    out = []
    for i, phi in enumerate(angles):
        closing = np.array([np.cos(phi), np.sin(phi), 0.0])
        if np.cos(phi - prefer_yaw) < 0:  # the sign nearest the preferred yaw keeps the wrist centred
            closing = -closing
        across = np.array([-closing[1], closing[0], 0.0])
        proj_a = (xy - centre_xy) @ across[:2]
        proj_c = (xy - centre_xy) @ closing[:2]
        lo, hi = float(proj_a.min()), float(proj_a.max())
        for frac in (0.5, 0.35, 0.65, 0.2, 0.8):
            s_off = lo + frac * (hi - lo) if hi - lo > 2 * FINGER_HALF_WIDTH else 0.0
            slab = np.abs(proj_a - s_off) < FINGER_HALF_WIDTH
            if slab.sum() < 5:
                continue
            local_top = float(pts[slab, 2].max())
            grasp_z = max(local_top - min(depth, max((local_top - surface_z) / 2, 0.0)), surface_z + FINGER_BELOW_TCP + 0.004) + height_offset
            grasp_z = min(grasp_z, local_top - 0.004)
            between = slab & (pts[:, 2] >= grasp_z - FINGER_BELOW_TCP)
            if between.sum() < 3:
                continue
            c_lo, c_hi = float(proj_c[between].min()), float(proj_c[between].max())
            width = c_hi - c_lo
            flat_ok = normals is not None and width <= MAX_WIDTH_FLAT and antipodal(normals, between, proj_c, closing, DOWN, COS_FLAT, flat=True)
            if (width > MAX_WIDTH and not flat_ok) or not antipodal(normals, between, proj_c, closing, DOWN):
                continue
            mid_c = (c_lo + c_hi) / 2
            # the palm (about 0.2 m along the closing axis, 0.06 m across) must clear everything
            palm = (np.abs(proj_c - mid_c) < 0.11) & (np.abs(proj_a - s_off) < 0.035) & (pts[:, 2] > grasp_z + PALM_BEHIND_TCP - 0.005)
            if palm.any():
                continue
            centre = np.array([*(centre_xy + across[:2] * s_off + closing[:2] * mid_c), grasp_z])
            rot = frame_from(np.array([0.0, 0.0, -1.0]), closing)
            score = 1.0 - (0.05 * i if i < 2 else 0.25) - 4.0 * abs(s_off) - 4.0 * abs(mid_c) + 0.3 * (MAX_WIDTH - width) / MAX_WIDTH
            if width > MAX_WIDTH:
                score -= 0.3  # little room either side of the pads: a last resort
            out.append(GraspCandidate("top", centre, rot, width, score))
    return out


def side_candidates(pts: np.ndarray, surface_z: float, from_xy: np.ndarray, height_offset: float = 0.0,
                    normals: np.ndarray | None = None) -> list[GraspCandidate]:
    """Horizontal grasps approaching from ``from_xy`` (the robot base), for tall objects."""
    top = float(pts[:, 2].max())
    height = top - surface_z
    if height < 0.07:
        return []
    centre_xy = pts[:, :2].mean(axis=0)
    out = []
    for k, dz in enumerate((0.5, 0.35, 0.65)):
        z = surface_z + max(height * dz, 0.04) + height_offset
        if z > top - 0.01:
            continue
        approach = np.array([*(centre_xy - from_xy), 0.0])
        approach /= np.linalg.norm(approach)
        closing = np.array([-approach[1], approach[0], 0.0])
        centre = np.array([centre_xy[0], centre_xy[1], z])
        rel = pts - centre
        band = np.abs(rel[:, 2]) < FINGER_HALF_WIDTH
        if band.sum() < 3:
            continue
        along = rel[band] @ approach
        front = float(along.min())
        tcp_along = min(0.0, front + 0.04)
        tcp = centre + approach * tcp_along
        rel2 = pts - tcp
        m2 = (np.abs(rel2[:, 2]) < FINGER_HALF_WIDTH) & (rel2 @ approach > -0.01) & (rel2 @ approach < 0.06)
        if m2.sum() < 3:
            continue
        c = rel2[m2] @ closing
        width = float(c.max() - c.min())
        if width > MAX_WIDTH or not antipodal(normals, m2, rel2 @ closing, closing, approach):
            continue
        tcp = tcp + closing * (c.max() + c.min()) / 2
        rot = frame_from(approach, closing)
        out.append(GraspCandidate("side", tcp, rot, width, 0.6 - 0.05 * k + 0.3 * (MAX_WIDTH - width) / MAX_WIDTH))
    return out


def rim_candidates(pts: np.ndarray, surface_z: float, prefer_yaw: float = 0.0, height_offset: float = 0.0,
                   normals: np.ndarray | None = None) -> list[GraspCandidate]:
    """Top-down grasps on the wall of an open container, closing radially."""
    top = float(pts[:, 2].max())
    in_band = pts[:, 2] > top - 0.02
    if in_band.sum() < 10:
        return []
    centre = pts[in_band, :2].mean(axis=0)
    rel = pts[:, :2] - centre
    out, walls = [], 0
    for k in range(8):
        ang = prefer_yaw + np.pi + k * np.pi / 4
        r = np.array([np.cos(ang), np.sin(ang)])
        perp = np.array([-r[1], r[0]])
        radial_all = rel @ r
        sector = in_band & (np.abs(rel @ perp) < FINGER_HALF_WIDTH) & (radial_all > 0)
        if sector.sum() < 4:
            continue
        radial = np.sort(radial_all[sector])[::-1]  # from the outer surface inwards
        gaps = -np.diff(np.append(radial, 0.0))
        hollow = np.flatnonzero(gaps > RIM_CAVITY_GAP)
        if not len(hollow):
            continue  # the top is closed across (a lid, a solid): no wall to pinch
        outer, inner = float(radial[0]), float(radial[hollow[0]])
        thickness = outer - inner
        if thickness > RIM_MAX_WALL:
            continue
        walls += 1
        wall = sector & (radial_all >= inner - 1e-9)
        closing = np.array([*r, 0.0])
        if not antipodal(normals, wall, radial_all, closing, DOWN):
            continue
        mid = centre + r * (outer + inner) / 2
        z = max(top - RIM_DEPTH, surface_z + FINGER_BELOW_TCP + 0.004) + height_offset
        rot = frame_from(np.array([0.0, 0.0, -1.0]), closing)
        out.append(GraspCandidate("rim", np.array([mid[0], mid[1], z]), rot, thickness, RIM_SCORE - 0.01 * k))
    return out if walls >= RIM_MIN_WALLS else []  # a rim goes (almost) all the way round


def grasp_candidates(pts: np.ndarray, surface_z: float, base_xy: np.ndarray, prefer_yaw: float = 0.0, height_offset: float = 0.0,
                     normals: np.ndarray | None = None) -> list[GraspCandidate]:
    """Every candidate for an object's world-frame surface points (and outward normals), best first."""
    cands = top_down_candidates(pts, surface_z, prefer_yaw, height_offset=height_offset, normals=normals)
    cands += side_candidates(pts, surface_z, base_xy, height_offset=height_offset, normals=normals)
    cands += rim_candidates(pts, surface_z, prefer_yaw, height_offset=height_offset, normals=normals)
    cands.sort(key=lambda c: -c.score)
    return cands


def footprint_widths(pts: np.ndarray, n: int = 36) -> tuple[float, float]:
    """The object's horizontal footprint over ``n`` directions (m): its length across the narrowest
    direction's perpendicular, and its narrowest extent (a lying can: its length, its diameter)."""
    angles = np.pi * np.arange(2 * n) / (2 * n)
    dirs = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    proj = pts[:, :2] @ dirs.T
    widths = proj.max(axis=0) - proj.min(axis=0)
    k = int(np.argmin(widths[::2])) * 2  # the n directions narrowest_width has always used
    return float(widths[(k + n) % (2 * n)]), float(widths[k])


def narrowest_width(pts: np.ndarray, n: int = 36) -> float:
    """The object's narrowest horizontal extent over ``n`` directions (m)."""
    return footprint_widths(pts, n)[1]


PAD_RADIUS = 0.008  # m: effective radius of a finger pad's contact patch for twisting friction
PAD_DEPTH = 0.02  # m: length of the pads' contact along the fingers


def twist_check(cand: GraspCandidate, com: np.ndarray, mass: float, friction: float, force: float) -> tuple[bool, float, float]:
    """Statics of a pinch: (holds, gravity torque, what the pads resist about that axis), N m.

    Gravity's torque about the pinch point has three parts the pads must resist: about the closing
    axis (the object spins between the pads) they resist by twisting friction, about 2 * (2/3) *
    friction * force * :data:`PAD_RADIUS`; about the axis across the fingers (the object
    tilts in the pinch) by the pressure spread along the fingers, about force * :data:`PAD_DEPTH`
    / 2; about the approach axis (a sideways hand: the object turns across the pads) by the
    pressure spread across the fingers' width, about force * :data:`FINGER_HALF_WIDTH`. The worst
    of the three, relative to its capacity, is returned."""
    arm = np.asarray(com, float) - cand.pos
    tau = np.cross(arm, np.array([0.0, 0.0, -9.81 * mass]))
    parts = [(abs(float(tau @ cand.rot[:, 1])), 2.0 * (2.0 / 3.0) * friction * force * PAD_RADIUS),
             (abs(float(tau @ cand.rot[:, 0])), force * PAD_DEPTH / 2.0),
             (abs(float(tau @ cand.rot[:, 2])), force * FINGER_HALF_WIDTH)]
    need, can = max(parts, key=lambda p: p[0] / p[1])
    return need <= can, need, can
