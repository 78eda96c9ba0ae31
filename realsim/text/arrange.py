"""Place the objects of a described scene so its relations hold and everything can rest.

Objects that stand on a support are placed first (by seeded rejection sampling, largest first,
apart by a gripper's clearance, those in a row as one unit, and each relation to an already
placed object as a region to sample in: left of, right of, behind, in front of, next to; an
object whose relation cannot be met is placed anywhere, with a warning). Then, parents before
children, objects on or in another object are lowered onto it (:func:`realsim.composition.layout.rest_height`,
exact on the convex pieces): stacked instances centred on the one below, contents at the lowest
free spot inside the container's cavity (its floor, then on each other), objects "on" a thing
at the lowest free spot on its top.

Directions are seen from the support's front edge (local -y): left -x, right +x, behind +y.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from realsim.composition.layout import LayoutParams, footprint, hull_pieces, reach_anchor, rest_contact, vertical_extent
from realsim.geometry import inside_convex_polygon, polygons_apart
from realsim.scene import SupportPlane

NEAR = 0.12  # m: "next to" means footprints at most this far apart


@dataclass
class Item:
    """One object instance to place (object frame: base centre at the origin)."""

    key: str  # unique instance key
    hulls: list[np.ndarray]  # convex pieces, object frame
    support: int | None = None  # support plane id when it stands on a support
    parent: str | None = None  # item key it rests on or in
    inside: bool = False  # in the parent's cavity (else on it)
    stacked: bool = False  # centred on the parent (a stack)
    relations: list[tuple[str, str]] = field(default_factory=list)  # (relation, item key)
    group: str | None = None  # items of one row share a group
    fixed_yaw: bool = False
    position: tuple[float, float] | None = None  # preferred (x, y) in [0, 1] on the support (a photo)
    extra: list[np.ndarray] = field(default_factory=list)  # more pieces moving with it (an articulated child), object frame
    local_print: np.ndarray | None = None  # footprint polygon in the object frame (a cache of _print)
    xy: np.ndarray | None = None
    yaw: float = 0.0
    z: float = 0.0


def _rot(yaw: float) -> np.ndarray:
    c, s = np.cos(yaw), np.sin(yaw)
    return np.array([[c, -s], [s, c]])


def _print(item: Item, xy: np.ndarray, yaw: float) -> np.ndarray:
    """The item's footprint polygon at (``xy``, ``yaw``): its own footprint (computed once) moved there."""
    if item.local_print is None:
        item.local_print = footprint(np.vstack([h[:, :2] for h in item.hulls + item.extra]))
    return item.local_print @ _rot(yaw).T + xy


def world_hulls(item: Item) -> list[np.ndarray]:
    """The item's own convex pieces where it stands (not the room kept for a drawer's travel)."""
    assert item.xy is not None
    r = _rot(item.yaw)
    return [np.column_stack([h[:, :2] @ r.T + item.xy, h[:, 2] + item.z]) for h in item.hulls]


def _local(support: SupportPlane, xy: np.ndarray) -> np.ndarray:
    """World xy -> the support rectangle's frame (centre at 0, x along its width)."""
    return support.rect_local(xy)


def _relation_ok(rel: str, poly: np.ndarray, other: np.ndarray, support: SupportPlane) -> bool:
    a, b = _local(support, poly), _local(support, other)
    ca, cb = a.mean(axis=0), b.mean(axis=0)
    overlap_y = a[:, 1].min() < b[:, 1].max() + 0.05 and b[:, 1].min() < a[:, 1].max() + 0.05
    overlap_x = a[:, 0].min() < b[:, 0].max() + 0.05 and b[:, 0].min() < a[:, 0].max() + 0.05
    # clearly on that side: the centre beyond the other's edge, the two side by side (not diagonal)
    if rel == "left_of":
        return ca[0] <= b[:, 0].min() and overlap_y
    if rel == "right_of":
        return ca[0] >= b[:, 0].max() and overlap_y
    if rel == "behind":
        return ca[1] >= b[:, 1].max() and overlap_x
    if rel == "in_front_of":
        return ca[1] <= b[:, 1].min() and overlap_x
    if rel == "next_to":
        return not polygons_apart(a, b, NEAR) and float(np.linalg.norm(ca - cb)) < 0.5
    return True


