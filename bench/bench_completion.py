"""How well does completion recover what the camera could not see? (real YCB meshes, ground truth)

Scenes from :mod:`realsim.synth` (real YCB scans on a table, seeded layouts) are written as one
organized Kinect-like view, converted (no robot), and every ground-truth object is matched to the
converted object holding most of its pixels. Per object: volume IoU of the completed solid (at
its composed pose) with the true mesh (occupancy on a 2 mm grid), the oriented size error (sorted
extents of the oriented bounding boxes), whether it was found once, and the pixels where the
completed solid hides something the camera saw farther away (a ray through the pixel centre hits
the solid more than 1 cm before the captured depth: free space filled), its collision pieces, whether
the hand fits it in truth (narrowest width <= 76 mm) and the grasp planner finds a grasp on the
completed shape, and for the bowl, mug and pitcher whether a 3 cm ball dropped in stays inside. ``--all`` covers every
shared YCB object once per seed (three scenes of five, layouts table, counter, table); a scene the
generator cannot lay out (five objects too large for the table at that seed) is skipped and listed, and
an object the generator's camera could not frame wholly (``out_of_view``) is listed apart, not scored. Run:

    .venv/bin/python bench/bench_completion.py [--seeds 0 1 2] [--objects 5] [--all] [--baseline] [--keep out/completion]
        [--overrides '{"complete": {...}}'] [--where] [--settling]

``--settling`` also scores each completed solid at its completion pose (the body's pose in scene.xml,
before settling) and splits the IoU lost between the completed shape and the settling (sinking,
tilting, sliding to keyframe ``initial``).
"""

from __future__ import annotations

import argparse
import json
import tempfile
from pathlib import Path
from types import SimpleNamespace

import mujoco
import numpy as np
import open3d as o3d
import trimesh
from scipy.spatial import cKDTree
from scipy.spatial.transform import Rotation

from realsim.errors import InputError
from realsim.perception.pcd_io import read_pcd
from realsim.physics.sim_checks import ball_in_container_test
from realsim.pipeline import convert
from realsim.robot.grasps import narrowest_width, rim_candidates, side_candidates, top_down_candidates
from realsim.synth import SceneSpec, make_scene, write_organized_view, ycb_root

GRID = 0.002
FREE_SPACE_TOLERANCE = 0.01  # m: a solid this much in front of the captured depth fills seen free space


def occupancy(mesh: trimesh.Trimesh, points: np.ndarray) -> np.ndarray:
    """Inside test for a closed (or nearly closed) surface: Open3D's ray-parity occupancy."""
    scene = o3d.t.geometry.RaycastingScene()
    scene.add_triangles(o3d.core.Tensor(np.asarray(mesh.vertices, np.float32)), o3d.core.Tensor(np.asarray(mesh.faces, np.uint32)))
    return scene.compute_occupancy(o3d.core.Tensor(points.astype(np.float32))).numpy() > 0.5


def volume_iou(parts: list[trimesh.Trimesh], b: trimesh.Trimesh) -> float:
    """IoU of the union of convex ``parts`` with the solid bounded by ``b``."""
    return volume_overlap(parts, b)[0]


def volume_overlap(parts: list[trimesh.Trimesh], b: trimesh.Trimesh) -> tuple[float, float, float]:
    """IoU of the union of convex ``parts`` with the solid bounded by ``b``, the share of the parts'
    volume inside ``b`` (too much: below 1) and the share of ``b`` the parts cover (too little)."""
    a_lo, a_hi = np.min([p.bounds[0] for p in parts], axis=0), np.max([p.bounds[1] for p in parts], axis=0)
    origin = np.minimum(a_lo, b.bounds[0])  # one lattice for all counts; each count only over its own boxes
    n_a = int(np.count_nonzero(np.any([occupancy(p, g) for p in parts], axis=0))) if len(g := _lattice(origin, a_lo, a_hi)) else 0
    n_b = int(np.count_nonzero(occupancy(b, g))) if len(g := _lattice(origin, *b.bounds)) else 0
    g = _lattice(origin, np.maximum(a_lo, b.bounds[0]), np.minimum(a_hi, b.bounds[1]))  # both: only where the boxes overlap
    both = float(np.count_nonzero(np.any([occupancy(p, g) for p in parts], axis=0) & occupancy(b, g))) if len(g) else 0.0
    union = n_a + n_b - both
    if not union:
        return 0.0, 0.0, 0.0
    return both / union, both / max(1, n_a), both / max(1, n_b)


