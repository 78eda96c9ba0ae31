"""Convex decomposition for collision: a primitive or a single hull when exact enough, an open
container's floor and wall ring when that passes the self-check, else tuned CoACD.

A hull budget then merges CoACD's parts down to the fewest hulls that still pass the fidelity
self-check (fewer hulls, fewer narrow-phase pairs per step); CoACD's own parts are cached apart
from the merging settings.

CoACD runs on a decimated copy of the solid with its own hull merging off (that merge is
quadratic and dominates its run time); parts are merged here greedily by added volume per area
(a thickness), which keeps cavities open. Every hull is checked for MuJoCo: >= 4 non-coplanar
vertices and a positive volume; flat ones are thickened.
"""

from __future__ import annotations

import warnings
from contextlib import nullcontext

import numpy as np
import trimesh

from realsim.assets.budget import fewest_hulls, merge_hulls
from realsim.assets.container_ring import container_ring, ring_with_rest
from realsim.assets.fidelity import parts_fidelity
from realsim.assets.hulls import hull_p95_distance, make_hull
from realsim.assets.params import AssetParams
from realsim.assets.primitives import PRIMITIVE_KEY, fit_primitive
from realsim.cache import DiskCache

REFINE = 0.6  # CoACD threshold factor of the refining attempt (finer parts)


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


def _finer_budget(coacd, dec: trimesh.Trimesh, pre: str, solid: trimesh.Trimesh, hulls: list[trimesh.Trimesh], params: AssetParams,
                  cavity: bool, cache: DiskCache | None, info: dict) -> list[trimesh.Trimesh]:
    """Still at ``max_hulls`` after the budget (parts that passed the self-check only barely): CoACD's
    finer parts (the refine threshold), merged and budgeted by the gap order (the distance order is
    quadratic in the many finer parts: minutes on the YCB pitcher); the fewer faithful hulls."""
    pts = _coacd_parts(coacd, dec, pre, params.threshold * REFINE, params, cache)
    merged = [h for h in (make_hull(p, params.min_hull_thickness, params.max_hull_vertices) for p in merge_hulls(pts, params)) if h is not None]
    if not merged:
        return hulls
    trial: dict = {}
    finer = fewest_hulls(pts, merged, solid, params, cavity, trial, by_error=False)
    if len(finer) >= len(hulls) or "budget_check" not in trial:  # not fewer, or never passed the self-check
        return hulls
    info.update(trial, coacd_parts=len(pts), threshold=params.threshold * REFINE)
    return finer


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
    ring = container_ring(solid, params) if cavity and params.container_ring else None
    if ring is not None and not len(ring[1]):
        info.update(ring[2], method="container_ring", hulls=len(ring[0]))
        return ring[0], info
    coacd = _import_single_threaded("coacd")
    coacd.set_log_level("error")
    dec = decimate(solid, params.decimate_faces)
    pre = "off" if dec.is_watertight else params.preprocess_mode
    info["decimated_faces"] = len(dec.faces)
    hulls: list[trimesh.Trimesh] = []
    threshold = params.threshold
    for attempt in range(1 + params.refine_attempts):
        pts = _coacd_parts(coacd, dec, pre, threshold, params, cache)
        merged = merge_hulls(pts, params)
        hulls = [h for h in (make_hull(p, params.min_hull_thickness, params.max_hull_vertices) for p in merged) if h is not None]
        info["coacd_parts"] = len(pts)
        info["threshold"] = threshold
        if not hulls or attempt == params.refine_attempts:
            break
        d95, iou = parts_fidelity(hulls, solid)
        info["self_check"] = {"p95": d95, "iou": iou}
        if d95 <= params.target_p95 and (cavity or iou >= params.target_iou):
            break
        threshold *= REFINE
    if hulls and params.hull_budget:
        hulls = fewest_hulls(pts, hulls, solid, params, cavity, info)
        if len(hulls) >= params.max_hulls and info["threshold"] == params.threshold and params.refine_attempts:
            hulls = _finer_budget(coacd, dec, pre, solid, hulls, params, cavity, cache, info)
    info["method"] = "coacd"
    if ring is not None and hulls and (both := ring_with_rest(ring[0], ring[1], hulls, solid, params)) is not None:
        info.update(ring[2], method="container_ring+coacd", self_check=both[1])
        hulls = both[0]
    info["hulls"] = len(hulls)
    if not hulls:
        info["method"] = "convex_hull_fallback"
        hulls = [hull]
    return hulls, info