def _sample_xy(rng: np.random.Generator, lo: np.ndarray, hi: np.ndarray, item: Item, support: SupportPlane, k: int) -> np.ndarray:
    """Uniform in [lo, hi], or near the item's preferred photo position (tightening with k)."""
    if item.position is None:
        return rng.uniform(lo, hi)
    half = np.asarray(support.rect_size) / 2
    local = (np.asarray(item.position) * 2 - 1) * half * 0.8
    spread = 0.02 + 0.25 * min(k / 300, 1.0)
    return support.rect_center + _rot(support.rect_yaw) @ local + rng.normal(0.0, spread, 2)


def _near(rng: np.random.Generator, relation: tuple[str, str], placed: dict[str, np.ndarray], support: SupportPlane) -> np.ndarray:
    """A position on the named side of an object already placed (support frame: left -x, behind +y)."""
    rel, target = relation
    b = _local(support, placed[target])
    lo, hi = b.min(axis=0), b.max(axis=0)
    c = (lo + hi) / 2
    gap = float(rng.uniform(0.05, 0.35))
    side = {"left_of": np.array([lo[0] - gap, c[1]]), "right_of": np.array([hi[0] + gap, c[1]]),
            "behind": np.array([c[0], hi[1] + gap]), "in_front_of": np.array([c[0], lo[1] - gap])}
    if rel in side:
        local = side[rel] + rng.normal(0.0, 0.04, 2)
    else:  # next to: any side, just beyond the target's edge
        angle = float(rng.uniform(-np.pi, np.pi))
        local = c + np.array([np.cos(angle), np.sin(angle)]) * (float(np.max(hi - lo)) / 2 + gap * 0.6)
    return support.rect_center + _rot(support.rect_yaw) @ local


