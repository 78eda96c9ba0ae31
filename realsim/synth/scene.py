"""Synthetic scenes of real YCB object scans on tables, counters and floors, with ground truth.

``make_scene(SceneSpec(...))`` builds a :class:`SynthScene` in the world frame (right-handed,
Z up, metres, floor top at z = 0): the support furniture as tessellated boxes, the YCB meshes
placed by seeded rejection sampling (one stacked pair and one touching pair on request), and
one merged triangle mesh whose faces carry what they belong to (``face_object``: object id or
0, ``face_part``: the mOSD-style part code). Everything is deterministic for a given spec.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import trimesh

from realsim.errors import InputError
from realsim.geometry import polygons_apart
from realsim.synth.meshes import box_mesh, load_ycb, raycaster
from realsim.synth.rest import PARAMS as REST
from realsim.synth.rest import base_holds, rest_rotation, stacked_rest, support_polygon_margin

# per-face part codes (the mOSD label convention for points: 1..9 furniture, objects 10 * id)
PART_SUPPORT_TOP = 1  # the upward-facing top surface of a table or counter
PART_SUPPORT_OTHER = 2  # legs, edges, sides and the underside of furniture
PART_FLOOR = 3  # the floor's top surface
PART_BACKGROUND = 4  # walls, the floor slab's sides and underside
LAYOUTS = ("table", "counter", "floor", "rooms")  # rooms: realsim.synth.rooms (several tables)
DEFAULT_OBJECTS = (
    "003_cracker_box", "005_tomato_soup_can", "006_mustard_bottle", "010_potted_meat_can", "011_banana",
    "019_pitcher_base", "021_bleach_cleanser", "024_bowl", "025_mug", "035_power_drill", "061_foam_brick",
    "077_rubiks_cube",
)
_PALETTE = np.array([
    [0.85, 0.20, 0.15], [0.15, 0.35, 0.85], [0.95, 0.80, 0.10], [0.20, 0.65, 0.30], [0.60, 0.25, 0.75],
    [0.95, 0.50, 0.10], [0.10, 0.70, 0.75], [0.80, 0.30, 0.55], [0.45, 0.30, 0.20], [0.30, 0.30, 0.35],
    [0.90, 0.90, 0.85], [0.55, 0.75, 0.15],
])
_CLEARANCE = 0.03  # gap between objects that are not meant to touch (m)
_LEVEL_DEG = 18.0  # a face whose normal is this close to up is level (part of a top something can stand on)
_SLIDE_TOLERANCE = 1e-5  # m: a body slid against another stops this close to it (they touch; no gap)
_STACK_BASE = "003_cracker_box"  # in drawn subsets with a stack: lying flat, it holds any small object
Furniture = list[tuple[trimesh.Trimesh, np.ndarray, np.ndarray]]  # (mesh, part per face, colour)


def ycb_root() -> Path:
    """Folder of the YCB google_16k scans: ``$REALSIM_YCB_ROOT``, else ``../shared/data/ycb_google16k``."""
    env = os.environ.get("REALSIM_YCB_ROOT")
    return Path(env) if env else Path(__file__).resolve().parents[3] / "shared" / "data" / "ycb_google16k"


@dataclass(frozen=True)
class SceneSpec:
    """What to build. ``objects``: YCB folder names (None: ``n_objects`` drawn from DEFAULT_OBJECTS)."""

    layout: str = "table"  # "table" | "counter" | "floor" | "rooms"
    objects: tuple[str, ...] | None = None
    n_objects: int = 4
    stacked: bool = True  # one object resting on another (a flat-topped base is chosen)
    touching: bool = True  # two objects side by side in contact
    seed: int = 0
    floor_size: tuple[float, float] = (3.0, 3.0)
    wall: bool | None = None  # a wall behind the support (None: for counters)


@dataclass(frozen=True)
class GtSupport:
    """A support surface: its upward-facing top at ``height``, an xy rectangle."""

    name: str  # "floor" | "table" | "counter"
    kind: str  # "floor" | "table"
    height: float
    center: tuple[float, float]
    size: tuple[float, float]
    yaw: float = 0.0
    thickness: float = 0.0


@dataclass
class GtObject:
    """One placed YCB object: id (1..K), the scan's name, its pose (object file frame -> world)."""

    id: int
    name: str
    mesh_file: Path
    pose: np.ndarray  # (4, 4)
    support: str  # name of the GtSupport under it (the bottom of its stack)
    resting_on: int | None = None  # object id it stands on
    touching: list[int] = field(default_factory=list)
    color: tuple[float, float, float] = (0.5, 0.5, 0.5)

    def mesh(self) -> trimesh.Trimesh:
        """The object's surface in the world frame."""
        m = load_ycb(str(self.mesh_file)).copy()
        m.apply_transform(self.pose)
        return m


