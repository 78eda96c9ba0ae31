"""bench/bench_units.py's check: the same generated cloud with its points in another order gives
the same world; written in metres and in centimetres (float32, so the two differ by rounding
alone) or moved by a fraction of a millimetre it must give the same supports and objects."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from realsim.synth.scene import ycb_root

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "bench"))
from bench_units import World, bench_scene, cloud_of, compare, convert_world, write_variant  # noqa: E402

pytestmark = pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")


def test_compare_reports_what_differs() -> None:
    ref = World("m", np.array([0.0, 0.75]), np.array([[3.0, 3.0], [0.7, 1.1]]), np.array([[0.1, 0.0, 0.8], [0.3, 0.1, 0.8]]), 0.0)
    moved = World("cm", ref.heights + [0.0, 2e-5], ref.extents + 0.01, ref.objects[::-1] + [0.002, 0.0, 0.0], 0.0)
    dh, dext, dpos = compare(ref, moved)
    assert dh == pytest.approx(2e-5) and dext == pytest.approx(0.01) and dpos == pytest.approx(0.002)
    fewer = World("m", ref.heights[:1], ref.extents[:1], ref.objects[:1], 0.0)
    assert all(np.isnan(v) for v in compare(ref, fewer))


def test_point_order_gives_one_world(tmp_path: Path) -> None:
    gt = bench_scene("counter:42")
    cloud = cloud_of(gt, 200_000)
    metres = convert_world(write_variant(gt, "cloud", "m", tmp_path, cloud))
    permuted = convert_world(write_variant(gt, "cloud", "perm", tmp_path, cloud))
    assert len(metres.heights) == 2 and abs(metres.heights[1] - gt.supports[1].height) < 0.003
    assert max(compare(metres, permuted)) < 1e-9 and len(permuted.objects) == len(metres.objects) >= 3  # sums in another order


@pytest.mark.parametrize("variant", ["cm", "shift"])
def test_cloud_in_other_units_or_moved_gives_one_world(tmp_path: Path, variant: str) -> None:
    gt = bench_scene("counter:42")  # a counter against walls: its RANSAC proposals had followed the rounding
    cloud = cloud_of(gt, 200_000)
    metres = convert_world(write_variant(gt, "cloud", "m", tmp_path, cloud))
    other = convert_world(write_variant(gt, "cloud", variant, tmp_path, cloud))
    assert (metres.units, other.units) == ("m", "cm" if variant == "cm" else "m")
    dh, dext, dpos = compare(metres, other)
    assert dh < 1e-4 and dext < 1e-3
    assert len(other.objects) == len(metres.objects) >= 3 and dpos < 1e-3
