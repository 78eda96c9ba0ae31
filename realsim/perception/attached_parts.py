"""Parts of one object that a camera view segments apart: a handle, a container's inside.

In a view, a pitcher's handle, a mug's handle or a bowl's inside can come out as clusters of
their own, each "resting on" its body (the body lies under its lowest points). A thing that
truly rests on another meets it at its own foot, over the other's top (a can on a box); a
part meets its body elsewhere: a handle along its height, a container's inside around its
rim, above its lowest part. Such a cluster is joined to the body it rests on.
"""

from __future__ import annotations

import numpy as np

from realsim.perception.contact_cut import CutParams, supported

__all__ = ["join_attached_parts"]


def join_attached_parts(points: np.ndarray, labels: np.ndarray, height: np.ndarray, a: np.ndarray, b: np.ndarray,
                        resting_on: dict[int, int | None], stand_height: float) -> np.ndarray:
    """Labels (>= 1 objects) with each object that rests on another but is not held up by it at
    its own foot (:func:`realsim.perception.contact_cut.supported`) merged into that other one.

    ``height`` is each point's height above its support (m), (a, b) the links between
    neighbouring points, ``resting_on`` the object each object rests on (None: its support),
    ``stand_height`` (m) the base height up to which an object stands on its support."""
    params = CutParams(stand_height=stand_height)
    root = {o: o for o in resting_on}

    def find(o: int) -> int:
        while root[o] != o:
            o = root[o]
        return o

    out = labels.copy()
    for o in sorted(resting_on):
        below = resting_on[o]
        if below is None:
            continue
        body = find(below)
        group = np.flatnonzero((out == o) | (out == body))
        local = np.full(len(out), -1, dtype=np.int64)
        local[group] = np.arange(len(group))
        side = out[group] == o
        la, lb = local[a], local[b]
        cross = (la >= 0) & (lb >= 0)
        cross &= side[np.maximum(la, 0)] != side[np.maximum(lb, 0)]
        if not cross.any():
            continue
        contact = np.zeros(len(group), dtype=bool)
        contact[la[cross]] = contact[lb[cross]] = True
        if not supported(points[group], height[group], side, contact, params):
            out[out == o] = body
            root[o] = body
    return out
