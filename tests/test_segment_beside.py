"""A camera view's measured normals (for the backdrop patches) made on a thread beside the
segmentation (realsim.beside): the labels of one thread, and the thread's error raised."""

from __future__ import annotations

import numpy as np
import pytest
from test_segment import BOXES, _render_boxes, _table

import realsim.perception.segment as segment
from realsim.beside import Beside
from realsim.perception.segment import SegmentParams, segment_objects


def test_the_view_s_normals_are_made_beside_and_the_labels_are_the_same(monkeypatch: pytest.MonkeyPatch) -> None:
    points, colors, _ = _render_boxes(BOXES)
    alone = segment_objects(points, colors, [_table()], (240, 320), SegmentParams(), seed=0)
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    begun: list[Beside[np.ndarray]] = []

    def spy(fn):  # type: ignore[no-untyped-def]
        begun.append(Beside(fn))
        return begun[-1]

    monkeypatch.setattr(segment, "Beside", spy)
    beside = segment_objects(points, colors, [_table()], (240, 320), SegmentParams(), seed=0)
    assert len(begun) == 1 and begun[0].thread is not None
    assert np.array_equal(beside.labels, alone.labels)
    assert beside.resting_on == alone.resting_on and beside.support_of == alone.support_of


def test_a_value_made_beside_is_the_value_and_its_error_is_raised_where_taken(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    assert Beside(lambda: np.arange(5) * 2).result().tolist() == [0, 2, 4, 6, 8]

    def fails() -> int:
        raise ValueError("beside")

    with pytest.raises(ValueError, match="beside"):
        Beside(fails).result()
    monkeypatch.setenv("REALSIM_WORKERS", "1")
    assert Beside(lambda: 3).thread is None and Beside(lambda: 3).result() == 3
