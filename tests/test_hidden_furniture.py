"""assign_supports: a table's legs under a corner of its top that objects hid are its furniture,
not objects on the floor; a thing on the floor there that does not rise to the top stays. Ground
truth: a generated table (rectangle top, corner cut from the seen polygon, four legs)."""

from __future__ import annotations

import numpy as np

from realsim.perception.segment import SegmentParams, assign_supports
from realsim.scene import SupportPlane


def _box(rng: np.random.Generator, lo: tuple[float, float, float], hi: tuple[float, float, float], n: int) -> np.ndarray:
    return rng.uniform(lo, hi, (n, 3))


def _plane(pid: int, kind: str, height: float, polygon: np.ndarray, size: tuple[float, float]) -> SupportPlane:
    return SupportPlane(pid, kind, np.array([0.0, 0.0, 1.0]), height, polygon, np.zeros(2), np.array(size), 0.0, 1000)


def test_legs_under_a_hidden_corner_are_furniture() -> None:
    rng = np.random.default_rng(0)
    floor = _plane(1, "floor", 0.0, np.array([[-2.0, -2.0], [2.0, -2.0], [2.0, 2.0], [-2.0, 2.0]]), (4.0, 4.0))
    # the seen top: the (+x, +y) corner hidden by objects standing on it; its rectangle is the whole 1.2 x 0.8 top
    seen = np.array([[-0.6, -0.4], [0.6, -0.4], [0.6, -0.3], [0.1, 0.4], [-0.6, 0.4]])
    table = _plane(2, "table", 0.72, seen, (1.2, 0.8))
    hidden_leg = _box(rng, (0.5, 0.3, 0.01), (0.55, 0.35, 0.68), 400)  # up to the top's underside (4 cm slab)
    seen_leg = _box(rng, (-0.55, -0.35, 0.01), (-0.5, -0.3, 0.68), 400)
    can = _box(rng, (0.45, 0.05, 0.01), (0.52, 0.12, 0.12), 200)  # on the floor under the hidden corner, 12 cm tall
    points = np.vstack([hidden_leg, seen_leg, can])
    support, _ = assign_supports(points, [floor, table], SegmentParams())
    legs = slice(0, len(hidden_leg) + len(seen_leg))
    assert (support[legs] == -1).all()  # neither leg stands on the floor as an object
    assert (support[len(hidden_leg) + len(seen_leg):] == 0).all()  # the can stays on the floor


def test_furniture_reaching_past_the_rectangle_is_taken_whole() -> None:
    """The seen top ends 40 cm short of the table's end: its apron and leg there, one connected
    group reaching into the seen rectangle, are furniture past the rectangle too (not cut at its
    edge into a floor object)."""
    rng = np.random.default_rng(1)
    floor = _plane(1, "floor", 0.0, np.array([[-2.0, -2.0], [2.0, -2.0], [2.0, 2.0], [-2.0, 2.0]]), (4.0, 4.0))
    seen = np.array([[-0.6, -0.4], [0.2, -0.4], [0.2, 0.4], [-0.6, 0.4]])  # a 0.8 x 0.8 rectangle
    table = _plane(2, "table", 0.72, seen, (0.8, 0.8))
    table.rect_center = np.array([-0.2, 0.0])
    apron = _box(rng, (0.0, 0.38, 0.62), (0.6, 0.40, 0.68), 1500)  # along the long side, past the seen end
    leg = _box(rng, (0.5, 0.3, 0.01), (0.55, 0.35, 0.68), 400)
    support, _ = assign_supports(np.vstack([apron, leg]), [floor, table], SegmentParams())
    assert (support == -1).all()
