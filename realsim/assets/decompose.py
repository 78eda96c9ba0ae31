"""Convex decomposition for collision: a primitive or a single hull when exact enough, else tuned CoACD.

A hull budget then merges CoACD's parts down to the fewest hulls that still pass the fidelity
self-check (fewer hulls, fewer narrow-phase pairs per step); CoACD's own parts are cached apart
from the merging settings.

CoACD runs on a decimated copy of the solid with its own hull merging off (that merge is
quadratic and dominates its run time); parts are merged here greedily by added volume per area
(a thickness), which keeps cavities open. Every hull is checked for MuJoCo: >= 4 non-coplanar
vertices and a positive volume; flat ones are thickened.
"""

from __future__ import annotations

import heapq
import warnings
from contextlib import nullcontext
from dataclasses import replace

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError, cKDTree

from realsim.assets.fidelity import sample_surface
from realsim.assets.params import AssetParams
from realsim.assets.primitives import PRIMITIVE_KEY, fit_primitive
from realsim.cache import DiskCache


def _import_single_threaded(name: str):
    """Import an OpenMP-linked module (CoACD, Open3D) with OMP_NUM_THREADS=1 while it loads.

    libgomp is not fork-safe: once its thread pool exists in a process, a forked worker that uses
    it hangs. Objects are decomposed in parallel processes anyway, so the libraries run
    single-threaded; the variable is restored so other libraries are unaffected.
    """
    import importlib
    import os
    import sys

    if name in sys.modules:
        return sys.modules[name]
    old = os.environ.get("OMP_NUM_THREADS")
    os.environ["OMP_NUM_THREADS"] = "1"
    try:
        return importlib.import_module(name)
    finally:
        if old is None:
            del os.environ["OMP_NUM_THREADS"]
        else:
            os.environ["OMP_NUM_THREADS"] = old


def decimate(mesh: trimesh.Trimesh, faces: int) -> trimesh.Trimesh:
    """Quadric decimation to about ``faces`` triangles (unchanged when already smaller)."""
    if len(mesh.faces) <= faces:
        return mesh
    o3d = _import_single_threaded("open3d")

    om = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(mesh.vertices), o3d.utility.Vector3iVector(mesh.faces))
    om = om.simplify_quadric_decimation(int(faces))
    out = trimesh.Trimesh(np.asarray(om.vertices), np.asarray(om.triangles), process=True)
    out.update_faces(out.nondegenerate_faces(height=1e-10))
    out.remove_unreferenced_vertices()
    return out


def make_hull(points: np.ndarray, min_thickness: float = 0.0005, max_vertices: int = 64) -> trimesh.Trimesh | None:
    """A MuJoCo-valid convex hull of ``points``: thickened when flat, None when degenerate."""
    pts = np.unique(np.asarray(points, float).round(9), axis=0)
    if len(pts) < 3:
        return None
    c = pts.mean(axis=0)
    _, s, vt = np.linalg.svd(pts - c, full_matrices=False)
    proj = (pts - c) @ vt.T
    thickness = proj[:, 2].max() - proj[:, 2].min() if len(s) == 3 else 0.0
    if len(s) < 3 or thickness < min_thickness:
        if len(s) < 2 or (proj[:, 1].max() - proj[:, 1].min()) < min_thickness:
            return None  # a line or a point
        n = vt[2] if len(vt) == 3 else np.cross(vt[0], vt[1])
        mid = (proj[:, 2].max() + proj[:, 2].min()) / 2
        flat = pts - np.outer(proj[:, 2] - mid, n)
        pts = np.vstack([flat + n * min_thickness / 2, flat - n * min_thickness / 2])
    try:
        hull = ConvexHull(pts)
    except QhullError:
        return None
    verts = pts[hull.vertices]
    if len(verts) > max_vertices:
        verts = _cap_vertices(verts, max_vertices)
        if verts is None:
            return None
    mesh = trimesh.convex.convex_hull(verts)
    if len(mesh.vertices) < 4 or mesh.volume <= 1e-12:
        return None
    return mesh


