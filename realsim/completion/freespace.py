"""The free-space rule: no completed piece covers a pixel where the camera saw farther away.

The line of sight to every observed pixel is empty up to the captured depth (less the sensor's
noise). A convex piece that pokes into that space is seen through from its front surface first
(a ray entering the piece meets its surface before its inside), so the piece is tested on samples
of its surface, each against all four pixels around its image (between an object's last pixel and
the first past it the edge may lie anywhere: only beyond that is the space certainly empty). It is
then cut by planes, one at a time, each chosen among vertical planes (keeping the base on its
support), planes along the line of sight (a cut of the silhouette) and across it (a cut in depth),
to remove the seen-through samples while losing the least of the piece's volume. A piece seen
through almost whole is dropped.
"""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from realsim.completion.carving import voxel_centres
from realsim.completion.cutsearch import best_cut
from realsim.completion.hull import MeshArrays, extreme_points, from_arrays, mesh_arrays, triangles_and_areas, trimesh_hull, volume, within_convex
from realsim.completion.neighbours import clip_convex
from realsim.completion.params import CompletionParams
from realsim.completion.stacking import set_shape
from realsim.completion.view import DepthView
from realsim.forkmap import fork_map
from realsim.geometry import inside_convex_polygon
from realsim.scene import SceneObject, SupportPlane

MAX_CUTS = 6
SURFACE_SAMPLES = 1500
INSIDE_SAMPLES = 2000
MAX_CUT_LOSS = 0.1  # a piece that one cut would lose more of is split in two first
MIN_SPLIT = 0.04  # m: pieces shorter than this are cut, never split
KEEP_MARGIN = 0.002  # m: seen points this far outside a piece still bind its cuts
STALL = 1e-4  # a cut taking less than this share of the piece's volume made no headway


def _unit_rows(rows: np.ndarray) -> np.ndarray:
    return np.asarray(rows / np.linalg.norm(rows, axis=1, keepdims=True))


_AZIMUTH = np.linspace(0.0, 2 * np.pi, 48, endpoint=False)
_FIXED = _unit_rows(np.vstack([np.column_stack([np.cos(_AZIMUTH), np.sin(_AZIMUTH), np.zeros_like(_AZIMUTH)]),  # horizontal
                               np.column_stack([np.cos(_AZIMUTH[::2]) * 0.7, np.sin(_AZIMUTH[::2]) * 0.7, np.full(24, 0.714)])]))  # tilted up
_TURN = np.linspace(0.0, 2 * np.pi, 72, endpoint=False)
_COS, _SIN = np.cos(_TURN)[:, None], np.sin(_TURN)[:, None]
_IMAGE_NORMALS = np.column_stack([np.cos(_TURN), np.sin(_TURN)])  # lines through the image: cuts through the camera centre


def _directions(ray: np.ndarray) -> np.ndarray:
    """Candidate cut normals (unit; the cut keeps ``n . x <= c``): horizontal, tilted up, across and
    along the mean line of sight ``ray``; none points far down (the base stays on its support)."""
    e1 = np.cross(ray, [0.0, 0.0, 1.0])
    e1 = e1 / np.linalg.norm(e1) if np.linalg.norm(e1) > 1e-6 else np.array([1.0, 0.0, 0.0])
    e2 = np.cross(ray, e1)
    across = _COS * e1 + _SIN * e2  # planes containing the line of sight
    normals = np.vstack([_FIXED, _unit_rows(np.vstack([across, -ray[None, :], [[0.0, 0.0, 1.0]]]))])
    return normals[normals[:, 2] > -0.5]


def _samples(piece: trimesh.Trimesh, seed: int) -> np.ndarray:
    """Surface samples of a convex piece: its vertices and area-weighted points on its faces."""
    rng = np.random.default_rng(seed)
    tri, area = triangles_and_areas(piece)
    if area.sum() <= 0:
        return np.asarray(piece.vertices)
    face = rng.choice(len(tri), SURFACE_SAMPLES, p=area / area.sum())
    a, b = rng.random((2, SURFACE_SAMPLES))
    flip = a + b > 1
    a[flip], b[flip] = 1 - a[flip], 1 - b[flip]
    t = tri[face]
    pts = t[:, 0] + a[:, None] * (t[:, 1] - t[:, 0]) + b[:, None] * (t[:, 2] - t[:, 0])
    return np.vstack([piece.vertices, pts])


