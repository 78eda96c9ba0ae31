"""Attached parts: a handle meeting its body along its height joins the body; a box resting on
another at its own foot stays an object of its own."""

from __future__ import annotations

import numpy as np

from realsim.perception.attached_parts import join_attached_parts
from realsim.perception.supervoxels import knn_links


def _block(lo: tuple[float, float, float], hi: tuple[float, float, float], spacing: float) -> np.ndarray:
    """Points filling a box on a regular grid ``spacing`` apart."""
    axes = [np.arange(a, b + 1e-9, spacing) for a, b in zip(lo, hi)]
    return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)


def _join(parts: list[np.ndarray], resting_on: dict[int, int | None]) -> tuple[np.ndarray, np.ndarray]:
    points = np.vstack(parts)
    labels = np.concatenate([np.full(len(p), k + 1, dtype=np.int32) for k, p in enumerate(parts)])
    a, b = knn_links(points, np.ones(len(points), dtype=bool), 8)
    return join_attached_parts(points, labels, points[:, 2], a, b, resting_on, stand_height=0.015), labels


def test_a_handle_joins_its_body() -> None:
    """A handle hanging on a body's side, meeting it at its top and bottom, its foot 3 cm up."""
    body = _block((0.0, 0.0, 0.0), (0.1, 0.1, 0.12), 0.01)
    handle = np.vstack([_block((0.11, 0.04, 0.03), (0.14, 0.06, 0.04), 0.01),  # lower arm
                        _block((0.11, 0.04, 0.09), (0.14, 0.06, 0.1), 0.01),  # upper arm
                        _block((0.14, 0.04, 0.05), (0.14, 0.06, 0.08), 0.01)])  # grip
    out, _ = _join([body, handle], {1: None, 2: 1})
    assert np.all(out == 1)


def test_a_box_resting_on_a_box_stays() -> None:
    """A small box standing on a larger one's top meets it only at its own foot."""
    base = _block((0.0, 0.0, 0.0), (0.2, 0.2, 0.06), 0.01)
    top = _block((0.05, 0.05, 0.07), (0.12, 0.12, 0.14), 0.01)
    out, labels = _join([base, top], {1: None, 2: 1})
    assert np.array_equal(out, labels)
