"""Which stroke to push: the asked one, or the nearest within the asked move's tolerance that
shoves nothing.

A push is judged by :func:`realsim.planner.relations.moved`: about the asked distance along the
asked direction, a little sideways allowed. When the straight stroke would run the object into a
neighbour, a person pushes a little less far or a little askew, so that it still ends where
asked; these functions propose such strokes and check each one's swept footprint against the
other objects. Only contacts a stroke makes count: a neighbour the object touches at the start
and moves away from is not shoved.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from realsim.planner.relations import moved_tolerance

__all__ = ["StrokeParams", "first_contact", "strokes"]


@dataclass(frozen=True)
class StrokeParams:
    """The strokes a push may try besides the asked one."""

    angles: tuple[float, ...] = (0.0, 0.2, -0.2, 0.35, -0.35)  # rad off the asked direction
    shorter: tuple[float, ...] = (0.4, 0.7)  # of the along tolerance a stroke may fall short by
    within: float = 0.8  # of the sideways tolerance a stroke may use (the object drifts a little more)
    support_fraction: float = 0.5  # of the way from the footprint's centre to its edge that must stay over its support at the stroke's end
    level_probe: float = 0.01  # m above the object's bottom its support is looked for from
    level_tol: float = 0.01  # m: the surface there is the one it stands on (not the floor past a table's edge)


def _turn(d: np.ndarray, angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.array([c * d[0] - s * d[1], s * d[0] + c * d[1]])


def strokes(d: np.ndarray, distance: float, params: StrokeParams = StrokeParams()) -> list[tuple[np.ndarray, float]]:
    """(unit xy direction, length) of strokes whose end lies within the tolerance of a move of
    ``distance`` along the unit ``d``, the asked stroke first, then by how far each ends from it."""
    along_tol, side_tol = moved_tolerance(distance)
    cands: list[tuple[float, np.ndarray, float]] = []
    for angle in params.angles:
        for along in (distance, *(distance - f * along_tol for f in params.shorter)):
            length = along / np.cos(angle)
            if along > 0 and length * abs(np.sin(angle)) <= params.within * side_tol:
                cands.append((distance - along + length * abs(np.sin(angle)), _turn(d, angle), float(length)))
    cands.sort(key=lambda c: c[0])
    return [(u, length) for _, u, length in cands]


def first_contact(foot: np.ndarray, others: np.ndarray, d: np.ndarray, distance: float, touch_gap: float, step: float,
                  nudge: float) -> tuple[float, int] | None:
    """(distance pushed, index into ``others``) where the footprint ``foot`` (xy points) swept
    along ``d`` first comes within ``touch_gap`` of a point of ``others`` it did not touch at the
    start, before the last ``nudge`` of the stroke; None when it shoves nothing."""
    if not len(others):
        return None
    tree = cKDTree(others)
    touching = {i for near in tree.query_ball_point(foot, touch_gap) for i in near}
    for k in np.linspace(0.0, distance, max(2, int(distance / step) + 1))[1:]:
        if k > distance - nudge + 1e-9:
            break
        new = {i for near in tree.query_ball_point(foot + k * d, touch_gap) for i in near} - touching
        if new:
            return float(k), min(new)
    return None