def _pixel_samples(piece: trimesh.Trimesh, view: DepthView) -> np.ndarray:
    """The piece's front surface where every pixel's ray enters it: a sliver thinner than the random
    samples' spacing (a top edge set a few millimetres too high) still covers whole pixels, each tested."""
    normals = np.asarray(piece.face_normals)
    planes = np.column_stack([normals, np.einsum("fk,fk->f", normals, piece.triangles[:, 0, :])])
    return view.front_hits(planes, np.asarray(piece.vertices))


def _tested_surface(piece: trimesh.Trimesh, view: DepthView, tolerance: float, seed: int, pixels: bool) -> tuple[np.ndarray, np.ndarray]:
    """The surface samples a clip is weighed on and which of them were seen through: the random ones
    (:func:`_samples`) and, with ``pixels``, every pixel's entry point (:func:`_pixel_samples`): no
    pixel the piece covers is left unasked."""
    surface = _samples(piece, seed)
    bad = view.seen_through(surface, tolerance)
    if not pixels:
        return surface, bad
    hits = _pixel_samples(piece, view)
    return np.vstack([surface, hits]), np.concatenate([bad, view.seen_through(hits, tolerance)])


def _image(view: DepthView, points: np.ndarray) -> np.ndarray:
    """Normalized image coordinates (x / z, y / z in the optical frame) of world points."""
    opt = points @ view.world_to_optical[:3, :3].T + view.world_to_optical[:3, 3]
    return np.asarray(opt[:, :2] / opt[:, 2:3])


def _cut(view: DepthView, inside: np.ndarray, bad: np.ndarray, samples: int, keep: np.ndarray | None = None) -> tuple[np.ndarray, float, float]:
    """The best cut as a world half-space ``n . x <= c`` (and its cost): a plane among the fixed
    directions (see :func:`_directions`), or one through the camera centre (a line in the image that
    trims the piece's silhouette) when that costs less; either leaves the ``keep`` points (what stands
    on the piece) kept. The image cut is found first: the plane search then skips what cannot match it."""
    n2, c2, cost2 = best_cut(_image(view, inside), _image(view, bad), _IMAGE_NORMALS, samples,
                             None if keep is None else _image(view, keep))
    ray = bad.mean(axis=0) - view.camera
    n, c, cost = best_cut(inside, bad, _directions(ray / np.linalg.norm(ray)), samples, keep, cost2 if np.isfinite(c2) else np.inf)
    if cost2 < cost and np.isfinite(c2):  # n2 . (y_xy / y_z) <= c2 with y = A x + b, y_z > 0
        k = np.array([n2[0], n2[1], -c2])
        a, b = view.world_to_optical[:3, :3], view.world_to_optical[:3, 3]
        return a.T @ k, float(-k @ b), cost2
    return n, c, cost


