"""Which clusters of a camera view are patches of the backdrop rather than objects.

The foreground test (above a support, inside its polygon and a margin) can cut a patch out of a
surface behind the objects: where a wall rises at the back edge of a counter, its pixels a few
millimetres either side of the margin pass and fail at random and the passing ones gather into a
cluster over nothing. An object's image outline is a silhouette: its pixels step away from the
surface behind it, or meet the support at a crease where it stands. A patch's outline continues
its surface: the pixels next to it lie within a depth jump and face the same way. A cluster
whose border mostly continues into pixels no object holds is backdrop.
"""

from __future__ import annotations

import numpy as np

__all__ = ["continues_backdrop"]


def continues_backdrop(labels: np.ndarray, a: np.ndarray, b: np.ndarray, depth: np.ndarray, normals: np.ndarray,
                       min_jump: float, max_turn_deg: float, share: float) -> np.ndarray:
    """Per cluster k (``labels`` == k > 0; 0 marks pixels no object holds, < 0 noise), whether more
    than ``share`` of its border pairs continue its surface into a 0 pixel.

    ``a``, ``b`` are the image-grid neighbour pairs, ``depth`` each point's distance along the
    viewing axis and ``normals`` its unit surface normal (NaN where unknown). A border pair (the
    other point outside the cluster and measured) continues the surface when the two points lie
    within ``min_jump`` along the view with normals within ``max_turn_deg``. Returns (max label + 1,)
    booleans (index 0 False)."""
    n = int(labels.max(initial=0)) + 1
    la, lb = labels[a], labels[b]
    border = (la != lb) & np.isfinite(depth[a]) & np.isfinite(depth[b])
    la, lb, pa, pb = la[border], lb[border], a[border], b[border]
    with np.errstate(invalid="ignore"):
        smooth = (np.abs(depth[pa] - depth[pb]) <= min_jump) & (
            np.abs((normals[pa] * normals[pb]).sum(axis=1)) > np.cos(np.radians(max_turn_deg)))
    seg = np.concatenate([la, lb])
    other = np.concatenate([lb, la])
    cont = np.concatenate([smooth, smooth]) & (other == 0)
    keep = seg > 0
    total = np.bincount(seg[keep], minlength=n)
    going = np.bincount(seg[keep], cont[keep], minlength=n)
    out: np.ndarray = going > share * total
    out[0] = False
    return out
