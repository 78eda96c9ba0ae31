"""The hull budget on a thin curved wall (merging by distance from the scan keeps patches even), and the vertex cap."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import trimesh

from realsim.assets.budget import fewest_hulls, merge_by_surface_error
from realsim.assets.fidelity import parts_fidelity
from realsim.assets.hulls import make_hull
from realsim.assets.params import AssetParams

RADIUS, WALL, HEIGHT, SECTORS = 0.07, 0.003, 0.04, 36


def _ring() -> tuple[trimesh.Trimesh, list[np.ndarray]]:
    """A thin upright ring (a cup's wall) and its 36 sector pieces (vertices, boundaries shared)."""
    ring = trimesh.creation.annulus(r_min=RADIUS - WALL, r_max=RADIUS, height=HEIGHT, sections=144)
    v = np.asarray(ring.vertices)
    phi = np.mod(np.arctan2(v[:, 1], v[:, 0]), 2 * np.pi)
    step = 2 * np.pi / SECTORS
    parts = []
    for k in range(SECTORS):
        rel = np.mod(phi - k * step + 1e-9, 2 * np.pi)
        parts.append(v[rel <= step + 2e-9])
    return ring, parts


def _span_deg(points: np.ndarray) -> float:
    phi = np.arctan2(points[:, 1], points[:, 0])
    mean = np.arctan2(np.sin(phi).mean(), np.cos(phi).mean())
    return float(np.degrees(np.ptp(np.angle(np.exp(1j * (phi - mean))))))


def test_surface_error_merge_makes_even_patches():
    ring, parts = _ring()
    merged = merge_by_surface_error(parts, ring, [12])[12]
    assert len(merged) == 12
    spans = [_span_deg(p) for p in merged]
    assert max(spans) <= 60.0 + 1e-6, spans  # no patch swallows a long arc while others stay small


def test_fewest_hulls_meets_target_with_few_hulls():
    ring, parts = _ring()
    params = replace(AssetParams(), target_p95=0.0038)
    hulls = [make_hull(p) for p in parts]
    info: dict = {}
    best = fewest_hulls(parts, [h for h in hulls if h is not None], ring, params, cavity=True, info=info)
    d95, _ = parts_fidelity(best, ring)
    assert d95 <= params.target_p95
    # a chord across angle a bulges r (1 - cos a/2) into the ring: at least this many sectors are needed
    least = math.ceil(math.pi / math.acos(1 - params.target_p95 / (RADIUS - WALL)))
    assert least - 2 <= len(best) <= 16, (len(best), least)
    assert all(len(h.vertices) <= params.max_hull_vertices for h in best)


def test_capped_hull_keeps_at_most_64_vertices_close_to_the_shape():
    from realsim.assets.hulls import capped

    ball = trimesh.creation.icosphere(subdivisions=3, radius=0.05)  # 642 vertices
    cut = capped(ball)
    assert len(cut.vertices) <= 64 and cut.is_convex
    assert np.abs(np.linalg.norm(cut.vertices, axis=1) - 0.05).max() < 1e-9  # vertices of the original
    assert cut.volume >= 0.85 * ball.volume
    box = trimesh.creation.box(extents=[0.1, 0.1, 0.1])
    assert capped(box) is box  # few vertices: unchanged
