"""Offline names a person can say: the evident colour and shape of a scanned object.

``obj3_red_box``, ``obj5_white_bowl``, ``obj2_tall_blue_can``: the colour is the most common
colour word over the object's own pixels (after a white-patch balance of the whole capture,
since consumer depth cameras see the world blue or yellow); the shape word comes from the
completed solid (round footprint: can, cup, bowl, disc; rectangular: box; else object) and,
for round ones, whether the observed top is hollow. A size-table category replaces the shape
word only when the fit is unambiguous (close, and clearly closer than the runner-up). When two
objects would share a name, they are told apart by size (small/big), then by a second colour,
then by where they are in the view (left/right). A generic name ("red_object") is what a person
may call any object of that colour, so it too gets such a word when another red object exists.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from realsim.colours import colour_words
from realsim.understanding.shape_label import ranked_labels

CATEGORY_MAX_DISTANCE = 0.1  # a size-table fit this close (RMS log extent ratio) ...
CATEGORY_MARGIN = 0.1  # ... and this much closer than the runner-up is unambiguous
SHAPE_ADJECTIVES = frozenset({"tall", "flat"})
GENERIC_SHAPES = frozenset({"object"})  # a shape word that says nothing a person could tell apart by
ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth", "eleventh", "twelfth")


@dataclass(frozen=True)
class Name:
    """An object's offline name and why."""

    label: str  # e.g. "tall_blue_can"
    colour: str
    shape: str
    note: str


def white_balance(colors: np.ndarray) -> np.ndarray:
    """White-patch balance of a whole capture's colours ((N, 3) in [0, 1], NaN allowed): each
    channel scaled so its 99th percentile is white (grey-world fails on scenes dominated by a
    wooden table, which it turns grey and everything else blue)."""
    return balanced(colors, white_point(colors))


def white_point(colors: np.ndarray) -> np.ndarray | None:
    """What :func:`white_balance` divides a capture's colours by (per channel), None when fewer than
    10 colours are finite (then they stay as they are)."""
    c = np.asarray(colors, float)
    ok = np.all(np.isfinite(c), axis=1)
    if ok.sum() < 10:
        return None
    return np.maximum(np.percentile(c[ok], 99, axis=0), 1e-3)


def balanced(colors: np.ndarray, white: np.ndarray | None) -> np.ndarray:
    """``colors`` (some of a capture's) balanced to the capture's ``white`` point (:func:`white_point`):
    each the value :func:`white_balance` gives it."""
    c = np.asarray(colors, float)
    return c if white is None else np.clip(c / white, 0, 1)


def dominant_colours(rgb: np.ndarray) -> list[tuple[str, float]]:
    """Colour words of an object's pixels with their shares, most common first."""
    if len(rgb) == 0:
        return [("grey", 1.0)]
    counts = Counter(colour_words(rgb).tolist())
    total = sum(counts.values())
    return [(w, n / total) for w, n in counts.most_common()]


def is_hollow(points: np.ndarray, centre: np.ndarray, radius: float, height: float) -> bool:
    """An open top: the observed points near the axis lie well below those near the rim."""
    r = np.linalg.norm(points[:, :2] - centre, axis=1)
    inner, rim = points[r < 0.45 * radius], points[(r > 0.75 * radius) & (r < 1.15 * radius)]
    if len(inner) < 20 or len(rim) < 20:
        return False
    return float(np.percentile(rim[:, 2], 90) - np.median(inner[:, 2])) > 0.3 * height


def top_is_rectangle(points: np.ndarray, top_z: float, height: float, min_fill: float = 0.85) -> bool:
    """The observed top face (points within a tenth of the height of the top) fills its minimum-area
    rectangle: a box seen from above, whatever its completed hidden side looks like."""
    top = points[points[:, 2] >= top_z - max(0.01, 0.1 * height)] if len(points) else points
    if len(top) < 30:
        return False
    try:
        hull = ConvexHull(top[:, :2])
        _, extents = trimesh.bounds.oriented_bounds_2D(top[hull.vertices, :2])
    except (QhullError, ValueError):
        return False
    return float(hull.volume) / max(float(np.prod(extents)), 1e-12) >= min_fill


def shape_word(size: np.ndarray, points: np.ndarray, axis_xy: np.ndarray, cylinder: bool, prism: bool,
               open_top: bool = False) -> tuple[str, str, bool, bool]:
    """(shape word, adjective, cylinder, prism) of a completed scan object: ``cylinder`` / ``prism``
    from its solid (:func:`realsim.understanding.shape_label.is_cylinder`, ``is_prism``),
    ``points`` observed (world), ``axis_xy`` the centre of its base; ``open_top`` when the
    completion already built it as an open container (its cavity seen over the rim)."""
    size = np.asarray(size, float)
    width, height = float(max(size[0], size[1])), float(size[2])
    if cylinder:
        ratio = height / max(width, 1e-6)
        hollow = open_top or len(points) > 0 and is_hollow(points, np.asarray(axis_xy, float), width / 2, height)
        if ratio < 0.25:
            return "disc", "", cylinder, prism
        if hollow:
            return ("bowl" if ratio < 0.7 else "cup"), "", cylinder, prism
        return ("can" if ratio >= 0.8 else "cylinder"), ("tall" if ratio >= 1.8 else ""), cylinder, prism
    if prism or top_is_rectangle(points, float(np.max(points[:, 2])) if len(points) else 0.0, height):
        prism = True
        if height < 0.35 * float(np.sort(size[:2])[0]):
            return "box", "flat", cylinder, prism
        return "box", ("tall" if height > 1.8 * width else ""), cylinder, prism
    return "object", "", cylinder, prism