@dataclass
class SynthScene:
    """A generated scene: supports, objects and the merged world mesh with per-face ground truth."""

    spec: SceneSpec
    supports: list[GtSupport]
    objects: list[GtObject]
    mesh: trimesh.Trimesh  # merged world mesh, vertex colours
    face_object: np.ndarray  # (F,) object id per face, 0 for furniture and background
    face_part: np.ndarray  # (F,) PART_* per face (objects: 10 * id)

    @property
    def bounds(self) -> np.ndarray:
        return self.mesh.bounds

    def primary_support(self) -> GtSupport:
        """The support the objects stand on (the floor for the floor layout; rooms: the main table)."""
        layout = self.spec.layout
        return next(s for s in self.supports if s.name == ("table" if layout == "rooms" else layout))

    def label_points(self, points: np.ndarray, max_distance: float = 0.015) -> np.ndarray:
        """Ground-truth object id (0 none) of world points: the object owning the nearest face, when
        that face is within ``max_distance`` (used to score any capture form, e.g. a fused mesh)."""
        import open3d as o3d

        rc = raycaster(self.mesh)
        pts = o3d.core.Tensor(np.ascontiguousarray(points, dtype=np.float32))
        res = rc.compute_closest_points(pts)
        prim = res["primitive_ids"].numpy().astype(np.int64)
        near = np.linalg.norm(res["points"].numpy() - points, axis=1) <= max_distance
        return np.where(near, self.face_object[prim], 0).astype(np.int32)


# ---------------------------------------------------------------------------------------------
# furniture


def box_parts(box: trimesh.Trimesh, top_z: float | None, top_part: int, other_part: int) -> np.ndarray:
    """Per-face part: ``top_part`` for the upward faces at ``top_z``, ``other_part`` elsewhere."""
    parts = np.full(len(box.faces), other_part, dtype=np.int32)
    if top_z is not None:
        up = (box.face_normals[:, 2] > 0.99) & (np.abs(box.triangles_center[:, 2] - top_z) < 1e-6)
        parts[up] = top_part
    return parts


def _furniture(spec: SceneSpec, rng: np.random.Generator) -> tuple[list[GtSupport], Furniture]:
    fx, fy = spec.floor_size
    slab = 0.05
    floor = box_mesh((fx, fy, slab), (0.0, 0.0, -slab / 2))
    supports = [GtSupport("floor", "floor", 0.0, (0.0, 0.0), (fx, fy), 0.0, slab)]
    parts = [(floor, box_parts(floor, 0.0, PART_FLOOR, PART_BACKGROUND), np.array([0.55, 0.52, 0.48]))]
    wood = np.array([0.72, 0.58, 0.42])
    if spec.layout == "table":
        h = round(float(rng.uniform(0.70, 0.78)), 4)
        sx, sy, t = round(float(rng.uniform(1.0, 1.3)), 3), round(float(rng.uniform(0.7, 0.9)), 3), 0.04
        supports.append(GtSupport("table", "table", h, (0.0, 0.0), (sx, sy), 0.0, t))
        parts += table_parts(supports[-1], wood)
    elif spec.layout == "counter":
        h = round(float(rng.uniform(0.86, 0.94)), 4)
        sx, sy = round(float(rng.uniform(1.4, 1.8)), 3), round(float(rng.uniform(0.55, 0.65)), 3)
        body = box_mesh((sx, sy, h), (0.0, 0.0, h / 2))
        parts.append((body, box_parts(body, h, PART_SUPPORT_TOP, PART_SUPPORT_OTHER), np.array([0.85, 0.85, 0.82])))
        supports.append(GtSupport("counter", "table", h, (0.0, 0.0), (sx, sy), 0.0, h))
    elif spec.layout != "floor":
        raise InputError(f"unknown layout {spec.layout!r}: use one of {', '.join(LAYOUTS)}")
    if spec.wall if spec.wall is not None else spec.layout == "counter":
        back = supports[-1].size[1] / 2 + 0.02 if spec.layout != "floor" else fy / 2 - 0.1
        wall = box_mesh((fx, 0.1, 1.6), (0.0, back + 0.05, 0.8))
        parts.append((wall, box_parts(wall, None, 0, PART_BACKGROUND), np.array([0.88, 0.86, 0.80])))
    return supports, parts


