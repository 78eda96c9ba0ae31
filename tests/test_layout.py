"""Seeded layout: objects inside the support, apart, and (for robot scenes) within reach of one edge."""

from __future__ import annotations

import numpy as np

from realsim.composition.layout import LayoutParams, declared_support, place_on_support, reach_anchor
from realsim.geometry import polygons_apart
from realsim.perception.capture_config import DeclaredSupport

SQUARE = np.array([[-0.04, -0.04], [0.04, -0.04], [0.04, 0.04], [-0.04, 0.04]])


def _layout(n: int, params: LayoutParams, seed: int = 0) -> list[np.ndarray]:
    support = declared_support(DeclaredSupport(size=(1.2, 0.8), height=0.75))
    poses = place_on_support([SQUARE] * n, support, [], np.random.default_rng(seed), params)
    return [SQUARE @ np.array([[np.cos(y), np.sin(y)], [-np.sin(y), np.cos(y)]]) + xy for xy, y in poses]


def test_reach_region_keeps_objects_near_one_long_edge() -> None:
    support = declared_support(DeclaredSupport(size=(1.2, 0.8), height=0.75))
    anchor = reach_anchor(support)
    assert np.allclose(anchor, [0.0, -0.4])
    for seed in range(5):
        polys = _layout(6, LayoutParams(reach_radius=0.5), seed)
        assert all(np.linalg.norm(p - anchor, axis=1).max() <= 0.5 + 1e-9 for p in polys)
        assert all(polygons_apart(a, b, 0.04 - 1e-9) for i, a in enumerate(polys) for b in polys[i + 1:])
    spread = np.vstack(_layout(6, LayoutParams(), 0))
    assert np.linalg.norm(spread - anchor, axis=1).max() > 0.5  # without the region they use the whole table


def test_reach_region_falls_back_to_the_whole_support_when_full() -> None:
    polys = _layout(15, LayoutParams(reach_radius=0.2))
    assert len(polys) == 15  # 15 squares do not fit in a 0.2 m half disc: the whole table is used
    assert np.linalg.norm(np.vstack(polys) - np.array([0.0, -0.4]), axis=1).max() > 0.2
