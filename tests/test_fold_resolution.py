"""The contact cut works only where a point normal is finer than the smallest object (segment_scene)."""

from __future__ import annotations

import dataclasses

import numpy as np
from scipy.spatial import cKDTree

from realsim.perception.segment import SegmentParams
from realsim.perception.segment_scene import at_resolution, fold_resolution


def test_a_normal_disc_at_the_fold_resolution_is_the_smallest_object() -> None:
    """On a plane sampled one point per cell of the fold resolution, a point's ``normal_neighbors``
    nearest neighbours reach about ``min_object_size``; finer objects need finer cells."""
    params = SegmentParams()
    cell = fold_resolution(params)
    g = np.arange(-40, 41) * cell
    plane = np.stack(np.meshgrid(g, g), axis=-1).reshape(-1, 2)
    reach = cKDTree(plane).query(np.zeros(2), k=params.normal_neighbors)[0].max()
    assert 0.8 * params.min_object_size <= reach <= 1.2 * params.min_object_size
    small = dataclasses.replace(params, min_object_size=0.01)
    assert fold_resolution(small) < cell


def test_the_cut_is_off_where_normals_span_objects() -> None:
    """A 200k-point room (1 cm cells) leaves touching objects to colour; a 1 M one (5 mm) cuts folds."""
    params = SegmentParams()
    assert at_resolution(params, 0.010).contact_cut_cell < 0.010
    assert at_resolution(params, 0.005).contact_cut_cell >= 0.005
    assert at_resolution(dataclasses.replace(params, contact_cut_cell=0.004), 0.005).contact_cut_cell < 0.005
