"""Handle grasps: pinches on the thin parts of an object (a loop, a bar, a strap) that the open
fingers can close around.

A handle is found from geometry, not from a list of objects: a place where the surface is
locally a bar (its neighbourhood is long in one direction and thin across) and where the hand,
set at the bar with its closing axis across it, finds only the bar between its pads and nothing
in the way of its fingers, its palm or its straight approach (:func:`pinch_fit`). Procedural
objects say where their handles are (``<body>_handle`` sites): then only the bar near those
points is tried; scanned meshes have no sites and every bar-like part is tried. The candidates
pass the same antipodal check as every other pinch; the robot then checks reach, collisions and
statics.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from realsim.robot.grasps import (
    FINGER_BELOW_TCP,
    FINGER_HALF_WIDTH,
    MAX_WIDTH,
    PAD_DEPTH,
    PALM_BEHIND_TCP,
    GraspCandidate,
    antipodal,
    frame_from,
)
from realsim.robot.model import GRIPPER_MAX_OPENING

OPEN_HALF = GRIPPER_MAX_OPENING / 2  # m from the tcp to each open pad
FINGER_THICKNESS = 0.012  # m of finger behind each pad
PALM_HALF = (0.035, 0.11)  # m: the hand's half extents across the fingers and along the closing axis
SUPPORT_GAP = 0.003  # m the hand keeps above the support
HANDLE_RADIUS = 0.02  # m around a seed: the points that say whether the part is a bar
BAR_RATIO = 0.35  # second over first principal variance below this: a bar, not a face
SEED_SPACING = 0.01  # m between seeds on the surface
THIN_SPACING = 0.003  # m between the surface samples a handle is looked for in
ANCHOR_REACH = 0.03  # m around a handle site where seeds are taken
HANDLE_MAX_WIDTH = 0.04  # m: a handle is a part thinner than this across the pads (wider: a chord of the body)
HANDLE_SCORE = 0.8  # below a pinch of the body: a handle is the second choice unless the body cannot be held
MAX_HANDLE_CANDIDATES = 16  # enough to find reachable ones; the search stops there
HAND_REACH = 0.2  # m around a seed: what the hand and its approach can touch
_YAWS = np.arange(8) * np.pi / 4
_HAND_CORNERS = np.array([[sx * xc, su * uc, wc]  # the fingertips and the palm's edge in the tcp frame (x, closing, approach)
                          for wc, uc, xc in ((FINGER_BELOW_TCP, OPEN_HALF + FINGER_THICKNESS, FINGER_HALF_WIDTH), (-PALM_BEHIND_TCP, PALM_HALF[1], PALM_HALF[0]))
                          for su in (-1, 1) for sx in (-1, 1)])
APPROACHES = np.vstack([[0.0, 0.0, -1.0]]
                       + [[np.cos(a), np.sin(a), 0.0] for a in _YAWS]
                       + [[np.cos(a) * 0.7071, np.sin(a) * 0.7071, -0.7071] for a in _YAWS])


def pinch_fit(pts: np.ndarray, normals: np.ndarray | None, pos: np.ndarray, rot: np.ndarray, surface_z: float,
              max_width: float = MAX_WIDTH) -> tuple[np.ndarray, float] | None:
    """The fully open hand at tcp ``pos``, ``rot`` (columns: across the fingers, closing axis,
    approach) closing on what lies between its pads: (tcp centred between the pinched extremes,
    width), or None when it does not fit.

    Everything in the fingers' slab from the fingertips back along the approach and within the
    open fingers must fit in ``max_width`` (so nothing blocks the fingers on the way in), the pads
    must reach both extremes, their patches must face them in full (:func:`antipodal`, no slope
    along the fingers), nothing may lie
    behind the fingers within the palm, and no part of the hand may go below the support.
    """
    if float((pos + _HAND_CORNERS @ rot.T)[:, 2].min()) < surface_z + SUPPORT_GAP:
        return None
    local = (pts - pos) @ rot
    x, u, w = local[:, 0], local[:, 1], local[:, 2]
    slab = (np.abs(x) < FINGER_HALF_WIDTH) & (w <= FINGER_BELOW_TCP)
    zone = slab & (np.abs(u) < OPEN_HALF + FINGER_THICKNESS)
    for _ in range(3):  # centre on what lies between the open fingers, then look again from there
        if zone.sum() < 3:
            return None
        lo, hi = float(u[zone].min()), float(u[zone].max())
        if hi - lo > max_width:
            return None
        mid = (lo + hi) / 2
        if abs(mid) < 5e-4:
            break
        u, pos = u - mid, pos + rot[:, 1] * mid
        zone = slab & (np.abs(u) < OPEN_HALF + FINGER_THICKNESS)
    else:
        return None
    pad = zone & (w > FINGER_BELOW_TCP - PAD_DEPTH - 0.005)
    if not pad.any() or u[pad].min() > lo + 0.004 or u[pad].max() < hi - 0.004:
        return None  # the part lies behind the pads, not between them
    palm = (np.abs(x) < PALM_HALF[0]) & (np.abs(u) < PALM_HALF[1]) & (w < -PALM_BEHIND_TCP + 0.005)
    if palm.any() or float((pos + _HAND_CORNERS @ rot.T)[:, 2].min()) < surface_z + SUPPORT_GAP:
        return None
    if not antipodal(normals, zone, u, rot[:, 1], None):
        return None
    return pos, hi - lo


def thin_out(pts: np.ndarray, normals: np.ndarray | None, spacing: float = THIN_SPACING) -> tuple[np.ndarray, np.ndarray | None]:
    """One surface sample (and its normal) per ``spacing`` voxel."""
    _, first = np.unique(np.floor(pts / spacing).astype(np.int64), axis=0, return_index=True)
    keep = np.sort(first)
    return pts[keep], None if normals is None else normals[keep]


def bar_seeds(pts: np.ndarray, anchors: list[np.ndarray] | None = None) -> list[tuple[np.ndarray, np.ndarray | None]]:
    """(centre, axis) of the parts of a surface to try: one seed per :data:`SEED_SPACING` voxel,
    centred in its neighbourhood. Without ``anchors`` only bar-like parts (long and thin,
    :data:`BAR_RATIO`) with their axis; with them, every seed within :data:`ANCHOR_REACH` of an
    anchor, its axis None where the neighbourhood is not a bar."""
    seeds, _ = thin_out(pts, None, SEED_SPACING)
    if anchors:
        dist = np.min([np.linalg.norm(seeds - a, axis=1) for a in anchors], axis=0)
        seeds = seeds[np.argsort(dist)][: int((dist < ANCHOR_REACH).sum())]  # nearest the anchors first
    tree = cKDTree(pts)
    out: list[tuple[float, np.ndarray, np.ndarray | None]] = []
    for s in seeds:
        nb = pts[tree.query_ball_point(s, HANDLE_RADIUS)]
        if len(nb) < 8:
            continue
        vals, vecs = np.linalg.eigh(np.cov(nb.T))
        bar = vals[2] > 0 and vals[1] / vals[2] < BAR_RATIO
        if bar or anchors:
            out.append((float(vals[1] / vals[2]), nb.mean(axis=0), vecs[:, 2] if bar else None))
    if not anchors:
        out.sort(key=lambda t: t[0])  # the most bar-like first
    return [(c, a) for _, c, a in out]


def _closings(axis: np.ndarray | None, approach: np.ndarray) -> list[np.ndarray]:
    """Closing axes for an approach: across the bar when the approach crosses it, else four
    directions about the approach (the hand comes in along the bar, or the part is no bar)."""
    if axis is not None:
        c = np.cross(axis, approach)
        if np.linalg.norm(c) > 0.5:
            return [c / np.linalg.norm(c)]
        if abs(float(axis @ approach)) < 0.9:
            return []
    ref = np.array([1.0, 0.0, 0.0]) if abs(approach[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(approach, ref)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(approach, e1)
    return [np.cos(a) * e1 + np.sin(a) * e2 for a in np.arange(4) * np.pi / 4]


def handle_candidates(pts: np.ndarray, normals: np.ndarray | None, surface_z: float, base_xy: np.ndarray,
                      anchors: list[np.ndarray] | None = None) -> list[GraspCandidate]:
    """Pinches across the object's bars (near ``anchors`` when given), best first: top-down
    first, then approaches turned away from the robot's base, a comfortable width."""
    pts, normals = thin_out(pts, normals)
    tree = cKDTree(pts)
    out: list[GraspCandidate] = []
    for centre, axis in bar_seeds(pts, anchors):
        near = np.asarray(tree.query_ball_point(centre, HAND_REACH), int)
        p, n = pts[near], None if normals is None else normals[near]
        away = np.array([*(centre[:2] - base_xy), 0.0])
        away /= max(float(np.linalg.norm(away)), 1e-9)
        for a in APPROACHES:
            if a @ away < -0.3:  # the hand would come back towards the robot from beyond the object
                continue
            for closing in _closings(axis, a):
                rot = frame_from(a, closing)
                fit = pinch_fit(p, n, centre, rot, surface_z, HANDLE_MAX_WIDTH)
                if fit is None:
                    continue
                pos, width = fit
                if any(np.linalg.norm(pos - c.pos) < 0.006 and abs(float(rot[:, 2] @ c.rot[:, 2])) > 0.95 for c in out):
                    continue
                score = HANDLE_SCORE - 0.1 * abs(float(a[2])) + 0.05 * float(a @ away)
                out.append(GraspCandidate("handle", pos, rot, width, score))
        if len(out) >= MAX_HANDLE_CANDIDATES:
            break
    out.sort(key=lambda c: -c.score)
    return out
