"""The contact cut's gate on a contact folded along most of its length but wider than a neck:
kept when its unfolded (convex) rest is as narrow as a neck, refused when it is mostly convex,
and refused when the two sides go on as narrow as the contact (one body's own neck)."""

from __future__ import annotations

import numpy as np

from realsim.perception.contact_cut import CutParams, _best_cut

SIDE = 30  # nodes per row and column of each patch


def _two_patches(weight: float, widen: float = 30.0) -> tuple[int, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Two 30 x 30 patches (1 cm apart, on the support) side by side, linked inside with
    weight 1 and across their common edge by two links per row of the given weight: 59
    crossing links, wider than a neck (sqrt(900) = 30). Each patch is a shallow trough whose
    width and depth grow by ``widen`` per metre away from the common edge (two bodies widening
    past their contact; 0: one body as wide beyond the edge as at it)."""
    idx = np.arange(2 * SIDE * SIDE).reshape(SIDE, 2 * SIDE)  # row j, column i
    a = [idx[:, :-1].ravel(), idx[:-1, :].ravel()]
    b = [idx[:, 1:].ravel(), idx[1:, :].ravel()]
    inside = np.ones(sum(len(x) for x in a))
    inside[np.flatnonzero(np.isin(a[0], idx[:, SIDE - 1]))] = weight  # the straight crossing link of each row
    diag_a, diag_b = idx[:-1, SIDE - 1], idx[1:, SIDE]  # and one diagonal per row
    a.append(diag_a)
    b.append(diag_b)
    w = np.r_[inside, np.full(len(diag_a), weight)]
    j, i = np.divmod(np.arange(2 * SIDE * SIDE), 2 * SIDE)
    grow = 1.0 + widen * np.abs(i - (SIDE - 0.5)) * 0.01
    across = (j - (SIDE - 1) / 2) * 0.01
    points = np.stack([i * 0.01, across * grow, 0.005 + 0.3 * np.abs(across) * grow], axis=1)
    height = points[:, 2].copy()
    return len(points), np.concatenate(a), np.concatenate(b), w, points, height


def _cut(weight: float, params: CutParams, widen: float = 30.0) -> np.ndarray | None:
    n, a, b, w, points, height = _two_patches(weight, widen)
    return _best_cut(n, a, b, w, points, height, params)


def test_a_mostly_folded_contact_whose_convex_rest_is_narrow_is_cut() -> None:
    side = _cut(0.45, CutParams())  # mean weight 0.45 (above the fold gate), weight 26.6 <= 30
    assert side is not None
    left = np.arange(len(side)) % (2 * SIDE) < SIDE
    assert (side == left).all() or (side == ~left).all()


def test_without_the_mixed_gate_the_same_contact_is_not_cut() -> None:
    assert _cut(0.45, CutParams(max_mixed_weight=0.0)) is None


def test_a_mostly_convex_contact_is_not_cut() -> None:
    assert _cut(0.505, CutParams()) is None  # mean 0.505: more convex than folded, though its weight 29.8 <= 30
    assert _cut(0.505, CutParams(max_mixed_weight=0.51)) is not None  # the mean gate alone refused it


def test_a_contact_whose_sides_go_on_as_narrow_is_not_cut() -> None:
    assert _cut(0.45, CutParams(), widen=0.0) is None  # the same links, but one body's neck
    assert _cut(0.45, CutParams(min_section_ratio=0.0), widen=0.0) is not None  # the section gate alone refused it
    assert _cut(0.3, CutParams(), widen=0.0) is not None  # a clear fold needs no widening


def _with_loose_pair() -> tuple[int, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The folded two-patch contact plus two linked points just behind the left patch's far
    corners whose every other link folds right back (weight 1e-20, as a thin wall's far side
    between near ones)."""
    n, a, b, w, points, height = _two_patches(0.3)
    corner = np.array([0, SIDE * 2 * (SIDE - 1)])  # the far left edge's ends
    back = points[corner] + [0.0, 0.0, -0.002]
    a = np.r_[a, n, n, n + 1]
    b = np.r_[b, n + 1, corner]
    w = np.r_[w, 1.0, 1e-20, 1e-20]
    return n + 2, a, b, w, np.vstack([points, back]), np.r_[height, back[:, 2]]


def test_points_linked_by_nothing_but_full_folds_do_not_hide_the_contact() -> None:
    """Alone they are a component of their own to the Laplacian: its Fiedler vector was their
    indicator, whose cut is too small to keep, and the contact was never tried."""
    n, a, b, w, points, height = _with_loose_pair()
    side = _best_cut(n, a, b, w, points, height, CutParams())
    assert side is not None
    left = np.r_[np.arange(n - 2) % (2 * SIDE) < SIDE, True, True]  # the loose pair joins its neighbours' side
    assert (side == left).all() or (side == ~left).all()