def place_roots(items: list[Item], support: SupportPlane, obstacles: list[np.ndarray], rng: np.random.Generator,
                params: LayoutParams, region: tuple[np.ndarray, np.ndarray] | None = None) -> list[str]:
    """Place the items standing on ``support``; returns warnings. Items of a row move as one; the
    whole support is laid out again (up to :data:`RELATION_RETRIES` times) until every relation holds."""
    units: dict[str, list[Item]] = {}
    for it in items:
        units.setdefault(it.group or it.key, []).append(it)
    keys = {it.key for it in items}

    def depth(u: list[Item]) -> int:
        return sum(1 for it in u for _, t in it.relations if t in keys)

    order = sorted(units, key=lambda k: (depth(units[k]), -_unit_area(units[k])))
    best: tuple[int, dict[str, tuple], list[str]] | None = None
    retries = RELATION_RETRIES if any(depth(u) for u in units.values()) else 1
    for attempt in range(retries):  # a layout keeping every relation, if one is found (the later half anywhere on the support)
        narrow = params if attempt < max(retries // 2, 1) else replace(params, reach_radius=None)
        try:
            misses = _place_units(units, order, support, obstacles, rng, narrow, region, keys)
        except _NoRoom:
            if best is None:
                raise
            break
        if best is None or len(misses) < best[0]:
            best = (len(misses), {it.key: (it.xy, it.yaw, it.z) for it in items}, misses)
        if not misses:
            break
    assert best is not None
    for it in items:
        it.xy, it.yaw, it.z = best[1][it.key]
    return list(best[2])


RELATION_RETRIES = 8


def _place_units(units: dict[str, list[Item]], order: list[str], support: SupportPlane, obstacles: list[np.ndarray],
                 rng: np.random.Generator, params: LayoutParams, region: tuple[np.ndarray, np.ndarray] | None, keys: set[str]) -> list[str]:
    """One seeded pass over the units; returns the relations it could not keep."""
    warnings: list[str] = []
    placed: dict[str, np.ndarray] = {}
    polys: list[np.ndarray] = list(obstacles)
    for key in order:
        unit = units[key]
        offsets = _row_offsets(unit)
        wanted = [(rel, t) for it in unit for rel, t in it.relations if t in placed]
        for relax in (False, True):
            ok = _try_place(unit, offsets, support, polys, placed, wanted if not relax else [], rng, params, region)
            if ok:
                break
            if not relax and wanted:
                warnings.append(f"{unit[0].key}: could not keep {', '.join(r.replace('_', ' ') + ' ' + t for r, t in wanted)}; placed elsewhere")
        else:
            raise _NoRoom(unit[0].key)
        for it in unit:
            placed[it.key] = _print(it, it.xy, it.yaw)  # type: ignore[arg-type]
            polys.append(placed[it.key])
    return warnings


class _NoRoom(Exception):
    pass


def _unit_area(unit: list[Item]) -> float:
    """Footprint box area of a unit (sort key: largest first)."""
    pts = np.vstack([h[:, :2] for it in unit for h in it.hulls])
    span = pts.max(axis=0) - pts.min(axis=0)
    return float(span[0] * span[1]) * len(unit)


def _row_offsets(unit: list[Item]) -> list[np.ndarray]:
    """x offsets of a row's members (side by side, 2 cm apart), centred."""
    if len(unit) == 1:
        return [np.zeros(2)]
    widths = [float(np.ptp(np.concatenate([h[:, 0] for h in it.hulls]))) for it in unit]
    xs, x = [], 0.0
    for w in widths:
        xs.append(x + w / 2)
        x += w + 0.02
    mid = x / 2
    return [np.array([v - mid, 0.0]) for v in xs]


def _try_place(unit: list[Item], offsets: list[np.ndarray], support: SupportPlane, polys: list[np.ndarray], placed: dict[str, np.ndarray],
               wanted: list[tuple[str, str]], rng: np.random.Generator, params: LayoutParams, region: tuple[np.ndarray, np.ndarray] | None) -> bool:
    lo, hi = (support.polygon.min(axis=0), support.polygon.max(axis=0)) if region is None else region
    anchor = reach_anchor(support) if params.reach_radius is not None and support.kind != "floor" else None
    attempts = params.attempts_per_object * (3 if wanted else 1)
    for use_anchor in ((True, False) if anchor is not None else (False,)):
        a_lo, a_hi = (np.maximum(lo, anchor - params.reach_radius), np.minimum(hi, anchor + params.reach_radius)) if use_anchor else (lo, hi)
        for k in range(attempts):
            yaw = 0.0 if (unit[0].fixed_yaw or len(unit) > 1 or not params.random_yaw) else float(rng.uniform(-np.pi, np.pi))
            if len(unit) > 1:
                yaw = support.rect_yaw
            xy = _near(rng, wanted[k % len(wanted)], placed, support) if wanted and k % 2 == 0 else _sample_xy(rng, a_lo, a_hi, unit[0], support, k)
            ok = True
            prints = []
            for it, off in zip(unit, offsets):
                p = _print(it, xy + _rot(yaw) @ off, yaw)
                if not np.all(inside_convex_polygon(p, support.polygon, -params.edge_margin)):
                    ok = False
                    break
                if use_anchor and np.linalg.norm(p - anchor, axis=1).max() > params.reach_radius:
                    ok = False
                    break
                if region is not None and (np.any(p < region[0]) or np.any(p > region[1])):
                    ok = False
                    break
                if not all(polygons_apart(p, other, params.clearance) for other in polys):  # a row's members stand closer
                    ok = False
                    break
                prints.append(p)
            if not ok:
                continue
            whole = np.vstack(prints)
            if not all(_relation_ok(rel, whole, placed[t], support) for rel, t in wanted):
                continue
            for it, off in zip(unit, offsets):
                it.xy, it.yaw, it.z = xy + _rot(yaw) @ off, yaw, support.height
            return True
    return False


def cavity_polygon(item: Item, step: float = 0.004) -> np.ndarray | None:
    """The xy polygon (world) over the item's open cavity: where its top surface lies well below
    its rim; None when it has none."""
    hulls = world_hulls(item)
    eqs = hull_pieces(hulls)
    pts = np.vstack([h[:, :2] for h in hulls])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    n = np.minimum(np.maximum(np.ceil((hi - lo) / step).astype(int), 3), 100)
    gx, gy = np.meshgrid(np.linspace(lo[0], hi[0], n[0]), np.linspace(lo[1], hi[1], n[1]))
    xy = np.column_stack([gx.ravel(), gy.ravel()])
    _, top = vertical_extent(eqs, xy)
    zmax = float(np.nanmax(top))
    base = float(np.nanmin(vertical_extent(eqs, xy)[0]))
    deep = xy[np.isfinite(top) & (top < zmax - 0.4 * (zmax - base))]
    if len(deep) < 4:
        return None
    return footprint(deep)


def place_children(items: list[Item], placed: dict[str, Item], rng: np.random.Generator, clearance: float = 0.002,
                   tries: int = 60) -> list[str]:
    """Lower each child onto (or into) its parent, parents first; returns warnings."""
    warnings: list[str] = []
    todo = list(items)
    while todo:
        ready = [it for it in todo if it.parent in placed]
        if not ready:
            for it in todo:
                warnings.append(f"{it.key}: what it rests on could not be placed; left out")
            break
        for it in ready:
            todo.remove(it)
            parent = placed[it.parent]  # type: ignore[index]
            below = world_hulls(parent) + [h for other in placed.values() if other.parent == parent.key or other is parent
                                            for h in (world_hulls(other) if other is not parent else [])]
            result = _lower(it, parent, below, rng, tries)
            if result is None:
                warnings.append(f"{it.key}: does not fit {'in' if it.inside else 'on'} {parent.key}; put on top of it")
                it.inside = False
                result = _lower(it, parent, below, rng, tries)
            if result is None:
                warnings.append(f"{it.key}: could not be put on {parent.key}; left out")
                continue
            it.xy, it.yaw, it.z = result
            it.z += clearance
            placed[it.key] = it
    return warnings


def _lower(it: Item, parent: Item, below: list[np.ndarray], rng: np.random.Generator, tries: int) -> tuple[np.ndarray, float, float] | None:
    """(xy, yaw, z) of the lowest resting place found for ``it`` on/in ``parent``."""
    assert parent.xy is not None
    cavity = cavity_polygon(parent) if it.inside else None
    if it.inside and cavity is None:
        return None
    top = np.vstack(world_hulls(parent))
    p_top = float(top[:, 2].max())
    region = cavity if cavity is not None else footprint(top[:, :2])
    lo, hi = region.min(axis=0), region.max(axis=0)
    best = None
    child, under = hull_pieces(it.hulls), hull_pieces(below)
    for k in range(tries if not it.stacked else 8):
        if it.stacked:
            xy = parent.xy + rng.normal(0.0, 0.002, 2)
            yaw = parent.yaw + float(rng.normal(0.0, 0.03))
        else:
            xy = rng.uniform(lo, hi)
            yaw = float(rng.uniform(-np.pi, np.pi))
        poly = _print(it, xy, yaw)
        margin = -0.002 if cavity is not None else 0.0
        if cavity is not None and not np.all(inside_convex_polygon(poly, region, margin)):
            continue
        if cavity is None and not it.stacked and not np.all(inside_convex_polygon(poly.mean(axis=0, keepdims=True), region, -0.01)):
            continue
        found = rest_contact(child, under, xy, yaw)
        if found is None:
            continue
        z, touching = found
        if cavity is not None and z > p_top - 0.004:  # must sit in the cavity, below the rim
            continue
        # prefer resting places whose contacts surround the centre (a knife across a plate's rim slides)
        steady = len(touching) >= 3 and bool(inside_convex_polygon(poly.mean(axis=0, keepdims=True), footprint(touching), -0.005)[0])
        over = cavity is not None or bool(np.all(inside_convex_polygon(poly, region, 0.0)))  # wholly over what it rests on
        key = (not over, not steady, z)
        if best is None or key < best[0]:
            best = (key, (xy, yaw, z))
    return None if best is None else best[1]
