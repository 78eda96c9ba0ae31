"""The bundled tabletop example's layout: a table, five household primitives on it (seeded,
apart, inside the table's edges) and a tripod camera looking at them. No rendering here."""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from realsim.geometry import polygons_apart

LABEL_NONE = 0
LABEL_TABLE_TOP = 1
LABEL_TABLE_OTHER = 2
LABEL_FLOOR = 3
MAX_RANGE = 3.0  # metres of depth beyond which a pixel is NaN (Kinect-like)

TABLE_HEIGHT = 0.75
TABLE_SIZE = (1.2, 0.8)
TABLE_THICKNESS = 0.04
LEG_SIZE = 0.05
FOVY_DEG = 45.0  # Kinect v1: 43-45 deg vertical, 57-58 deg horizontal at 4:3
TOP_SURFACE_TOL = 0.003  # table pixels further than this from the top plane are "other"
MIN_VISIBLE_PIXELS = 400
_CLEARANCE = 0.03  # minimum gap between objects that are not meant to touch
_MARGIN = 0.06  # minimum distance from an object footprint to the table edge


@dataclass(frozen=True)
class _Kind:
    name: str
    shape: str  # "box" | "cylinder"
    size: tuple[float, float, float]  # extents x, y, z (cylinder: diameter, diameter, height)
    rgba: tuple[float, float, float, float]


# Household sizes, distinct colours. Order = object k = 1..5 (ids 2..6).
_KINDS = (
    _Kind("cereal_box", "box", (0.19, 0.07, 0.28), (0.85, 0.18, 0.12, 1.0)),
    _Kind("can", "cylinder", (0.066, 0.066, 0.122), (0.12, 0.32, 0.85, 1.0)),
    _Kind("shoe_box", "box", (0.30, 0.18, 0.11), (0.15, 0.62, 0.25, 1.0)),
    _Kind("block", "box", (0.08, 0.06, 0.05), (0.62, 0.22, 0.75, 1.0)),
    _Kind("mug", "cylinder", (0.082, 0.082, 0.095), (0.95, 0.78, 0.10, 1.0)),
)


@dataclass(frozen=True)
class PlacedObject:
    """One object of the layout, in the world frame (Z up)."""

    id: int  # = pcd label // 10
    name: str
    shape: str
    size: tuple[float, float, float]  # extents in the object frame
    position: tuple[float, float, float]  # centre of the base
    yaw: float  # rad, about world Z
    rgba: tuple[float, float, float, float]
    resting_on: int | None  # object id, or None for the table

    @property
    def pcd_label(self) -> int:
        return 10 * self.id


@dataclass(frozen=True)
class CameraPose:
    """A pinhole camera: position and the optical-frame axes (+x right, +y down, +z forward)."""

    position: np.ndarray  # (3,)
    rotation: np.ndarray  # (3, 3) columns = optical x, y, z axes in the world frame
    fovy_deg: float

    def optical_to_world(self) -> np.ndarray:
        t = np.eye(4)
        t[:3, :3] = self.rotation
        t[:3, 3] = self.position
        return t

    def mujoco_quat(self) -> np.ndarray:
        """MuJoCo camera orientation (w, x, y, z): the camera looks along its -z, +y up."""
        r_mj = self.rotation @ np.diag([1.0, -1.0, -1.0])
        q = np.zeros(4)
        mujoco.mju_mat2Quat(q, np.ascontiguousarray(r_mj).reshape(-1))
        return q


@dataclass(frozen=True)
class TabletopLayout:
    """A generated tabletop: the table, the objects and their true poses (the ground truth of a synthetic capture)."""

    seed: int
    table_height: float
    table_size: tuple[float, float]
    objects: tuple[PlacedObject, ...]
    camera: CameraPose


# --------------------------------------------------------------------------------------------
# layout


def _footprint(shape: str, size: tuple[float, float, float], xy: np.ndarray,
               yaw: float) -> np.ndarray:
    """Convex footprint polygon (K, 2) of an upright box or cylinder."""
    if shape == "box":
        hx, hy = size[0] / 2, size[1] / 2
        local = np.array([[-hx, -hy], [hx, -hy], [hx, hy], [-hx, hy]])
    else:
        ang = np.linspace(0.0, 2 * np.pi, 16, endpoint=False)
        local = (size[0] / 2) * np.stack([np.cos(ang), np.sin(ang)], axis=1)
    c, s = math.cos(yaw), math.sin(yaw)
    rot = np.array([[c, -s], [s, c]])
    return local @ rot.T + xy


def _on_table(poly: np.ndarray, margin: float, y_range: tuple[float, float] | None = None) -> bool:
    hx, hy = TABLE_SIZE[0] / 2 - margin, TABLE_SIZE[1] / 2 - margin
    ok = bool(np.all(np.abs(poly[:, 0]) <= hx) and np.all(np.abs(poly[:, 1]) <= hy))
    if ok and y_range is not None:
        ok = bool(np.all((poly[:, 1] >= y_range[0]) & (poly[:, 1] <= y_range[1])))
    return ok


def _jitter(rng: np.random.Generator, kind: _Kind) -> tuple[float, float, float]:
    f = rng.uniform(0.92, 1.08, size=3)
    if kind.shape == "cylinder":
        f[1] = f[0]
    x, y, z = (round(float(v), 4) for v in np.asarray(kind.size) * f)
    return (x, y, z)


