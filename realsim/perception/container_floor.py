"""The floor of a container seen through its opening, claimed from the support.

A bowl's or a mug's inner floor lies a few millimetres over the support it stands on, so a
camera view takes it for support. But the support under a standing container is covered by it:
a patch of support pixels that the image encloses in one object, lying within that object's
outline seen from above and walled in by it (the object stands well above the patch), is that
object's floor. A flat object's holes (scissors' finger loops) show the support itself.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage

from realsim.geometry import inside_convex_polygon, polygon_and_rectangle

__all__ = ["claim_enclosed_floors"]

ENCLOSED_SHARE = 0.9  # of a patch's neighbouring pixels (with depth) belong to the enclosing object
INSIDE_SHARE = 0.9  # of its points lie within that object's outline seen from above
MIN_WALL = 0.02  # m: the enclosing object's top (90th height percentile) stands this much above the patch


def claim_enclosed_floors(labels: np.ndarray, points: np.ndarray, support_pixels: np.ndarray,
                          grid_shape: tuple[int, int]) -> np.ndarray:
    """``labels`` (objects >= 1 over a row-major ``grid_shape`` image) with every connected patch
    of ``support_pixels`` enclosed in the image by one object and within its outline seen from
    above given to that object."""
    h, w = grid_shape
    patches, count = ndimage.label(support_pixels.reshape(h, w))
    if count == 0:
        return labels
    image = labels.reshape(h, w)
    finite = np.isfinite(points).all(axis=1).reshape(h, w)
    out = labels.copy()
    hulls: dict[int, np.ndarray | None] = {}
    tops: dict[int, float] = {}
    for k, box in enumerate(ndimage.find_objects(patches), start=1):
        r0, r1, c0, c1 = box[0].start, box[0].stop, box[1].start, box[1].stop
        if r0 == 0 or c0 == 0 or r1 == h or c1 == w:
            continue  # reaches the image border: not enclosed
        window = (slice(r0 - 1, r1 + 1), slice(c0 - 1, c1 + 1))
        patch = patches[window] == k
        ring = ndimage.binary_dilation(patch) & ~patch & finite[window]
        owners = image[window][ring]
        if len(owners) == 0:
            continue
        values, counts = np.unique(owners, return_counts=True)
        owner = int(values[np.argmax(counts)])
        if owner < 1 or counts.max() < ENCLOSED_SHARE * len(owners):
            continue
        rows, cols = np.nonzero(patch)
        idx = (rows + r0 - 1) * w + (cols + c0 - 1)
        if owner not in tops:
            tops[owner] = float(np.percentile(points[labels == owner, 2], 90))
        if tops[owner] - np.median(points[idx, 2]) < MIN_WALL:
            continue
        if owner not in hulls:
            xy = points[labels == owner, :2]
            try:
                hulls[owner] = polygon_and_rectangle(xy)[0]
            except ValueError:
                hulls[owner] = None
        hull = hulls[owner]
        if hull is not None and inside_convex_polygon(points[idx, :2], hull).mean() >= INSIDE_SHARE:
            out[idx] = owner
    return out
