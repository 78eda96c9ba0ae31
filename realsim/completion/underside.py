"""The hidden underside of a body lying on its support: the visible upper side mirrored below its widest level.

A camera above sees a lying body (a marker, a banana, a bottle on its side) from above and from one
side. Extruded straight down to the support its round cross-section becomes its bounding rectangle
(a lying cylinder so completed fills 4 / pi of its volume). A body resting on a support touches it
along a narrow contact: below the level where its side is widest (where the side seen from above
turns vertical: its silhouette from above) its underside mirrors the visible upper side about that
level, bounded by the support. A side seen vertical down to the support (a box lying flat) keeps
its full width there: mirrored about any level at most halfway up, a box is its own image. Where
the camera did not see the side below that level it may as well go on widening down to the support
(a banana lying on its flat side): extruded, as before.

A section turned about the body's long axis (an oval bottle resting on its flank) is widest at
different heights on its two sides. Its section is centrally symmetric (an ellipse, a rectangle, a
circle), so the widest points of its two sides are images of each other through the centre, halfway
up: a side seen widest low has the other side widest as high above the middle. The far side, seen
only above where the line of sight grazes it, is mirrored about that level, not about the near
side's (which extruded its grazing line nearly down to the support, a wall the section never
reaches), and its underside is the image of the near upper side through the centre (the middle of
the seen lateral extent, halfway up). A section counts as turned when it is widest below its middle
on one side and its top lies off its lateral middle; the body lies turned when most of its seen
points are in such sections (its hull spans them all: one section walled down is a wall along it).
"""

from __future__ import annotations

import numpy as np


def underside_floors(points: np.ndarray, base_z: float, top_z: float, slab: float, max_height_share: float,
                     edge: float, central: bool = False) -> np.ndarray | None:
    """The height down to which each of ``points`` (world frame) is extruded: its mirror image about
    the widest level of its slice, at least ``base_z``, at most its own height (a point below the
    widest level is not extruded: the mirrored upper side bounds the body there).

    The body is cut into slices about ``slab`` long across its principal horizontal axis. In each the
    widest level is the median height of the points within ``edge`` of either lateral extreme (the
    silhouette from above: a round side is widest at its middle, a side seen vertical or flaring
    down is widest low), the lower of the two sides, at most halfway between ``base_z`` and the
    slice's top (a body is no narrower at its contact than its mirror image); the support, when no
    point of the slice was seen below that level (the side was not seen turning in). With ``central``,
    in a body lying turned (see the module notes) only the side widest at that level (the lower one)
    is mirrored about it; the points of the other half (beyond the middle of the slice's lateral
    extent) about that level's image through the middle height, unless that side was seen widest
    lower, and no lower than the image of the near upper side through the section's centre. None when
    the body is not lying: higher than ``max_height_share`` of its longest horizontal extent, or too
    few points.
    """
    kept = points[:, 2] <= top_z
    if np.count_nonzero(kept) < 30:
        return None
    xy = points[:, :2] - points[kept, :2].mean(axis=0)
    _, _, vt = np.linalg.svd(xy[kept], full_matrices=False)
    s, t = xy @ vt[0], xy @ vt[1]
    length = float(np.percentile(s[kept], 99.5) - np.percentile(s[kept], 0.5))
    if top_z - base_z >= max_height_share * length:
        return None  # upright: its sides are the silhouette, seen (or mirrored) down to the support
    count = max(1, int(round(length / slab)))
    edges = np.linspace(float(s[kept].min()), float(s[kept].max()), count + 1)
    slot = np.clip(np.searchsorted(edges, s, side="right") - 1, 0, count - 1)
    widest = np.full((count, 2), np.nan)  # per slice: the level of the half toward -t and toward +t
    split = np.zeros(count)  # per slice: the middle of its lateral extent, between the halves
    imaged = np.full(len(points), -np.inf)  # per point: the floor its half's image through the section's centre gives
    sections: list[tuple[int, np.ndarray, list[float], float, float, bool]] = []  # the slices seen turning in
    for k in range(count):
        inside = kept & (slot == k)
        if np.count_nonzero(inside) < 10:
            continue
        zs, ts = points[inside, 2], t[inside]
        top = float(np.percentile(zs, 98))
        sides = [float(np.median(zs[sign * ts >= np.max(sign * ts) - edge])) for sign in (-1.0, 1.0)]
        half = 0.5 * (base_z + top)
        middle = min(half, *sides)
        widest[k] = middle if float(np.min(zs)) < middle else base_z  # the side not seen turning in below it: extruded
        split[k] = 0.5 * (float(ts.min()) + float(ts.max()))
        if central and widest[k, 0] > base_z:
            sections.append((k, np.flatnonzero(inside), sides, half, middle, _turned(zs, ts, top, middle, half, split[k], edge)))
    weight = sum(len(idx) for _, idx, *_ in sections)
    if weight and sum(len(idx) for _, idx, *_, turned in sections if turned) >= 0.5 * weight:  # the body lies turned: every section is
        for k, idx, sides, half, middle, _ in sections:
            if middle >= half - edge:
                continue  # this section is widest at its middle on both sides: mirrored about it
            other = int(np.argmax(sides))  # the side widest higher: its image through the centre (see the module notes)
            widest[k, other] = max(middle, min(2.0 * half - middle, sides[other]))
            imaged[idx] = _imaged_floors(points[idx, 2], t[idx], split[k], half, 2 * other - 1, edge)
    if np.all(np.isnan(widest)):
        return None
    known = np.flatnonzero(~np.isnan(widest[:, 0]))
    widest = np.column_stack([np.interp(np.arange(count), known, widest[known, j]) for j in (0, 1)])  # a slice too thinly seen: its neighbours'
    split = np.interp(np.arange(count), known, split[known])
    level = widest[slot, (t > split[slot]).astype(np.int64)]
    floors = np.maximum(2.0 * level - points[:, 2], imaged)
    return np.asarray(np.clip(floors, base_z, points[:, 2]))