def table_parts(table: GtSupport, wood: np.ndarray) -> Furniture:
    """A table's top (its upper face PART_SUPPORT_TOP) and four legs 6 cm in from its corners."""
    (cx, cy), (sx, sy), h, t = table.center, table.size, table.height, table.thickness
    top = box_mesh((sx, sy, t), (cx, cy, h - t / 2))
    parts = [(top, box_parts(top, h, PART_SUPPORT_TOP, PART_SUPPORT_OTHER), wood)]
    for ix in (-1, 1):
        for iy in (-1, 1):
            leg = box_mesh((0.05, 0.05, h - t), (cx + ix * (sx / 2 - 0.06), cy + iy * (sy / 2 - 0.06), (h - t) / 2))
            parts.append((leg, box_parts(leg, None, 0, PART_SUPPORT_OTHER), wood * 0.7))
    return parts


# ---------------------------------------------------------------------------------------------
# objects


def _hull2d(points: np.ndarray) -> np.ndarray:
    from scipy.spatial import ConvexHull

    return points[ConvexHull(points).vertices]


def _lying(mesh: trimesh.Trimesh) -> np.ndarray:
    """Rotation laying a box-like object on its largest face (its smallest extent vertical)."""
    ext = mesh.extents
    axis = int(np.argmin(ext))
    rot = np.eye(4)
    if axis == 0:
        rot[:3, :3] = trimesh.transformations.rotation_matrix(math.pi / 2, [0, 1, 0])[:3, :3]
    elif axis == 1:
        rot[:3, :3] = trimesh.transformations.rotation_matrix(math.pi / 2, [1, 0, 0])[:3, :3]
    return rot


def _top_faces(mesh: trimesh.Trimesh) -> np.ndarray:
    """Mask of the faces of a world mesh's top: the connected level faces (normal within
    ``_LEVEL_DEG`` of up) holding the highest level face. A bulged or slightly tilted top is
    whole (a band under the highest point is only its highest corner), a ridge's is its crest."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    level = mesh.face_normals[:, 2] > math.cos(math.radians(_LEVEL_DEG))
    if not level.any():
        return level
    pairs = mesh.face_adjacency[level[mesh.face_adjacency].all(axis=1)]
    n = len(mesh.faces)
    _, comp = connected_components(coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n)), directed=False)
    highest = int(np.flatnonzero(level)[np.argmax(mesh.triangles_center[level, 2])])
    return level & (comp == comp[highest])


def _flat_top(mesh: trimesh.Trimesh) -> float:
    """Area of the mesh's top (:func:`_top_faces`): how well something can stand on it."""
    return float(mesh.area_faces[_top_faces(mesh)].sum())


def _posed(mesh: trimesh.Trimesh, base_rot: np.ndarray, yaw: float, xy: np.ndarray, z: float) -> np.ndarray:
    """Pose putting the rotated mesh's xy-bounds centre at ``xy`` and its lowest point at ``z``."""
    rz = trimesh.transformations.rotation_matrix(yaw, [0, 0, 1])
    rot = rz @ base_rot
    v = mesh.vertices @ rot[:3, :3].T
    centre = (v[:, :2].min(axis=0) + v[:, :2].max(axis=0)) / 2
    pose = rot.copy()
    pose[:3, 3] = [xy[0] - centre[0], xy[1] - centre[1], z - v[:, 2].min()]
    return pose