def _cap_vertices(verts: np.ndarray, max_vertices: int) -> np.ndarray | None:
    """At most ``max_vertices`` of a convex polytope's vertices whose hull stays closest to it:
    start from the extreme points in 12 directions, then add, one at a time, the vertex lying
    farthest outside the current hull (greedy Hausdorff reduction: the base an object stands on
    and every protrusion are kept first)."""
    idx = list(np.unique(np.argmax(verts @ _fibonacci(12).T, axis=0)))
    while len(idx) < max_vertices:
        try:
            eq = ConvexHull(verts[idx]).equations
        except QhullError:
            return None
        outside = (verts @ eq[:, :3].T + eq[:, 3]).max(axis=1)
        outside[idx] = -np.inf
        far = int(np.argmax(outside))
        if outside[far] <= 1e-9:
            break
        idx.append(far)
    try:
        hull = ConvexHull(verts[idx])
    except QhullError:
        return None
    return verts[idx][hull.vertices]


def _fibonacci(n: int) -> np.ndarray:
    i = np.arange(n) + 0.5
    phi = np.arccos(1 - 2 * i / n)
    theta = np.pi * (1 + 5**0.5) * i
    return np.stack([np.cos(theta) * np.sin(phi), np.sin(theta) * np.sin(phi), np.cos(phi)], axis=1)


def hull_p95_distance(hull: trimesh.Trimesh, solid: trimesh.Trimesh, n: int = 4000, dense: int = 60000) -> float:
    """95th percentile distance between a single hull and the solid surface, both ways (m)."""
    tree = cKDTree(sample_surface(solid, dense, 7))
    d_h2s = tree.query(sample_surface(hull, n, 8))[0]
    eq = ConvexHull(hull.vertices).equations
    d_s2h = np.maximum(-(sample_surface(solid, n, 9) @ eq[:, :3].T + eq[:, 3]).max(axis=1), 0.0)
    return float(max(np.percentile(d_h2s, 95), np.percentile(d_s2h, 95)))


def parts_fidelity(hulls: list[trimesh.Trimesh], solid: trimesh.Trimesh, n: int = 6000) -> tuple[float, float]:
    """(p95 two-way surface distance, volume IoU) of a decomposition — a quick self-check."""
    from realsim.assets.fidelity import surface_distances, volume_iou

    a, b = surface_distances(hulls, solid, n=n, dense=60000, seed=11)
    return float(max(np.percentile(a, 95), np.percentile(b, 95))), volume_iou(hulls, solid)


def _gap(h: ConvexHull, eq_a: np.ndarray, eq_b: np.ndarray) -> float:
    """How far the merged hull ``h`` reaches outside both parts (m): the max over its face
    centroids and edge midpoints of the distance (plane lower bound) to the nearer part."""
    tri = h.points[h.simplices]
    probes = np.vstack([tri.mean(axis=1), (tri[:, 0] + tri[:, 1]) / 2, (tri[:, 1] + tri[:, 2]) / 2, (tri[:, 2] + tri[:, 0]) / 2])
    da = (probes @ eq_a[:, :3].T + eq_a[:, 3]).max(axis=1)
    db = (probes @ eq_b[:, :3].T + eq_b[:, 3]).max(axis=1)
    return float(np.maximum(np.minimum(da, db), 0.0).max())