def _turned(zs: np.ndarray, ts: np.ndarray, top: float, middle: float, half: float, split: float, edge: float) -> bool:
    """Whether a slice's section is turned about the long axis: widest below its middle height on one
    side (by more than ``edge``) and its top (the points within ``edge`` of it) off its lateral middle
    by more than a sixth of its width (an upright round or box section has its top over its middle)."""
    width = float(np.ptp(ts))
    crest = float(np.median(ts[zs >= top - edge]))
    return middle < half - edge and abs(crest - split) > width / 6

def _imaged_floors(zs: np.ndarray, ts: np.ndarray, split: float, half: float, far: int, edge: float) -> np.ndarray:
    """Per point of a turned slice: the floor the image of the other half's upper side through the
    section's centre (``split``, ``half``) gives the points of the ``far`` half (its sign along t): the
    lower side below a far point is the image of the upper side as far on the near side; -inf for the
    near half's points and where no near point was seen that far out (nothing to image)."""
    out = np.full(len(zs), -np.inf)
    near = far * (ts - split) < 0
    if np.count_nonzero(near) < 5:
        return out
    cells = np.floor((ts[near] - split) / edge).astype(np.int64)
    order = np.argsort(cells)
    keys, first = np.unique(cells[order], return_index=True)
    upper = np.maximum.reduceat(zs[near][order], first)  # the near half's upper side, per lateral cell
    centres = split + (keys + 0.5) * edge
    mirror = 2.0 * split - ts  # where a far point's image lies on the near side
    lo, hi = float(centres.min()), float(centres.max())
    within = ~near & (mirror >= lo) & (mirror <= hi)
    out[within] = 2.0 * half - np.interp(mirror[within], centres, upper)
    return out