def clip_to_free_space(piece: trimesh.Trimesh, view: DepthView, tolerance: float, seed: int = 0,
                       splits: int = 2, keep: np.ndarray | None = None, seen: np.ndarray | None = None) -> list[trimesh.Trimesh]:
    """``piece`` (convex, world frame) cut until none of its surface samples lies nearer the camera
    than the captured depth at its pixel by more than ``tolerance``: convex pieces, none when next
    to nothing is left (a piece standing in seen free space). A cut that would lose more than
    MAX_CUT_LOSS of the piece (its hull bridges a concave side the camera saw) splits it in two
    halves across its longest extent instead, each clipped in turn (at most ``splits`` times deep).
    ``keep``: points no cut may take off (the base of what stands on the piece, see :func:`_cut`);
    ``seen``: what the camera saw of the object, of which a cut takes off at most ``tolerance`` (its
    noise): the wrong guess behind a seen face is cut, not the face (only points in this piece bind)."""
    whole = volume(piece)
    if seen is not None and len(seen):
        seen = seen[within_convex(piece, seen, KEEP_MARGIN)]  # within this piece
        towards = piece.centroid - seen
        far = np.maximum(np.linalg.norm(towards, axis=1, keepdims=True), 1e-9)
        seen = seen + towards / far * np.minimum(far, tolerance)
        keep = seen if keep is None else np.vstack([keep, seen])
    pixels = False  # every pixel's entry point is asked too once the random samples are clear or their cuts stall
    for cut_number in range(MAX_CUTS):
        surface, bad = _tested_surface(piece, view, tolerance, seed, pixels)
        if not bad.any() and not pixels:
            pixels = True
            surface, bad = _tested_surface(piece, view, tolerance, seed, pixels)
        if not bad.any():
            return [piece]
        if keep is not None and cut_number == 0:
            keep = extreme_points(keep)  # only these can bind a cut (the others lie inside them)
        step = float(np.clip(np.max(piece.extents) / 25, 0.001, 0.005))
        inside = np.vstack([voxel_centres(piece, step), surface[~bad]])
        if len(inside) > INSIDE_SAMPLES:
            inside = inside[np.random.default_rng(seed).choice(len(inside), INSIDE_SAMPLES, replace=False)]
        n, c, _ = _cut(view, inside, surface[bad], len(surface), keep)
        lost = float(np.mean(inside @ n > c)) if np.isfinite(c) else 0.0
        if splits > 0 and lost > MAX_CUT_LOSS and bad.mean() < 0.5 and np.max(piece.extents) > MIN_SPLIT:
            axis = np.zeros(3)
            axis[int(np.argmax(piece.extents))] = 1.0
            middle = float(np.median(inside @ axis))
            halves = [clip_convex(piece, sign * axis, sign * middle) for sign in (1.0, -1.0)]
            return [c for h in halves if h is not None for c in clip_to_free_space(h, view, tolerance, seed, splits - 1, keep)]  # seen is in keep
        if not np.isfinite(c):  # no cut is worth its loss
            return [] if bad.mean() > 0.5 else [piece]
        cut = clip_convex(piece, -n, -c)
        if cut is None or volume(cut) < 0.05 * whole:
            return []
        pixels |= volume(cut) > (1.0 - STALL) * volume(piece)  # a shave off samples lying on the last cut's face
        piece = cut
    return [piece]


def clip_pieces(pieces: list[trimesh.Trimesh], view: DepthView, tolerance: float,
                keep: np.ndarray | None = None, seen: np.ndarray | None = None) -> tuple[list[trimesh.Trimesh], float]:
    """Every piece clipped to the free space (pieces left empty dropped), and the share of volume
    removed; ``keep``: points no cut may take off (something stands on it there); ``seen``: what the
    camera saw of it (see :func:`clip_to_free_space`)."""
    return clip_batches([(pieces, keep, seen)], view, tolerance)[0]


Batch = tuple[list[trimesh.Trimesh], "np.ndarray | None", "np.ndarray | None"]


def clip_batches(batches: list[Batch], view: DepthView, tolerance: float) -> list[tuple[list[trimesh.Trimesh], float]]:
    """:func:`clip_pieces` of every ``(pieces, keep, seen)``: the pieces of all of them clipped one by
    one in this process and a forked helper (:func:`realsim.forkmap.fork_map`), the same results."""
    jobs = [(b, i) for b, (pieces, _, _) in enumerate(batches) for i in range(len(pieces))]

    def clip(job: int) -> list[MeshArrays] | None:
        b, i = jobs[job]
        pieces, keep, seen = batches[b]
        splits = 2 if len(pieces) <= 2 else 0  # a shape already in many pieces is cut, not split further
        out = clip_to_free_space(pieces[i], view, tolerance, seed=i, splits=splits, keep=keep, seen=seen)
        return None if len(out) == 1 and out[0] is pieces[i] else [mesh_arrays(c) for c in out]  # None: unchanged

    done = fork_map(clip, len(jobs))
    results = []
    for b, (pieces, _, _) in enumerate(batches):
        out = [c for (j, i), r in zip(jobs, done) if j == b for c in ([pieces[i]] if r is None else [from_arrays(a) for a in r])]
        before = sum(volume(p) for p in pieces)
        results.append((out, (1.0 - sum(volume(p) for p in out) / before) if before > 0 else 0.0))
    return results