def _sample_camera(rng: np.random.Generator) -> CameraPose:
    """A tripod-mounted Kinect in front of the table (at -y), looking down at its middle."""
    distance = rng.uniform(1.0, 1.15)
    pitch = math.radians(rng.uniform(38.0, 46.0))
    yaw = math.radians(rng.uniform(-8.0, 8.0))  # 0: looking along +y
    target = np.array([rng.uniform(-0.05, 0.05), rng.uniform(-0.02, 0.06), TABLE_HEIGHT])
    fwd = np.array([math.sin(yaw) * math.cos(pitch), math.cos(yaw) * math.cos(pitch),
                    -math.sin(pitch)])
    pos = target - distance * fwd
    right = np.cross(fwd, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    down = np.cross(fwd, right)
    rot = np.stack([right, down, fwd], axis=1)
    return CameraPose(position=pos, rotation=rot, fovy_deg=FOVY_DEG)


def sample_layout(seed: int = 0, attempt: int = 0) -> TabletopLayout:
    """The seeded table layout: five objects, a stacked pair and a touching pair."""
    rng = np.random.default_rng([seed, attempt])
    camera = _sample_camera(rng)
    for _ in range(500):
        objs = _try_layout(rng)
        if objs is not None:
            return TabletopLayout(seed, TABLE_HEIGHT, TABLE_SIZE, objs, camera)
    raise RuntimeError("could not place the objects on the table")  # pragma: no cover


def _pos(xy: np.ndarray, z: float) -> tuple[float, float, float]:
    return (float(xy[0]), float(xy[1]), float(z))


def _try_layout(rng: np.random.Generator) -> tuple[PlacedObject, ...] | None:
    cereal, can, shoe, block, mug = _KINDS
    placed: list[PlacedObject] = []
    polys: list[np.ndarray] = []
    z0 = TABLE_HEIGHT

    def free(poly: np.ndarray, ignore: tuple[int, ...] = ()) -> bool:
        return all(polygons_apart(poly, q, _CLEARANCE) for i, q in enumerate(polys)
                   if i not in ignore)

    # 1. cereal box, towards the back of the table (+y) so it hides little
    s1 = _jitter(rng, cereal)
    xy1 = np.array([rng.uniform(-0.4, 0.4), rng.uniform(0.02, 0.22)])
    yaw1 = rng.uniform(-0.5, 0.5)
    p1 = _footprint("box", s1, xy1, yaw1)
    if not _on_table(p1, _MARGIN):
        return None
    placed.append(PlacedObject(2, cereal.name, "box", s1, _pos(xy1, z0), float(yaw1),
                               cereal.rgba, None))
    polys.append(p1)

    # 2. can touching the cereal box's narrow (local +-x) side
    s2 = _jitter(rng, can)
    side = 1.0 if rng.uniform() < 0.5 else -1.0
    along = rng.uniform(-0.3, 0.3) * s1[1]
    c, s = math.cos(yaw1), math.sin(yaw1)
    local = np.array([side * (s1[0] / 2 + s2[0] / 2), along])
    xy2 = xy1 + np.array([[c, -s], [s, c]]) @ local
    p2 = _footprint("cylinder", s2, xy2, 0.0)
    if not _on_table(p2, _MARGIN):
        return None
    placed.append(PlacedObject(3, can.name, "cylinder", s2, _pos(xy2, z0), 0.0, can.rgba, None))
    polys.append(p2)

    # 3. shoe box, towards the front
    s3 = _jitter(rng, shoe)
    xy3 = np.array([rng.uniform(-0.4, 0.4), rng.uniform(-0.22, 0.05)])
    yaw3 = rng.uniform(-np.pi / 2, np.pi / 2)
    p3 = _footprint("box", s3, xy3, yaw3)
    if not (_on_table(p3, _MARGIN) and free(p3)):
        return None
    placed.append(PlacedObject(4, shoe.name, "box", s3, _pos(xy3, z0), float(yaw3),
                               shoe.rgba, None))
    polys.append(p3)

    # 4. block stacked on the shoe box, fully supported by its top
    s4 = _jitter(rng, block)
    yaw4 = yaw3 + rng.uniform(-0.6, 0.6)
    for _ in range(50):
        off = rng.uniform(-0.25, 0.25, size=2) * np.array(s3[:2])
        c3, s3n = math.cos(yaw3), math.sin(yaw3)
        xy4 = xy3 + np.array([[c3, -s3n], [s3n, c3]]) @ off
        p4 = _footprint("box", s4, xy4, yaw4)
        local4 = (p4 - xy3) @ np.array([[c3, -s3n], [s3n, c3]])
        if np.all(np.abs(local4) <= np.array(s3[:2]) / 2 - 0.01):
            break
    else:
        return None
    placed.append(PlacedObject(5, block.name, "box", s4, _pos(xy4, z0 + s3[2]), float(yaw4),
                               block.rgba, 4))
    # (not added to the footprint list: it lies inside the shoe box's footprint)

    # 5. mug anywhere free
    s5 = _jitter(rng, mug)
    xy5 = np.array([rng.uniform(-0.45, 0.45), rng.uniform(-0.25, 0.2)])
    p5 = _footprint("cylinder", s5, xy5, 0.0)
    if not (_on_table(p5, _MARGIN) and free(p5)):
        return None
    placed.append(PlacedObject(6, mug.name, "cylinder", s5, _pos(xy5, z0), 0.0, mug.rgba, None))
    return tuple(placed)


# --------------------------------------------------------------------------------------------
# MuJoCo scene
