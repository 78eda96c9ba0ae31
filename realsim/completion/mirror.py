"""Mirror symmetry: the hidden half of a body seen from one side is its visible half reflected."""

from __future__ import annotations

import numpy as np
from scipy.spatial import ConvexHull, QhullError

from realsim.completion.params import CompletionParams
from realsim.completion.view import DepthView


def mirror_hidden_half(points: np.ndarray, view: DepthView, base_z: float, top_z: float, params: CompletionParams) -> np.ndarray | None:
    """The observed points plus their mirror image behind the silhouette, when the camera evidently saw
    only the front half of a body: its visible depth (along the horizontal view direction) is short
    of its width and its top is not seen whole (a box whose top face is seen has its depth already)."""
    camera = np.linalg.inv(view.world_to_optical)[:3, 3]
    d = np.append(points[:, :2].mean(axis=0) - camera[:2], 0.0)
    if np.linalg.norm(d) < 1e-6:
        return None
    d /= np.linalg.norm(d)
    lateral = np.array([-d[1], d[0], 0.0])
    s, w = points @ d, points @ lateral
    depth = float(np.percentile(s, 98) - np.percentile(s, 2))
    width = float(np.percentile(w, 98) - np.percentile(w, 2))
    if depth >= params.mirror_max_depth_share * width or _top_face_seen(points[points[:, 2] >= top_z - 0.1 * (top_z - base_z)], d, depth):
        return None
    plane = float(np.percentile(s, 98))
    return np.vstack([points, points - 2.0 * (s - plane)[:, None] * d[None, :]])


def _top_face_seen(top: np.ndarray, d: np.ndarray, depth: float, cell: float = 0.005) -> bool:
    """The top band spans the visible depth and fills its outline (a face seen whole, not a rim arc)."""
    if len(top) < 10 or float(np.ptp(top @ d)) < 0.6 * depth:
        return False
    try:
        area = float(ConvexHull(top[:, :2]).volume)
    except QhullError:
        return False
    cells = len(np.unique(np.floor(top[:, :2] / cell).astype(np.int64), axis=0))
    return cells * cell * cell >= 0.6 * area
