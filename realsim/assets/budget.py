"""The hull budget: convex parts merged down to the fewest hulls that pass the self-check.

Two merge orders are tried at every budget: by the gap a merged hull opens between its two parts
(cheap, keeps cavities open), and by how far the merged hull strays from the scanned surface
(the better order on thin curved walls: bowls, mugs). The first is also the tolerance merge
applied to CoACD's raw parts.
"""

from __future__ import annotations

import heapq
from dataclasses import replace

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError, cKDTree

from realsim.assets.fidelity import dense_count, parts_fidelity, sample_surface
from realsim.assets.hulls import make_hull
from realsim.assets.params import AssetParams

NEAR = 0.002  # m: parts whose boxes come this close are neighbours (candidates to merge)


def _gap(h: ConvexHull, eq_a: np.ndarray, eq_b: np.ndarray) -> float:
    """How far the merged hull ``h`` reaches outside both parts (m): the max over its face
    centroids and edge midpoints of the distance (plane lower bound) to the nearer part."""
    tri = h.points[h.simplices]
    probes = np.vstack([tri.mean(axis=1), (tri[:, 0] + tri[:, 1]) / 2, (tri[:, 1] + tri[:, 2]) / 2, (tri[:, 2] + tri[:, 0]) / 2])
    da = (probes @ eq_a[:, :3].T + eq_a[:, 3]).max(axis=1)
    db = (probes @ eq_b[:, :3].T + eq_b[:, 3]).max(axis=1)
    return float(np.maximum(np.minimum(da, db), 0.0).max())


def merge_hulls(parts: list[np.ndarray], params: AssetParams) -> list[np.ndarray]:
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
    margin = NEAR

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


def surface_error(points: np.ndarray, tree: cKDTree, samples: int = 300) -> tuple[float, np.ndarray]:
    """(95th percentile distance of the hull of ``points`` from the scanned surface whose samples
    ``tree`` holds, the hull's vertices): how far a merged part strays from the scan."""
    try:
        hull = ConvexHull(points)
    except QhullError:  # flat: it lies on the surface it came from
        return 0.0, points
    tri = points[hull.simplices]
    area = np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    rng = np.random.default_rng(0)
    t = tri[rng.choice(len(tri), size=samples, p=area / area.sum())]
    r = rng.random((samples, 2))
    r[r.sum(axis=1) > 1] = 1 - r[r.sum(axis=1) > 1]
    probes = t[:, 0] + r[:, :1] * (t[:, 1] - t[:, 0]) + r[:, 1:] * (t[:, 2] - t[:, 0])
    return float(np.percentile(tree.query(probes)[0], 95)), points[hull.vertices]


def merge_by_surface_error(parts: list[np.ndarray], solid: trimesh.Trimesh, budgets: list[int]) -> dict[int, list[np.ndarray]]:
    """Neighbouring parts merged greedily, the pair whose merged hull stays closest to the scanned
    surface first (a thin curved wall is cut into even patches); the parts at each of ``budgets``."""
    tree = cKDTree(sample_surface(solid, dense_count(solid), 7))
    alive = {i: surface_error(np.asarray(p, float), tree)[1] for i, p in enumerate(parts)}
    lo = {i: v.min(axis=0) for i, v in alive.items()}
    hi = {i: v.max(axis=0) for i, v in alive.items()}
    heap: list[tuple[float, int, int, np.ndarray]] = []

    def push(a: int, b: int) -> None:
        if np.all(lo[a] <= hi[b] + NEAR) and np.all(lo[b] <= hi[a] + NEAR):
            err, verts = surface_error(np.vstack([alive[a], alive[b]]), tree)
            heapq.heappush(heap, (err, min(a, b), max(a, b), verts))

    keys = sorted(alive)
    for x, a in enumerate(keys):
        for b in keys[x + 1:]:
            push(a, b)
    out: dict[int, list[np.ndarray]] = {}
    next_id = len(parts)
    wanted = sorted(budgets, reverse=True)
    while heap and wanted:
        if len(alive) <= wanted[0]:
            out[wanted.pop(0)] = [alive[k] for k in sorted(alive)]
            continue
        _, a, b, verts = heapq.heappop(heap)
        if a not in alive or b not in alive:
            continue
        del alive[a], alive[b]
        alive[next_id], lo[next_id], hi[next_id] = verts, verts.min(axis=0), verts.max(axis=0)
        for m in sorted(alive)[:-1]:
            push(m, next_id)
        next_id += 1
    return out


def fewest_hulls(parts: list[np.ndarray], hulls: list[trimesh.Trimesh], solid: trimesh.Trimesh, params: AssetParams,
                 cavity: bool, info: dict, by_error: bool = True) -> list[trimesh.Trimesh]:
    """The hull budget: ``parts`` merged down to ever fewer hulls, each budget by two orders (the
    gap between merged parts, and, with ``by_error``, the merged hull's distance from the scan:
    quadratic in the parts), while the self-check still holds (two-way p95 within ``target_p95``;
    IoU at ``target_iou`` unless the scan is a cavity's walls); the smallest set that passes
    (``hulls`` when none does)."""

    def check(candidate: list[np.ndarray]) -> tuple[list[trimesh.Trimesh], float, float] | None:
        made = [h for h in (make_hull(p, params.min_hull_thickness, params.max_hull_vertices) for p in candidate) if h is not None]
        if not made:
            return None
        d95, iou = parts_fidelity(made, solid)
        return (made, d95, iou) if d95 <= params.target_p95 and (cavity or iou >= params.target_iou) else None

    first = check([np.asarray(h.vertices) for h in hulls])
    if first is None:
        return hulls
    best = hulls
    budgets = [b for b in params.hull_budgets if b < len(hulls)]
    by_error = merge_by_surface_error(parts, solid, budgets) if budgets and by_error else {}
    for budget in budgets:
        if budget >= len(best):
            continue
        passed = [r for r in (check(merge_hulls(parts, replace(params, max_hulls=budget))), check(by_error.get(budget, [])))
                  if r is not None]
        if not passed:
            break
        best, d95, iou = min(passed, key=lambda r: (len(r[0]), r[1]))
        info["budget_check"] = {"hulls": len(best), "p95": d95, "iou": iou}
    return best