def offline_name(size: np.ndarray, points: np.ndarray, rgb: np.ndarray, axis_xy: np.ndarray, cylinder: bool,
                 prism: bool, open_top: bool = False) -> tuple[Name, list[tuple[str, float]]]:
    """The colour+shape name of one object (or colour+category when the shape is a box or round and
    the size-table fit among categories of that shape is unambiguous)."""
    colours = dominant_colours(rgb)
    colour = colours[0][0]
    word, adjective, cylinder, prism = shape_word(size, points, axis_xy, cylinder, prism, open_top)
    ranked = ranked_labels(size, cylinder, prism=prism) if (cylinder or prism) else []
    dims = " x ".join(f"{v * 1000:.0f}" for v in size)
    if ranked and ranked[0].distance <= CATEGORY_MAX_DISTANCE and (len(ranked) == 1 or ranked[1].distance - ranked[0].distance >= CATEGORY_MARGIN):
        best = ranked[0]
        note = f"name from colour ({colour}, {100 * colours[0][1]:.0f} % of its pixels) and size-table category {best.label!r} (distance {best.distance:.2f}, unambiguous; {dims} mm)"
        return Name(f"{colour}_{best.label}", colour, best.label, note), colours
    label = "_".join(w for w in (adjective, colour, word) if w)
    note = f"name from colour ({colour}, {100 * colours[0][1]:.0f} % of its pixels) and shape ({word}, {dims} mm)"
    return Name(label, colour, word, note), colours


def distinct(names: list[Name], volumes: list[float], colours: list[list[tuple[str, float]]], image_x: list[float | None]) -> list[Name]:
    """``names`` with a discriminating word added wherever two objects would share a name."""
    out = list(names)
    for _ in range(4):  # size, then second colour, then position (and a generic name told apart)
        groups: dict[str, list[int]] = {}
        for i, n in enumerate(out):  # "the white can" would mean a tall white can too: shape adjectives do not tell apart
            groups.setdefault("_".join(w for w in n.label.split("_") if w not in SHAPE_ADJECTIVES), []).append(i)
        clashes = [g for g in groups.values() if len(g) > 1]
        if clashes:
            for group in clashes:
                _disambiguate(out, group, volumes, colours, image_x)
            continue
        generic = _generic_clash(out)
        if generic is None:
            break
        told_apart = list(out)
        _disambiguate(told_apart, generic, volumes, colours, image_x)
        for i in generic:  # only the generic name gets the extra word; "the red box" stays what it was
            if out[i].shape in GENERIC_SHAPES:
                out[i] = told_apart[i]
    return out


def _generic_clash(names: list[Name]) -> list[int] | None:
    """The first bare generic name ("red_object") with the objects of its colour: "the red object"
    is what a person may call any red thing, so the name alone must not single one out."""
    for i, n in enumerate(names):
        if n.shape in GENERIC_SHAPES and n.label == f"{n.colour}_{n.shape}":
            same = [j for j, m in enumerate(names) if m.colour == n.colour]
            if len(same) > 1:
                return same
    return None


def _disambiguate(out: list[Name], group: list[int], volumes: list[float], colours: list[list[tuple[str, float]]], image_x: list[float | None]) -> None:
    vols = np.array([volumes[i] for i in group])
    order = np.argsort(vols)
    if len(group) <= 3 and np.all(vols[order][1:] > 1.3 * vols[order][:-1]):
        words = ["small", "big"] if len(group) == 2 else ["small", "medium", "big"]
        for word, k in zip(words, order):
            i = group[k]
            out[i] = Name(f"{word}_{out[i].label}", out[i].colour, out[i].shape, out[i].note + f"; '{word}' tells it from a look-alike")
        return
    seconds = [next((w for w, share in colours[i][1:] if share >= 0.15 and w != out[i].colour), None) for i in group]
    if all(seconds) and len(set(seconds)) == len(seconds):
        for i, second in zip(group, seconds):
            label = out[i].label.replace(out[i].colour, f"{out[i].colour}_and_{second}", 1)
            out[i] = Name(label, out[i].colour, out[i].shape, out[i].note + f"; second colour {second} tells it from a look-alike")
        return
    xs = [image_x[i] for i in group]
    if all(x is not None for x in xs):
        words = ["left", "right"] if len(group) == 2 else ["left"] + ["middle"] * (len(group) - 2) + ["right"]
        for rank, k in enumerate(np.argsort(xs)):
            i = group[k]
            word = words[rank] if len(group) <= 3 else f"{ORDINALS[min(rank, len(ORDINALS) - 1)]}_from_left"
            out[i] = Name(f"{word}_{out[i].label}", out[i].colour, out[i].shape, out[i].note + f"; '{word}' (in the capture's view) tells it from a look-alike")

