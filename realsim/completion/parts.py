"""Parts of one open round container, segmented as two objects, are completed as one.

Segmentation can split a bowl or a mug where its surface turns away from the camera: the two
halves of its rim, or its outer wall and its inside seen over the rim. The points of such parts lie
on one rim circle: the top band of the two together is one ring (a circle, not a filled disc: an open
top) spanning at least half a turn (an object in front may hide the rest of it, and the ring's middle
between the parts: parts are tested up to a rim's largest diameter apart), and each part has points on
that circle. Two neighbours that are not one container fail that
test: two cups side by side have two rims, a box beside a bowl no circle at all, two halves of a
closed can a filled disc on top, and a fruit lying in a bowl has no points on its rim.

The lower outside of a bowl's near wall, where it curves in under the rim, may be split off with no
point on the rim. Such a part is the container's wall when the container alone is open and round
(a rim circle over a hollow top), and the part lies under its rim, on the camera's side of its axis
and outside its cavity: the lines of sight to it enter the rim's vertical cylinder below the rim
(into the cavity the camera sees only over the rim: a fruit lying in the bowl is seen so).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from realsim.completion.containers import ContainerParams, cavity_floor, round_rim
from realsim.forkmap import fork_map
from realsim.scene import Scene, SceneObject

SHARED_PAIRS = 16  # fewer pairs: their verdicts are made here (most are rejected by their gap at once; a fork costs several)
RIM_BAND = 0.15  # the rim: the top this share of the height, within this share of the radius of the circle
MIN_RIM_POINTS = 15  # each part holds at least this many points on the rim circle


def _base(scene: Scene, obj: SceneObject, pts: np.ndarray) -> float:
    return scene.plane(obj.support_id).height if obj.support_id is not None else float(np.min(pts[:, 2]))


def one_container(a: np.ndarray, b: np.ndarray, base_z: float, max_radius: float) -> bool:
    """True when the points ``a`` and ``b`` of two objects are parts of one open round container:
    together their top band is one circular ring (see :func:`round_rim`), and each has points on it."""
    top_z = float(np.percentile(np.concatenate([a[:, 2], b[:, 2]]), 98))
    height = top_z - base_z
    if height <= 0:
        return False
    high = [part[:, 2] >= top_z - RIM_BAND * height for part in (a, b)]
    if any(np.count_nonzero(h) < MIN_RIM_POINTS for h in high):  # too few in the top band: none can be on the rim
        return False
    rim = round_rim(np.vstack([a, b]), base_z, top_z, max_radius)
    if rim is None:
        return False
    centre, radius = rim
    for part, h in zip((a, b), high):
        on_rim = h & (np.abs(np.linalg.norm(part[:, :2] - centre, axis=1) - radius) <= RIM_BAND * radius)
        if np.count_nonzero(on_rim) < MIN_RIM_POINTS:
            return False
    return True


@dataclass(frozen=True)
class OpenRim:
    """The rim of an open round container: its top height, height over its base, centre and radius."""

    top_z: float
    height: float
    centre: np.ndarray
    radius: float


def open_rim(container: np.ndarray, base_z: float, max_radius: float, camera: np.ndarray,
             params: ContainerParams = ContainerParams()) -> OpenRim | None:
    """The rim of the points ``container`` when they are an open round container with a cavity seen
    from ``camera`` (None otherwise)."""
    top_z = float(np.percentile(container[:, 2], 98))
    height = top_z - base_z
    rim = round_rim(container, base_z, top_z, max_radius) if height > 0 else None
    if rim is None:
        return None
    centre, radius = rim
    if np.linalg.norm(camera[:2] - centre) < 1e-6 or cavity_floor(container, centre, radius, height, params, camera[:2], float(camera[2])) is None:
        return None
    return OpenRim(top_z, height, centre, radius)


def wall_under_rim(rim: OpenRim, part: np.ndarray, camera: np.ndarray) -> bool:
    """True when the points ``part`` are the outside of the near wall under ``rim``, seen from ``camera``."""
    rel = part[:, :2] - rim.centre
    toward = camera[:2] - rim.centre
    under = (np.linalg.norm(rel, axis=1) <= (1 + RIM_BAND) * rim.radius) & (part[:, 2] < rim.top_z - RIM_BAND * rim.height) & (rel @ toward > 0)
    if np.mean(under) < 1 - RIM_BAND:
        return False
    return bool(np.median(_entry_height(camera, part, rim.centre, rim.radius)) < rim.top_z - RIM_BAND * rim.height)


def outer_wall_part(container: np.ndarray, part: np.ndarray, base_z: float, max_radius: float, camera: np.ndarray,
                    params: ContainerParams = ContainerParams()) -> bool:
    """True when the points ``part`` are the outside of the near wall under the rim of the open round
    container whose points are ``container`` (see the module's notes), seen from ``camera``."""
    rim = open_rim(container, base_z, max_radius, camera, params)
    return rim is not None and wall_under_rim(rim, part, camera)


def _entry_height(camera: np.ndarray, points: np.ndarray, centre: np.ndarray, radius: float) -> np.ndarray:
    """Where the line of sight to each point enters the vertical cylinder of ``radius`` about ``centre``:
    its height there (-inf when it reaches the point without entering: the point is outside). Inside
    an open container, the camera sees only what its lines of sight reach over the rim."""
    c = camera[:2] - centre
    d = points[:, :2] - camera[:2]
    a, b, k = np.einsum("ij,ij->i", d, d), d @ c, float(c @ c) - radius * radius
    disc = b * b - a * k
    t = (-b - np.sqrt(np.maximum(disc, 0.0))) / np.maximum(a, 1e-12)
    enters = (disc > 0) & (t >= 0) & (t <= 1)
    return np.where(enters, camera[2] + t * (points[:, 2] - camera[2]), -np.inf)


def merge_container_parts(scene: Scene, max_radius: float, params: ContainerParams = ContainerParams(),
                          camera: np.ndarray | None = None) -> list[tuple[int, int]]:
    """Give the pixels of every object that is a part of the same open round container as another
    (see :func:`one_container`, and with the ``camera`` centre :func:`outer_wall_part`) that object's id and
    drop it from ``scene.objects``; the (kept, merged) id pairs. Objects standing on something else,
    or on different supports, are never merged."""
    if scene.labels is None or scene.points is None or not params.enabled:
        return []
    labels, points = scene.labels, scene.points
    merged: list[tuple[int, int]] = []
    rims: dict[tuple[int, float], OpenRim | None] = {}  # (object id, base height): its rim, while its points stay
    verdicts: dict[tuple[int, int], str | None] = {}  # (object id, object id): why they are one container, or None

    def is_wall(container: SceneObject, part: SceneObject, base_z: float) -> bool:
        assert camera is not None
        key = (container.id, base_z)
        if key not in rims:
            rims[key] = open_rim(pts[container.id], base_z, max_radius, camera, params)
        rim = rims[key]
        return rim is not None and wall_under_rim(rim, pts[part.id], camera)

    def joined(a: SceneObject, b: SceneObject) -> str | None:
        pa, pb = pts[a.id], pts[b.id]
        if a.support_id != b.support_id or len(pa) == 0 or len(pb) == 0:
            return None
        gap = np.maximum(pa[:, :2].min(axis=0) - pb[:, :2].max(axis=0), pb[:, :2].min(axis=0) - pa[:, :2].max(axis=0))
        base_z = _base(scene, a, pa)
        if np.any(gap > 2 * max_radius):  # farther apart than a rim's diameter
            return None
        if one_container(pa, pb, base_z, max_radius):
            return "their top is one ring"
        if camera is not None and (is_wall(a, b, base_z) or is_wall(b, a, base_z)):
            return "one is the outside of the other's near wall under its rim"
        return None

    changed, first = True, True
    while changed:
        changed = False
        objects = [o for o in scene.objects if o.resting_on is None]
        pts = {o.id: points[labels == o.id] for o in objects}
        if first:  # a pair's verdict reads only its two objects' points, unchanged until one is merged (then it is
            first = False  # dropped): every first verdict made at once, shared with a forked helper
            pairs = [(a, b) for i, a in enumerate(objects) for b in objects[i + 1:]]
            verdicts.update(zip([(a.id, b.id) for a, b in pairs], fork_map(lambda k: joined(*pairs[k]), len(pairs), least=SHARED_PAIRS)))
        for i, a in enumerate(objects):
            for b in objects[i + 1:]:
                if (a.id, b.id) not in verdicts:
                    verdicts[(a.id, b.id)] = joined(a, b)
                why = verdicts[(a.id, b.id)]
                if why is None:
                    continue
                pa, pb = pts[a.id], pts[b.id]
                keep, gone = (a, b) if len(pa) >= len(pb) else (b, a)
                stale = {keep.id, gone.id}  # the kept object's points grow: what was found of the others stays
                for key in [k for k in rims if k[0] in stale]:
                    del rims[key]
                for pair in [k for k in verdicts if stale & set(k)]:
                    del verdicts[pair]
                labels[labels == gone.id] = keep.id
                keep.point_count += gone.point_count
                scene.objects = [o for o in scene.objects if o.id != gone.id]
                for o in scene.objects:
                    if o.resting_on == gone.id:
                        o.resting_on = keep.id
                keep.notes.append(f"joined with object {gone.id}: parts of one open round container ({why})")
                merged.append((keep.id, gone.id))
                changed = True
                break
            if changed:
                break
    return merged