def _transformed(mesh: trimesh.Trimesh, pose: np.ndarray) -> np.ndarray:
    return mesh.vertices @ pose[:3, :3].T + pose[:3, 3]


def _drop_height(vertices: np.ndarray, below: list[trimesh.Trimesh]) -> float:
    """How far ``vertices`` must rise so none is under the surface of ``below`` (ray cast down)."""
    import open3d as o3d

    rc = o3d.t.geometry.RaycastingScene()
    for m in below:
        rc.add_triangles(o3d.core.Tensor(m.vertices.astype(np.float32)), o3d.core.Tensor(m.faces.astype(np.uint32)))
    top = max(float(m.bounds[1, 2]) for m in below) + 1.0
    rays = np.zeros((len(vertices), 6), dtype=np.float32)
    rays[:, :2] = vertices[:, :2]
    rays[:, 2] = top
    rays[:, 5] = -1.0
    t = rc.cast_rays(o3d.core.Tensor(rays))["t_hit"].numpy()
    hit = np.isfinite(t)
    if not hit.any():
        return 0.0
    return float(np.max((top - t[hit]) - vertices[hit, 2]))


def _slide_into_contact(mesh_b: trimesh.Trimesh, pose_b: np.ndarray, mesh_a_world: trimesh.Trimesh, direction: np.ndarray) -> np.ndarray:
    """Move B along the horizontal ``direction`` until it touches A (within ``_SLIDE_TOLERANCE``)."""
    import open3d as o3d

    rc = o3d.t.geometry.RaycastingScene()
    rc.add_triangles(o3d.core.Tensor(mesh_a_world.vertices.astype(np.float32)), o3d.core.Tensor(mesh_a_world.faces.astype(np.uint32)))
    pose = pose_b.copy()
    for _ in range(40):
        v = _transformed(mesh_b, pose).astype(np.float32)
        gap = float(rc.compute_distance(o3d.core.Tensor(v)).numpy().min())
        if gap < _SLIDE_TOLERANCE:
            break
        pose[:3, 3] += direction * gap
    return pose


def _region(spec: SceneSpec, support: GtSupport) -> tuple[np.ndarray, np.ndarray]:
    """xy box (lo, hi) where object footprints must lie."""
    if spec.layout == "floor":
        half = np.array([0.6, 0.45])
        return -half, half
    half = np.array(support.size) / 2 - 0.06
    return np.array(support.center) - half, np.array(support.center) + half