def _lattice(origin: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """The GRID cell centres of the lattice anchored at ``origin`` that lie in the box ``lo``-``hi``
    (the same cells as one grid over the union of the boxes: a completed shape far off its truth
    spans a large union, but each box is an object's)."""
    first = np.ceil((lo - origin) / GRID - 0.5).astype(np.int64)
    last = np.floor((hi - origin) / GRID - 0.5).astype(np.int64)
    if np.any(last < first):
        return np.zeros((0, 3))
    axes = [origin[i] + (np.arange(first[i], last[i] + 1) + 0.5) * GRID for i in range(3)]
    return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)


def hit_depth(hulls: list[trimesh.Trimesh], world_to_optical: np.ndarray, intrinsics: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
    """(H, W) depth at which the ray through each pixel centre first meets the solid (inf: never)."""
    scene = o3d.t.geometry.RaycastingScene()
    for h in hulls:
        v = h.vertices @ world_to_optical[:3, :3].T + world_to_optical[:3, 3]
        scene.add_triangles(o3d.core.Tensor(v.astype(np.float32)), o3d.core.Tensor(np.asarray(h.faces, np.uint32)))
    height, width = shape
    v, u = np.mgrid[0:height, 0:width]
    ray = np.stack([(u - intrinsics[0, 2]) / intrinsics[0, 0], (v - intrinsics[1, 2]) / intrinsics[1, 1], np.ones(u.shape)], axis=-1)
    rays = np.concatenate([np.zeros_like(ray), ray], axis=-1).reshape(-1, 6).astype(np.float32)
    return np.asarray(scene.cast_rays(o3d.core.Tensor(rays))["t_hit"].numpy().reshape(height, width))  # t along (x, y, 1) is the depth


def free_space_pixels(hulls: list[trimesh.Trimesh], world_to_optical: np.ndarray, intrinsics: np.ndarray,
                      depth: np.ndarray) -> int:
    """Pixels whose ray meets the solid more than FREE_SPACE_TOLERANCE before the captured depth."""
    z = hit_depth(hulls, world_to_optical, intrinsics, depth.shape)
    with np.errstate(invalid="ignore"):
        return int(np.count_nonzero(np.isfinite(z) & (z < depth - FREE_SPACE_TOLERANCE)))


def silhouette_off(hulls: list[trimesh.Trimesh], mine: np.ndarray, others: np.ndarray, depth: np.ndarray,
                   world_to_optical: np.ndarray, intrinsics: np.ndarray) -> tuple[float, float]:
    """How far the completed solid's silhouette falls short of the object's seen pixel mask ``mine``
    (H, W) and how far it overshoots it (onto pixels not hidden by a nearer object of ``others``), in
    pixels per pixel of the mask's silhouette edge (about the mean shortfall and overshoot per side,
    in pixels). An edge pixel beside another object's pixel nearer than its own depth by
    FREE_SPACE_TOLERANCE is that object's occluding contour, not the silhouette."""
    z = hit_depth(hulls, world_to_optical, intrinsics, mine.shape)
    hit = np.isfinite(z)
    far = np.nan_to_num(depth, nan=np.inf)
    occluded = np.zeros_like(mine)
    for axis in (0, 1):
        for shift in (-1, 1):
            near = np.roll(others, shift, axis) & (np.roll(far, shift, axis) < far - FREE_SPACE_TOLERANCE)
            occluded |= near
    inner = mine & np.roll(mine, 1, 0) & np.roll(mine, -1, 0) & np.roll(mine, 1, 1) & np.roll(mine, -1, 1)
    edge = max(1, int(np.count_nonzero(mine & ~inner & ~occluded)))
    with np.errstate(invalid="ignore"):
        hidden = others & (far < z)  # a nearer object's pixel: the solid may lie behind it
    return np.count_nonzero(mine & ~hit) / edge, np.count_nonzero(hit & ~mine & ~hidden) / edge


EDGE_PX = 1.5  # pixels: a cell projecting this near the edge of the object's seen mask is at its silhouette
WHERE = ("edge", "hidden", "occluded", "free", "beyond")


def where_off(parts: list[trimesh.Trimesh], truth: trimesh.Trimesh, mine: np.ndarray, others: np.ndarray, depth: np.ndarray,
              world_to_optical: np.ndarray, intrinsics: np.ndarray) -> dict[str, tuple[float, float]]:
    """Where the completed solid (union of convex ``parts``) misses the true one and where it exceeds it:
    per place, (missing, excess) in shares of the true volume, GRID cells classed by the pixel they
    project to (nearest pixel centre) in the capture: ``edge`` within EDGE_PX pixels of the edge of the
    object's seen pixel mask ``mine`` (H, W) and not on another object's pixel (the silhouette), ``hidden``
    inside the mask behind the seen surface, ``occluded`` behind another object's pixel (``others``),
    ``free`` nearer than the captured depth by FREE_SPACE_TOLERANCE (seen through; anywhere), ``beyond``
    elsewhere (background pixels away from the silhouette)."""
    from scipy.ndimage import distance_transform_edt

    lo = np.minimum(np.min([q.bounds[0] for q in parts], axis=0), truth.bounds[0])
    hi = np.maximum(np.max([q.bounds[1] for q in parts], axis=0), truth.bounds[1])
    g = _lattice(lo, lo, hi)
    a, b = np.any([occupancy(q, g) for q in parts], axis=0), occupancy(truth, g)
    opt = g @ world_to_optical[:3, :3].T + world_to_optical[:3, 3]
    height, width = depth.shape
    u = np.clip(np.rint(opt[:, 0] / opt[:, 2] * intrinsics[0, 0] + intrinsics[0, 2]).astype(np.int64), 0, width - 1)
    v = np.clip(np.rint(opt[:, 1] / opt[:, 2] * intrinsics[1, 1] + intrinsics[1, 2]).astype(np.int64), 0, height - 1)
    edge_distance = (distance_transform_edt(mine) + distance_transform_edt(~mine))[v, u]  # from the mask's edge, inside or out
    with np.errstate(invalid="ignore"):
        free = opt[:, 2] < np.nan_to_num(depth[v, u], nan=np.inf) - FREE_SPACE_TOLERANCE
    seen, other = mine[v, u], others[v, u]
    edge = ~free & ~other & (edge_distance <= EDGE_PX)
    place = {"free": free, "edge": edge, "hidden": ~free & ~edge & seen, "occluded": ~free & ~edge & other}
    place["beyond"] = ~np.any(list(place.values()), axis=0)
    n = max(1, int(np.count_nonzero(b)))
    return {k: (np.count_nonzero(b & ~a & place[k]) / n, np.count_nonzero(a & ~b & place[k]) / n) for k in WHERE}


F_TOLERANCE = 0.005  # m: surface F-score distance (fair to walls thinner than the 2 mm IoU grid and the sensor noise)
F_SAMPLES = 6000


def surface_f_score(parts: list[trimesh.Trimesh], b: trimesh.Trimesh) -> float:
    """F-score at F_TOLERANCE of the outer surface of the union of convex ``parts`` against the surface
    of ``b``: the harmonic mean of the share of each surface's samples within F_TOLERANCE of the other.
    A sample of a piece is on the outer surface unless the point 1 mm out along its normal lies inside
    another piece (faces shared by neighbouring pieces). Unlike volume IoU, a 1 mm wall completed 3 mm
    thick and well placed scores high."""
    own = []
    for i, p in enumerate(parts):
        pts, face = trimesh.sample.sample_surface(p, max(50, int(F_SAMPLES * p.area / sum(q.area for q in parts))), seed=i)
        out = pts + 0.001 * p.face_normals[face]
        inner = np.any([occupancy(q, out) for j, q in enumerate(parts) if j != i], axis=0) if len(parts) > 1 else np.zeros(len(pts), bool)
        own.append(pts[~inner])
    a = np.vstack(own)
    scene = o3d.t.geometry.RaycastingScene()
    scene.add_triangles(o3d.core.Tensor(np.asarray(b.vertices, np.float32)), o3d.core.Tensor(np.asarray(b.faces, np.uint32)))
    precision = float(np.mean(scene.compute_distance(o3d.core.Tensor(a.astype(np.float32))).numpy() <= F_TOLERANCE))
    truth = trimesh.sample.sample_surface(b, F_SAMPLES, seed=0)[0]
    recall = float(np.mean(cKDTree(a).query(truth)[0] <= F_TOLERANCE))
    return 2 * precision * recall / (precision + recall) if precision + recall > 0 else 0.0


def obb_extents(mesh: trimesh.Trimesh) -> np.ndarray:
    return np.sort(np.asarray(mesh.bounding_box_oriented.primitive.extents, float))[::-1]


HAND_FITS = 0.076  # m: narrowest true width the Panda hand closes on (the bar)


def declared_graspable(hulls: list[trimesh.Trimesh], surface_z: float, camera_xy: np.ndarray) -> bool:
    """Whether the robot's grasp planner finds a candidate on the completed shape (surface samples of
    its pieces): from above, from the side (the camera's side stands in for the robot's), or at a rim."""
    pts = np.vstack([trimesh.sample.sample_surface(h, 400, seed=0)[0] for h in hulls])
    return bool(top_down_candidates(pts, surface_z) or side_candidates(pts, surface_z, camera_xy) or rim_candidates(pts, surface_z))


CONTAINERS = {"024_bowl", "025_mug", "019_pitcher_base"}  # thin-walled: volume IoU of walls, reported apart
BASELINE = {"complete": {"carve": False, "containers": {"enabled": False}, "mirror_max_depth_share": 1e-6}}  # extrusion and cylinders only


def all_objects(seed: int) -> list[tuple[str, tuple[str, ...]]]:
    """Every shared YCB object once: three (layout, objects) scenes of five, shuffled by ``seed``."""
    names = sorted(p.name for p in ycb_root().iterdir() if (p / "textured.obj").is_file())
    names = [names[i] for i in np.random.default_rng([seed, 14]).permutation(len(names))]
    return [(layout, tuple(names[k::3])) for k, layout in enumerate(("table", "counter", "table"))]


def measure(seed: int, n_objects: int, root: Path, baseline: bool = False, layout: str = "table",
            objects: tuple[str, ...] | None = None, overrides: dict | None = None, where: bool = False,
            settling: bool = False) -> list[dict]:
    scene = make_scene(SceneSpec(layout=layout, objects=objects, n_objects=n_objects, stacked=True, touching=True, seed=seed))
    tag = f"{layout}{seed}_{'-'.join(o[:3] for o in objects or ())}"
    capture = root / f"seed{tag}"
    capture.mkdir(parents=True)
    form = write_organized_view(scene, capture / "view.pcd", seed=seed)
    out = root / f"out{tag}"
    stages: dict = {"robot": {"enabled": False}, **(BASELINE if baseline else {})}
    for stage, values in (overrides or {}).items():
        stages[stage] = {**stages.get(stage, {}), **values}
    convert(capture / "view.pcd", out, overrides=stages)
    record = json.loads((out / "scene.json").read_text())
    synth_to_realsim = np.asarray(record["capture"]["input_to_world"]) @ np.linalg.inv(np.asarray(form["capture_to_world"]))
    labels = np.load(out / "labels.npy")
    pcd = read_pcd(capture / "view.pcd")
    gt_ids = np.where(pcd.labels >= 10, pcd.labels // 10, 0)
    depth = pcd.points[:, 2].reshape(480, 640)
    world_to_optical = np.linalg.inv(np.asarray(record["capture"]["input_to_world"]))
    composed = mujoco.MjModel.from_xml_path(str(out / "scene.xml")) if settling else None
    rows = []
    for obj in scene.objects:
        if obj.name in form["out_of_view"]:  # the capture's fault, not the completion's
            rows.append({"seed": seed, "name": obj.name, "out_of_view": True})
            continue
        mine = labels[gt_ids == obj.id]
        found = np.unique(mine[mine > 0])
        counts = {int(k): int(np.count_nonzero(mine == k)) for k in found}
        row = {"seed": seed, "name": obj.name, "pixels": int(np.count_nonzero(gt_ids == obj.id)), "clusters": len([k for k, c in counts.items() if c > 0.1 * len(mine)])}
        if not counts:
            rows.append({**row, "iou": 0.0, "size_err_mm": float("nan")})
            continue
        best = max(counts, key=counts.get)
        rec = next(o for o in record["objects"] if o["id"] == best)
        hulls = [trimesh.load(out / "assets" / f"{rec['name']}_collision_{i}.stl") for i in range(64)
                 if (out / "assets" / f"{rec['name']}_collision_{i}.stl").is_file()]
        local = trimesh.util.concatenate(hulls)  # object frame: base at z = 0
        ball = (ball_in_container_test(SimpleNamespace(hulls=hulls, solid=local, size=local.extents))["inside"]  # type: ignore[arg-type]
                if obj.name in CONTAINERS else None)
        at_completion = _settling_split(hulls, composed.body(rec["name"]), rec, obj.mesh().apply_transform(synth_to_realsim)) if composed else {}
        pose = _pose(rec["position"], rec["quat_wxyz"])
        for h in hulls:
            h.apply_transform(pose)
        solid = trimesh.util.concatenate(hulls)
        truth = obj.mesh()
        truth.apply_transform(synth_to_realsim)  # the conversion levels and centres the scene its own way
        iou, inside, covered = volume_overlap(hulls, truth)
        rule = next((n for n in rec["notes"] if n.startswith("completed from")), "").split(" as a ")[-1]
        rows.append({**row, **at_completion, "iou": iou, "inside": inside, "covered": covered, "rule": _rule(rule), "f5": surface_f_score(hulls, truth), "size_err_mm": float(np.max(np.abs(obb_extents(solid) - obb_extents(truth))) * 1000),
                     "free_px": free_space_pixels(hulls, world_to_optical, form["intrinsics"], depth), "pieces": len(hulls),
                     "label": rec["label"], "hollow": any("open container" in n for n in rec["notes"]),
                     "ball": ball, "fits": narrowest_width(np.asarray(truth.vertices)) <= HAND_FITS,
                     "graspable": declared_graspable(hulls, float(solid.bounds[0][2]), np.linalg.inv(world_to_optical)[:2, 3]),
                     "silhouette": silhouette_off(hulls, (gt_ids == obj.id).reshape(depth.shape), ((gt_ids > 0) & (gt_ids != obj.id)).reshape(depth.shape),
                                                  depth, world_to_optical, form["intrinsics"]) if where else None,
                     "where": where_off(hulls, truth, (gt_ids == obj.id).reshape(depth.shape), ((gt_ids > 0) & (gt_ids != obj.id)).reshape(depth.shape),
                                        depth, world_to_optical, form["intrinsics"]) if where else None})
    return rows


def _pose(position, quat_wxyz) -> np.ndarray:
    """4x4 pose of a position and a (w, x, y, z) quaternion."""
    pose = np.eye(4)
    pose[:3, :3] = Rotation.from_quat(np.roll(np.asarray(quat_wxyz, float), -1)).as_matrix()
    pose[:3, 3] = position
    return pose


def _settling_split(hulls: list[trimesh.Trimesh], body, rec: dict, truth: trimesh.Trimesh) -> dict:
    """The completed solid scored at its completion pose (``body``: its scene.xml body, the pose it was
    composed at) and how settling moved it: the lowest point's drop (mm, + down), the sideways motion (mm)
    and the turn (degrees) from the completion pose to keyframe ``initial`` (``rec``), and the lowest
    point's height over the truth's before and after (mm)."""
    before, after = _pose(body.pos, body.quat), _pose(rec["position"], rec["quat_wxyz"])
    placed = [h.copy().apply_transform(before) for h in hulls]
    low0 = min(float(h.bounds[0][2]) for h in placed)
    low1 = min(float(h.copy().apply_transform(after).bounds[0][2]) for h in hulls)
    turn = Rotation.from_matrix(after[:3, :3] @ before[:3, :3].T).magnitude()
    low = float(truth.bounds[0][2])
    return {"iou0": volume_iou(placed, truth), "drop_mm": 1000 * (low0 - low1), "low0_mm": 1000 * (low0 - low), "low1_mm": 1000 * (low1 - low),
            "slide_mm": 1000 * float(np.linalg.norm(after[:2, 3] - before[:2, 3])), "turn_deg": float(np.degrees(turn))}


RULES = (("open container", "hollow"), ("solid of revolution", "revolved"), ("cylinder", "cylinder"), ("silhouette", "mirror"),
         ("crest", "crest"), ("tiles", "tiles"), ("slabs", "slabs"), ("bands", "bands"), ("underside", "under"))


def _rule(kind: str) -> str:
    """A short name of the completion rules named in a completion note (the shape's ``kind``)."""
    return "+".join(short for word, short in RULES if word in kind) or "hull"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", nargs="*", type=int, default=[0, 1, 2])
    parser.add_argument("--objects", type=int, default=5)
    parser.add_argument("--all", action="store_true", help="every shared YCB object once per seed (3 scenes of 5)")
    parser.add_argument("--baseline", action="store_true", help="without free-space carving, hollow containers and mirroring")
    parser.add_argument("--keep", type=Path, default=None, help="write the captures and outputs here (a new folder)")
    parser.add_argument("--overrides", type=json.loads, default=None, help="stage parameters as JSON, as realsim.convert takes them (an A/B in one tree)")
    parser.add_argument("--where", action="store_true", help="also where each completed solid misses and exceeds the truth (see where_off)")
    parser.add_argument("--settling", action="store_true", help="also the IoU at the completion pose, before settling (see _settling_split)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        root = args.keep or Path(tmp)
        runs = [(seed, layout, objects) for seed in args.seeds for layout, objects in (all_objects(seed) if args.all else [("table", None)])]
        rows, skipped = [], []
        for seed, layout, objects in runs:
            try:
                rows += measure(seed, args.objects, root, args.baseline, layout, objects, args.overrides, args.where, args.settling)
            except InputError as error:  # the generator could not lay the scene out: no capture to measure
                skipped.append(f"seed {seed} {layout} ({error})")
    unframed = [r for r in rows if r.get("out_of_view")]
    rows = [r for r in rows if not r.get("out_of_view")]
    print(f"{'seed':>4s} {'object':28s} {'pixels':>7s} {'found':>5s} {'IoU':>5s} {'in':>4s} {'cover':>5s} {'F@5mm':>5s} {'size err mm':>11s} {'free px':>7s} {'pieces':>6s} {'fits':>4s} {'grasp':>5s} {'ball':>4s}  name given")
    for r in rows:
        print(f"{r['seed']:4d} {r['name']:28s} {r['pixels']:7d} {r['clusters']:5d} {r['iou']:5.2f} {r.get('inside', 0.0):4.2f} {r.get('covered', 0.0):5.2f} {r.get('f5', 0.0):5.2f} {r['size_err_mm']:11.1f} {r.get('free_px', 0):7d} {r.get('pieces', 0):6d} {'yes' if r.get('fits') else 'no':>4s} {'yes' if r.get('graspable') else 'no':>5s} {'-' if r.get('ball') is None else 'in' if r['ball'] else 'out':>4s}  "
              f"{r.get('label', '-')}{' (hollow)' if r.get('hollow') else ''} [{r.get('rule', '-')}]")
    ious = [r["iou"] for r in rows]
    errs = [r["size_err_mm"] for r in rows if np.isfinite(r["size_err_mm"])]
    solid = [r["iou"] for r in rows if r["name"] not in CONTAINERS]
    print(f"\n{len(rows)} objects: median volume IoU {np.median(ious):.2f} (min {np.min(ious):.2f}), median oriented size error "
          f"{np.median(errs):.1f} mm, found once {sum(r['clusters'] == 1 for r in rows)}/{len(rows)}")
    print(f"{len(solid)} solid objects (not {', '.join(sorted(CONTAINERS))}): median IoU {np.median(solid):.2f}, min {np.min(solid):.2f}; "
          f"pixels of seen free space covered: {sum(r.get('free_px', 0) for r in rows)} "
          f"({sum(r.get('free_px', 0) > 0 for r in rows)} objects); collision pieces per object: median {np.median([r.get('pieces', 0) for r in rows]):.0f}, "
          f"total {sum(r.get('pieces', 0) for r in rows)}")
    f5 = [r.get("f5", 0.0) for r in rows]
    print(f"surface F-score at {1000 * F_TOLERANCE:.0f} mm (fair to thin walls): median {np.median(f5):.2f}, min {np.min(f5):.2f}; "
          + ", ".join(f"{r['name']} {r['iou']:.2f} IoU / {r.get('f5', 0.0):.2f} F" for r in rows if r["name"] in CONTAINERS))
    if unframed:
        names = ", ".join(f"seed {r['seed']} {r['name']}" for r in unframed)
        print(f"objects out of view (the generator could not frame them; not scored): {names}")
    if skipped:
        print(f"scenes not measured (the generator could not lay them out): {'; '.join(skipped)}")
    if args.where:
        _print_where(rows)
    if args.settling:
        _print_settling(rows)
    fits = [r for r in rows if r.get("fits")]
    print(f"objects the hand fits in truth (narrowest width <= {1000 * HAND_FITS:.0f} mm): {len(fits)}, "
          f"declared graspable {sum(bool(r.get('graspable')) for r in fits)}")


def _print_where(rows: list[dict]) -> None:
    """Per object and summed over the solid ones: where the completed solid misses / exceeds the truth."""
    print(f"\nwhere the completed solid misses / exceeds the truth (% of the true volume, by the pixel a cell projects to): {', '.join(WHERE)}; "
          "its silhouette against the seen mask (centre rays)")
    scored = [r for r in rows if r.get("where")]
    for r in scored:
        print(f"{r['seed']:4d} {r['name']:28s} " + " ".join(f"{k} {100 * r['where'][k][0]:4.1f}/{100 * r['where'][k][1]:5.1f}" for k in WHERE)
              + f" | silhouette short/over {r['silhouette'][0]:.2f}/{r['silhouette'][1]:.2f} px per edge px")
    solid = [r for r in scored if r["name"] not in CONTAINERS]
    if solid:
        print(f"     {'solid objects, median':28s} " + " ".join(f"{k} {100 * np.median([r['where'][k][0] for r in solid]):4.1f}/{100 * np.median([r['where'][k][1] for r in solid]):5.1f}" for k in WHERE)
              + f" | silhouette short/over {np.median([r['silhouette'][0] for r in solid]):.2f}/{np.median([r['silhouette'][1] for r in solid]):.2f} px per edge px")


def _print_settling(rows: list[dict]) -> None:
    """Per object and summed over the solid ones: IoU at the completion pose, after settling, and the motion."""
    scored = [r for r in rows if "iou0" in r]
    print("\nsettling: IoU at the completion pose -> after settling (keyframe initial); lowest point's drop (mm, + down), slide (mm), turn (deg); "
          "lowest point over the truth's before -> after (mm)")
    for r in scored:
        print(f"{r['seed']:4d} {r['name']:28s} {r['iou0']:5.2f} -> {r['iou']:5.2f} ({r['iou'] - r['iou0']:+5.2f})  drop {r['drop_mm']:6.1f}  "
              f"slide {r['slide_mm']:6.1f}  turn {r['turn_deg']:5.1f}  low {r['low0_mm']:+5.1f} -> {r['low1_mm']:+5.1f}")
    solid = [r for r in scored if r["name"] not in CONTAINERS]
    if solid:
        loss = [r["iou0"] - r["iou"] for r in solid]
        print(f"     solid objects: median IoU at completion {np.median([r['iou0'] for r in solid]):.3f}, after settling "
              f"{np.median([r['iou'] for r in solid]):.3f}; settling cost total {sum(loss):+.2f} IoU points (median {np.median(loss):+.3f}); "
              f"median drop {np.median([r['drop_mm'] for r in solid]):.1f} mm, slide {np.median([r['slide_mm'] for r in solid]):.1f} mm, "
              f"turn {np.median([r['turn_deg'] for r in solid]):.1f} deg")


if __name__ == "__main__":
    main()