def _merge_hulls(parts: list[np.ndarray], params: AssetParams) -> list[np.ndarray]:
    """Greedy merging of neighbouring convex parts, cheapest first, while the merged hull stays
    within ``merge_tolerance`` of the two parts (so cavities stay open), then, only if more than
    ``max_hulls`` remain, further merges by least added volume."""
    alive: dict[int, tuple[np.ndarray, np.ndarray, float]] = {}
    for i, p in enumerate(parts):
        try:
            h = ConvexHull(p)
        except QhullError:
            continue
        alive[i] = (p[h.vertices], h.equations, h.volume)
    lo = {i: v[0].min(axis=0) for i, v in alive.items()}
    hi = {i: v[0].max(axis=0) for i, v in alive.items()}
    margin = 0.002

    def cost(i: int, j: int) -> tuple[float, float]:
        try:
            h = ConvexHull(np.vstack([alive[i][0], alive[j][0]]))
        except QhullError:
            return np.inf, np.inf
        return _gap(h, alive[i][1], alive[j][1]), h.volume - alive[i][2] - alive[j][2]

    def near(i: int, j: int) -> bool:
        return bool(np.all(lo[i] <= hi[j] + margin) and np.all(lo[j] <= hi[i] + margin))

    for phase in (0, 1):  # 0: within tolerance (by gap), 1: down to max_hulls (by added volume)
        if phase == 1 and len(alive) <= params.max_hulls:
            break
        heap: list[tuple[float, int, int]] = []
        keys = sorted(alive)
        for a in range(len(keys)):
            for b in range(a + 1, len(keys)):
                i, j = keys[a], keys[b]
                if near(i, j):
                    gap, dv = cost(i, j)
                    if phase == 1 or gap <= params.merge_tolerance:
                        heapq.heappush(heap, (gap + 1e-3 * max(dv, 0.0) ** (1 / 3), i, j))
        next_id = max(alive) + 1 if alive else 0
        while heap and len(alive) > 1:
            if phase == 1 and len(alive) <= params.max_hulls:
                break
            _, i, j = heapq.heappop(heap)
            if i not in alive or j not in alive:
                continue
            try:
                h = ConvexHull(np.vstack([alive[i][0], alive[j][0]]))
            except QhullError:
                continue
            del alive[i], alive[j]
            k = next_id
            next_id += 1
            alive[k] = (h.points[h.vertices], h.equations, h.volume)
            lo[k], hi[k] = alive[k][0].min(axis=0), alive[k][0].max(axis=0)
            for m in sorted(alive):
                if m != k and near(m, k):
                    gap, dv = cost(m, k)
                    if phase == 1 or gap <= params.merge_tolerance:
                        heapq.heappush(heap, (gap + 1e-3 * max(dv, 0.0) ** (1 / 3), m, k))
    return [alive[k][0] for k in sorted(alive)]


def _coacd_parts(coacd, dec: trimesh.Trimesh, pre: str, threshold: float, params: AssetParams, cache: DiskCache | None) -> list[np.ndarray]:
    """CoACD's convex parts (vertex arrays) of the decimated solid, cached (in ``cache``) by the mesh
    and CoACD's own settings only: changing how parts are merged or budgeted never re-runs CoACD."""
    from realsim.cache import cache_key

    cache = cache if cache is not None else DiskCache(enabled=False)

    settings = {"threshold": threshold, "pre": pre, "preprocess_resolution": params.preprocess_resolution, "resolution": params.resolution,
                "mcts": [params.mcts_iterations, params.mcts_nodes, params.mcts_max_depth], "seed": params.seed}
    key = cache_key("assets.coacd_parts", data=np.asarray(dec.vertices, np.float64).tobytes() + np.asarray(dec.faces, np.int64).tobytes(),
                    params=settings)
    parts = cache.get(key)
    if parts is not None:
        return parts
    with cache.lock(key) if cache.enabled else nullcontext():  # another worker on the same mesh waits, then reads its result
        parts = cache.get(key)
        if parts is not None:
            return parts
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            raw = coacd.run_coacd(
                coacd.Mesh(np.asarray(dec.vertices), np.asarray(dec.faces)),
                threshold=threshold, max_convex_hull=-1, preprocess_mode=pre, preprocess_resolution=params.preprocess_resolution,
                resolution=params.resolution, mcts_iterations=params.mcts_iterations, mcts_nodes=params.mcts_nodes,
                mcts_max_depth=params.mcts_max_depth, merge=False, seed=params.seed,
            )
        parts = [np.asarray(v, float) for v, _ in raw if len(v) >= 4]
        cache.put(key, parts)
    return parts