def _place_objects(spec: SceneSpec, names: list[str], support: GtSupport, furniture: list[trimesh.Trimesh],
                   rng: np.random.Generator) -> list[GtObject] | None:
    root = ycb_root()
    files = {n: str(root / n / "textured.obj") for n in names}
    meshes = {n: load_ycb(files[n]) for n in names}
    base_rot = {n: rest_rotation(files[n], np.eye(4)) for n in names}  # as each scan rests on a flat support
    order = list(names)
    lo, hi = _region(spec, support)
    stack_pair: tuple[str, str] | None = None
    if spec.stacked and len(names) >= 2:
        lied = {n: rest_rotation(files[n], _lying(meshes[n])) for n in names}
        flat = {n: _flat_top(trimesh.Trimesh(_transformed(meshes[n], lied[n]), meshes[n].faces, process=False)) for n in names}
        base = max(names, key=lambda n: (flat[n], n))
        base_rot[base] = lied[base]
        fits = [n for n in names if n != base and max(meshes[n].extents[:2]) < 0.8 * max(meshes[base].extents)]
        if fits:
            top = min(fits, key=lambda n: (float(np.prod(meshes[n].extents[:2])), n))
            stack_pair = (base, top)
            order = [base] + [n for n in names if n not in stack_pair] + [top]
    touch_pair: tuple[str, str] | None = None
    if spec.touching:
        free = [n for n in order if stack_pair is None or n not in stack_pair]
        if len(free) >= 2:
            touch_pair = (free[0], free[1])
    placed: list[GtObject] = []
    footprints: list[np.ndarray] = []
    world_meshes: list[trimesh.Trimesh] = []
    colors = _PALETTE[rng.permutation(len(_PALETTE))]
    for k, name in enumerate(order):
        mesh = meshes[name]
        file = root / name / "textured.obj"
        ok = False
        stack_tries = REST.stack_tries if stack_pair and name == stack_pair[1] else 0
        set_downs = REST.stack_set_downs if stack_tries else 0
        for _ in range(200):
            yaw = float(rng.uniform(-math.pi, math.pi))
            if stack_tries and set_downs:
                base_obj = next(o for o in placed if o.name == stack_pair[0])  # type: ignore[index]
                set_downs -= 1
                pose = _stacked_pose(mesh, base_rot[name], yaw, world_meshes[placed.index(base_obj)], support.height, rng, name, base_obj.name)
                if pose is None:
                    continue
                stack_tries -= 1
                if isinstance(pose, bool):  # simulated and not at rest there
                    continue
                rest_on, touching = base_obj.id, []
            else:
                xy = rng.uniform(lo, hi)
                pose = _posed(mesh, base_rot[name], yaw, xy, support.height)
                rest_on, touching = None, []
                if touch_pair and name == touch_pair[1]:
                    a = next(o for o in placed if o.name == touch_pair[0])
                    a_world = world_meshes[placed.index(a)]
                    centre_a = a_world.bounds.mean(axis=0)[:2]
                    ang = rng.uniform(-math.pi, math.pi)
                    direction = np.array([math.cos(ang), math.sin(ang)])
                    start = centre_a + direction * 0.5
                    pose = _posed(mesh, base_rot[name], yaw, start, support.height)
                    pose = _slide_into_contact(mesh, pose, a_world, -np.r_[direction, 0.0])
                    touching = [a.id]
                v = _transformed(mesh, pose)
                poly = _hull2d(v[:, :2])
                if not (np.all(poly >= lo) and np.all(poly <= hi)):
                    continue
                others = [f for f, o in zip(footprints, placed) if not touching or o.id not in touching]
                if not all(polygons_apart(poly, q, _CLEARANCE) for q in others):
                    continue
            ok = True
            break
        if not ok or not isinstance(pose, np.ndarray):
            return None
        obj = GtObject(k + 1, name, file, pose, support.name, rest_on, touching, tuple(float(c) for c in colors[k % len(colors)]))
        for t in touching:
            placed[t - 1].touching.append(obj.id)
        placed.append(obj)
        world_meshes.append(obj.mesh())
        footprints.append(_hull2d(world_meshes[-1].vertices[:, :2]))
    return placed


def _stacked_pose(mesh: trimesh.Trimesh, rot: np.ndarray, yaw: float, base_world: trimesh.Trimesh, floor_z: float,
                  rng: np.random.Generator, name: str, base_name: str) -> np.ndarray | bool | None:
    """A seeded pose of ``mesh`` resting on ``base_world``: set down over the base's top (its
    footprint 1 cm inside the top's), settled in MuJoCo and put back exactly on the base's surface, kept when the base holds it.
    None: the footprint does not fit the top (no simulation run); False: simulated, not at rest there."""
    from realsim.geometry import inside_convex_polygon

    top_z = float(base_world.bounds[1, 2])
    top = _top_faces(base_world)
    area = base_world.area_faces[top]
    c = (base_world.triangles_center[top, :2] * area[:, None]).sum(axis=0) / area.sum() + rng.uniform(-0.01, 0.01, size=2)
    pose = _posed(mesh, rot, yaw, c, top_z)
    v = _transformed(mesh, pose)
    base_poly = _hull2d(base_world.vertices[np.unique(base_world.faces[top]), :2])
    if not inside_convex_polygon(_hull2d(v[:, :2]), base_poly if _ccw(base_poly) else base_poly[::-1], 0.01).all():
        return None
    pose[2, 3] += _drop_height(v, [base_world])
    motion = stacked_rest(trimesh.Trimesh(_transformed(mesh, pose), mesh.faces, process=False), base_world, floor_z)
    if motion is None:
        return False
    pose = motion @ pose
    pose[2, 3] += _drop_height(_transformed(mesh, pose), [base_world])  # on the surface: the simulation's sink taken out
    placed = trimesh.Trimesh(_transformed(mesh, pose), mesh.faces, process=False)
    masses = (typical_mass(base_name, base_world), typical_mass(name, placed))
    if support_polygon_margin(placed, base_world) < REST.stack_margin or not base_holds(base_world, placed, floor_z, masses):
        return False
    return pose