def free_space_tolerance(view: DepthView, params: CompletionParams, points: np.ndarray | None = None,
                         planes: list[SupportPlane] | None = None) -> float:
    """How far in front of the captured depth a surface may stand: ``free_space_sigmas`` sigmas of
    the sensor's depth noise, the larger of its pixel-to-pixel noise on the objects and the spread
    of the largest support's points about its plane (quantization and slow distortions show there)."""
    sigma = view.noise()
    seen = [p for p in planes or [] if p.observed]
    if points is not None and seen:
        support = max(seen, key=lambda p: p.inlier_count)
        with np.errstate(invalid="ignore"):
            residual = points[:, 2] - support.height
            near = residual[np.abs(residual) < 0.01]
        if len(near) >= 100:
            sigma = max(sigma, 1.4826 * float(np.median(np.abs(near - np.median(near)))))
    return max(params.free_space_sigmas * sigma, params.free_space_min_tolerance)


def _holds(pieces: list[trimesh.Trimesh], xy: np.ndarray) -> bool:
    """Whether the footprint of ``pieces`` (world frame) still lies under all the points ``xy``."""
    verts = np.vstack([p.vertices for p in pieces])[:, :2]
    try:
        polygon = verts[ConvexHull(verts).vertices]
    except (QhullError, ValueError):
        return False
    return bool(np.all(inside_convex_polygon(xy, polygon, 0.0)))


def keep_out_of_free_space(objects: list[SceneObject], view: DepthView, tolerance: float, params: CompletionParams,
                           supporters: dict[int, np.ndarray] | None = None, seen: dict[int, np.ndarray] | None = None) -> None:
    """Clip every completed object's collision pieces to the free space (see :func:`clip_to_free_space`);
    an object's single hull is also its visual, so that is clipped with it. ``supporters``: objects
    holding another on their top, with the points of what stands there (its base): no cut of theirs
    takes those off, so that top stays where it was under them, and a clip that would leave them
    beyond the supporter's footprint is not made (the shape stays as completed). ``seen``: what the
    camera saw of each object, of which no cut of a single hull takes off more than the tolerance (a
    wrong guess behind it is cut, not the face in front: test55's tilted box kept its seen corners)."""
    supporters, seen = supporters or {}, seen or {}
    batches: list[tuple[SceneObject, np.ndarray, Batch]] = []
    for obj in objects:
        if not obj.collision:
            continue
        base = obj.position - np.array([0.0, 0.0, params.base_clearance])
        world = [p.copy() for p in obj.collision]
        for p in world:
            p.apply_translation(base)
        one = len(world) == 1  # pieces of a body that is not convex may each have to lose seen points (a tile across a handle's opening)
        batches.append((obj, base, (world, supporters.get(obj.id), seen.get(obj.id) if one else None)))
    clips = clip_batches([batch for _, _, batch in batches], view, tolerance)
    for (obj, base, (world, _, _)), (clipped, share) in zip(batches, clips):
        if not clipped or (share <= 0.0 and len(clipped) == len(world)):
            continue
        if obj.id in supporters and not _holds(clipped, supporters[obj.id][:, :2]):
            continue
        hull = trimesh_hull(np.vstack([p.vertices for p in clipped]))
        if obj.visual is None or obj.visual is obj.collision[0]:  # a single hull is its own visual: the clipped pieces' hull
            visual = hull
        else:
            visual = obj.visual.copy()
            visual.apply_translation(base)
        set_shape(obj, hull, base, params, None if len(clipped) == 1 and visual is hull else clipped, visual)
        obj.notes.append(f"cut back out of the space the camera saw through ({100 * share:.0f} % of its volume, "
                         f"{1000 * tolerance:.1f} mm tolerance)")


def free_drops(points: np.ndarray, base_z: float, view: DepthView, tolerance: float, heights: int = 6) -> np.ndarray:
    """Which points may be extruded down to ``base_z``: none of ``heights`` points on the vertical
    segment below it was seen through (a side that tapers in below its top edge was seen there)."""
    t = (np.arange(heights) + 0.5) / heights
    below = np.repeat(points, heights, axis=0)
    below[:, 2] -= np.tile(t, len(points)) * np.repeat(points[:, 2] - base_z, heights)
    return np.asarray(~view.seen_through(below, tolerance).reshape(len(points), heights).any(axis=1))