def _fewest_hulls(parts: list[np.ndarray], hulls: list[trimesh.Trimesh], solid: trimesh.Trimesh, params: AssetParams,
                  cavity: bool, info: dict) -> list[trimesh.Trimesh]:
    """The hull budget: merge ``parts`` down to ever fewer hulls while the self-check still holds
    (two-way p95 within ``target_p95``; IoU at ``target_iou`` unless the scan is a cavity's
    walls), and keep the smallest set that passes (``hulls`` when none does)."""
    d95, iou = parts_fidelity(hulls, solid)
    if not (d95 <= params.target_p95 and (cavity or iou >= params.target_iou)):
        return hulls
    best = hulls
    for budget in params.hull_budgets:
        if budget >= len(best):
            continue
        merged = _merge_hulls(parts, replace(params, max_hulls=budget))
        fewer = [h for h in (make_hull(p, params.min_hull_thickness, params.max_hull_vertices) for p in merged) if h is not None]
        if not fewer:
            break
        d95, iou = parts_fidelity(fewer, solid)
        if not (d95 <= params.target_p95 and (cavity or iou >= params.target_iou)):
            break
        best = fewer
        info["budget_check"] = {"hulls": len(fewer), "p95": d95, "iou": iou}
    return best


def decompose(solid: trimesh.Trimesh, params: AssetParams, open_container: bool | None = None,
              cache: DiskCache | None = None) -> tuple[list[trimesh.Trimesh], dict]:
    """Convex parts of ``solid`` (object frame) and a small report.

    ``open_container`` (from the size table) says the mesh shows a cavity, so only surface
    distance (not volume IoU) is checked; None guesses it from the solid / hull volume ratio.
    """
    info: dict = {}
    hull = make_hull(solid.vertices, params.min_hull_thickness, 10**6)
    ratio = solid.volume / hull.volume if hull is not None and hull.volume > 0 else 0.0
    info["convex_ratio"] = float(ratio)
    cavity = open_container if open_container is not None else ratio < 0.6  # walls only: IoU is not meaningful
    if params.primitives and not cavity:  # a box, cylinder or sphere as faithful as hulls collides far more cheaply
        primitive, info["primitive_fits"] = fit_primitive(solid, params.primitive_tolerance, params.target_iou)
        if primitive is not None:
            info["method"] = "primitive_" + primitive.metadata[PRIMITIVE_KEY]["type"]
            return [primitive], info
    if hull is not None and ratio >= params.convex_volume_ratio:
        d95 = hull_p95_distance(hull, solid)
        info["convex_p95"] = d95
        if d95 <= params.convex_tolerance:
            info["method"] = "single_hull"
            single = make_hull(solid.vertices, params.min_hull_thickness, params.max_hull_vertices)
            return [single], info
    coacd = _import_single_threaded("coacd")
    coacd.set_log_level("error")
    dec = decimate(solid, params.decimate_faces)
    pre = "off" if dec.is_watertight else params.preprocess_mode
    info["decimated_faces"] = len(dec.faces)
    hulls: list[trimesh.Trimesh] = []
    threshold = params.threshold
    for attempt in range(1 + params.refine_attempts):
        pts = _coacd_parts(coacd, dec, pre, threshold, params, cache)
        merged = _merge_hulls(pts, params)
        hulls = [h for h in (make_hull(p, params.min_hull_thickness, params.max_hull_vertices) for p in merged) if h is not None]
        info["coacd_parts"] = len(pts)
        info["threshold"] = threshold
        if not hulls or attempt == params.refine_attempts:
            break
        d95, iou = parts_fidelity(hulls, solid)
        info["self_check"] = {"p95": d95, "iou": iou}
        if d95 <= params.target_p95 and (cavity or iou >= params.target_iou):
            break
        threshold *= 0.6
    if hulls and params.hull_budget:
        hulls = _fewest_hulls(pts, hulls, solid, params, cavity, info)
    info["method"] = "coacd"
    info["hulls"] = len(hulls)
    if not hulls:
        info["method"] = "convex_hull_fallback"
        hulls = [hull]
    return hulls, info