def typical_mass(name: str, mesh: trimesh.Trimesh) -> float:
    """A scan's typical mass (kg): its category's in the size table (YCB's own weights for the
    categories it covers), else its hull's volume at ``REST.density``."""
    from realsim.physics.size_table import lookup

    match = lookup(name.split("_", 1)[1] if name[:3].isdigit() else name)
    return match.category.mass[1] if match is not None else float(mesh.convex_hull.volume * REST.density)


def _ccw(poly: np.ndarray) -> bool:
    x, y = poly[:, 0], poly[:, 1]
    return float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)) > 0


def make_scene(spec: SceneSpec = SceneSpec()) -> SynthScene:
    """Build the seeded scene: furniture, YCB objects placed on the primary support, merged mesh."""
    if spec.layout not in LAYOUTS:
        raise InputError(f"unknown layout {spec.layout!r}: use one of {', '.join(LAYOUTS)}")
    root = ycb_root()
    rng = np.random.default_rng([spec.seed, LAYOUTS.index(spec.layout)])
    if spec.objects is not None:
        names = list(spec.objects)
    else:
        pool = [n for n in DEFAULT_OBJECTS if not (spec.stacked and n == _STACK_BASE)]
        count = min(spec.n_objects, len(DEFAULT_OBJECTS)) - (1 if spec.stacked else 0)
        names = sorted(rng.choice(pool, size=count, replace=False).tolist() + ([_STACK_BASE] if spec.stacked else []))
    for n in names:
        if not (root / n / "textured.obj").is_file():
            raise InputError(f"{root / n}: no YCB scan textured.obj here (set REALSIM_YCB_ROOT)")
    if spec.layout == "rooms":
        from realsim.synth.rooms import make_rooms  # builds on this module's furniture and placement

        return make_rooms(spec, names, rng)
    supports, furniture = _furniture(spec, rng)
    support = supports[-1] if spec.layout != "floor" else supports[0]
    objects = place_on(spec, names, support, furniture, rng)
    return assemble(spec, supports, furniture, objects)


def place_on(spec: SceneSpec, names: list[str], support: GtSupport, furniture: Furniture,
             rng: np.random.Generator) -> list[GtObject]:
    """The named objects placed on ``support`` (30 seeded attempts), or InputError."""
    for _ in range(30):
        objects = _place_objects(spec, names, support, [m for m, _, _ in furniture], rng)
        if objects is not None:
            return objects
    raise InputError(f"could not place {len(names)} objects on the {support.name}; use fewer or smaller objects")


def assemble(spec: SceneSpec, supports: list[GtSupport], furniture: Furniture, objects: list[GtObject]) -> SynthScene:
    """The scene of this furniture and these objects: one merged, vertex-coloured mesh with the
    object id and part code of every face."""
    meshes, face_obj, face_part, colors = [], [], [], []
    for mesh, parts, color in furniture:
        meshes.append(mesh)
        face_obj.append(np.zeros(len(mesh.faces), dtype=np.int32))
        face_part.append(parts)
        colors.append(np.tile(color, (len(mesh.vertices), 1)))
    for obj in objects:
        m = obj.mesh()
        meshes.append(m)
        face_obj.append(np.full(len(m.faces), obj.id, dtype=np.int32))
        face_part.append(np.full(len(m.faces), 10 * obj.id, dtype=np.int32))
        shade = 0.85 + 0.15 * np.sin(m.vertices[:, 2] * 60.0)[:, None]  # bands, so texture is not flat
        colors.append(np.clip(np.asarray(obj.color) * shade, 0, 1))
    merged = trimesh.util.concatenate(meshes)
    rgba = np.hstack([np.vstack(colors), np.ones((len(merged.vertices), 1))])
    merged.visual = trimesh.visual.ColorVisuals(merged, vertex_colors=(rgba * 255).round().astype(np.uint8))
    return SynthScene(spec, supports, objects, merged, np.concatenate(face_obj), np.concatenate(face_part))
