"""Which segments of a camera view lie in front of the segments around them (objects, not pieces).

A small segment is either a piece of a larger neighbour (a patch cut off at a fold or a colour edge
of one surface) or a small object resting on or against it (a marker lying on a box, a strawberry
leaning on a bottle). Along a piece's image border the surface continues into its neighbour, or the
neighbour's own rim hides it; a small object's border is its silhouette: its pixels lie nearer to
the camera than the neighbour's pixels next to them, all round but where it touches, and where it
touches the two surfaces meet at a crease rather than continue. The share of border pixel pairs
that step toward the camera tells them apart, whatever the size in pixels.
"""

from __future__ import annotations

import numpy as np

__all__ = ["in_front"]


def in_front(labels: np.ndarray, a: np.ndarray, b: np.ndarray, depth: np.ndarray, normals: np.ndarray, min_jump: float,
             max_turn_deg: float, share: float) -> np.ndarray:
    """Per segment (``labels`` >= 0 per point), whether it lies in front of its neighbours.

    ``a``, ``b`` are the image-grid neighbour pairs (every one, across depth jumps too), ``depth``
    each point's distance along the viewing axis and ``normals`` its unit surface normal. Over the
    pairs joining a segment to another one, a pair steps toward the camera when the segment's point
    is more than ``min_jump`` nearer, and continues the surface when the two lie within ``min_jump``
    with normals within ``max_turn_deg``; pairs where the segment is the farther one (hidden there)
    or that meet at a crease (where it stands on or leans against the other) do not count. A
    segment lies in front when more than ``share`` of the counted pairs step toward the camera."""
    n_seg = int(labels.max(initial=-1)) + 1
    la, lb = labels[a], labels[b]
    border = la != lb
    la, lb, pa, pb = la[border], lb[border], a[border], b[border]
    step = depth[pa] - depth[pb]  # negative: a's point is the nearer one
    with np.errstate(invalid="ignore"):
        smooth = np.abs((normals[pa] * normals[pb]).sum(axis=1)) > np.cos(np.radians(max_turn_deg))
    seg = np.concatenate([la, lb])
    nearer = np.concatenate([step < -min_jump, step > min_jump])
    along = np.concatenate([(np.abs(step) <= min_jump) & smooth] * 2)
    n_near = np.bincount(seg, nearer, minlength=n_seg)
    n_along = np.bincount(seg, along, minlength=n_seg)
    out: np.ndarray = n_near > share * (n_near + n_along)
    return out
