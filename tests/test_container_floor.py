"""Container floors: support pixels enclosed in the image by one object, within its outline seen
from above and walled in by it, become that object's; support seen through a loop beside an
object, or through a flat object's hole, stays support."""

from __future__ import annotations

import numpy as np

from realsim.perception.container_floor import claim_enclosed_floors


def _view(ring_xy: float, hole_xy: float, ring_z: float = 0.05) -> tuple[np.ndarray, np.ndarray, np.ndarray, tuple[int, int]]:
    """A 20 x 20 pixel view from straight above: an object's ring of pixels (label 1, at height
    ``ring_z``) around a 6 x 6 hole whose points lie on the support at z = 0; the ring's points sit
    at x, y offset by ``ring_xy`` and the hole's by ``hole_xy`` from their pixel positions (1 cm pixels)."""
    shape = (20, 20)
    rows, cols = np.mgrid[0:20, 0:20]
    labels = np.zeros(shape, dtype=np.int32)
    labels[5:15, 5:15] = 1
    hole = np.zeros(shape, dtype=bool)
    hole[7:13, 7:13] = True
    labels[hole] = 0
    points = np.stack([cols * 0.01, rows * 0.01, np.where(labels == 1, ring_z, 0.0)], axis=-1).astype(np.float64)
    points[labels == 1, :2] += ring_xy
    points[hole, :2] += hole_xy
    support = (labels == 0).ravel()
    return labels.ravel(), points.reshape(-1, 3), support, shape


def test_a_floor_inside_a_container_is_claimed() -> None:
    labels, points, support, shape = _view(0.0, 0.0)
    out = claim_enclosed_floors(labels, points, support, shape)
    hole = (labels == 0) & (points[:, 0] > 0.065) & (points[:, 0] < 0.125) & (points[:, 1] > 0.065) & (points[:, 1] < 0.125)
    assert np.all(out[hole] == 1)
    assert np.all(out[(labels == 0) & ~hole] == 0)  # the support around the object stays support


def test_support_seen_through_a_loop_beside_the_object_stays() -> None:
    """The same picture, but what shows through the hole lies 20 cm off, beyond the object's
    outline seen from above (a table seen through a handle from low down)."""
    labels, points, support, shape = _view(0.0, 0.2)
    assert np.array_equal(claim_enclosed_floors(labels, points, support, shape), labels)


def test_a_flat_objects_hole_stays_support() -> None:
    """Scissors' finger loop, 8 mm thick, around the table it lies on: no wall, no floor."""
    labels, points, support, shape = _view(0.0, 0.0, ring_z=0.008)
    assert np.array_equal(claim_enclosed_floors(labels, points, support, shape), labels)
