"""The cut search with a bound: the full search's answer whenever that costs no more than the bound."""

from __future__ import annotations

import numpy as np

from realsim.completion.cutsearch import MISS_WEIGHT, _count, best_cut
from realsim.completion.freespace import _directions


def _case(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray | None]:
    centre = rng.normal(size=3) * 0.1
    inside = centre + rng.normal(size=(int(rng.integers(300, 2000)), 3)) * rng.uniform(0.01, 0.05, 3)
    bad = centre + rng.normal(size=(int(rng.integers(2, 200)), 3)) * 0.03 + rng.normal(size=3) * 0.02
    ray = rng.normal(size=3)
    keep = inside[rng.choice(len(inside), 5, replace=False)] if rng.random() < 0.3 else None
    return inside, bad, _directions(ray / np.linalg.norm(ray)), keep


def test_a_bound_changes_nothing_the_bound_allows() -> None:
    rng = np.random.default_rng(7)
    checked = 0
    for trial in range(40):
        inside, bad, normals, keep = _case(rng)
        n, c, cost = best_cut(inside, bad, normals, 1530, keep)
        for bound in (cost, cost + 0.05, cost * 0.5, rng.uniform(0.0, 1.0)):
            bn, bc, bcost = best_cut(inside, bad, normals, 1530, keep, bound)
            if cost <= bound:  # the same cut, bit for bit
                assert np.array_equal(bn, n) and (bc == c or not (np.isfinite(bc) or np.isfinite(c))) and bcost == cost, trial
                checked += 1
            else:  # whatever it finds costs more than the bound, as the full answer does
                assert bcost > bound and bcost >= cost, trial
    assert checked >= 40


def test_the_bound_prunes_only_cuts_that_cost_more() -> None:
    """Every cut the exhaustive search prices at or under the bound is still weighed: the bounded answer
    is the exhaustive minimum (the first in row order among equals)."""
    rng = np.random.default_rng(11)
    for trial in range(20):
        inside, bad, normals, _ = _case(rng)
        samples = 1530
        pi, pb = inside @ normals.T, bad @ normals.T
        cuts = np.sort(pb, axis=0) - 1e-6 * np.maximum(np.ptp(pi, axis=0), 1e-9)
        every = 1.0 - (pi[:, None, :] <= cuts[None]).mean(axis=0) + MISS_WEIGHT * np.arange(len(bad))[:, None] / samples
        if every.min() >= MISS_WEIGHT * len(bad) / samples:
            continue
        n, c, cost = best_cut(inside, bad, normals, samples, bound=float(every.min()) + 1e-3)
        k, j = np.unravel_index(int(np.argmin(every)), every.shape)
        assert np.allclose(n, normals[j]) and c == cuts[k, j] and abs(cost - every[k, j]) < 1e-12, trial


def test_counts_in_narrow_sums_match_numpy() -> None:
    rng = np.random.default_rng(2)
    for width in (1, 7, 2000, 40000):
        below = rng.random((5, width)) < 0.6
        assert np.array_equal(_count(below), below.sum(axis=1))
