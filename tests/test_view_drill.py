"""A power drill lying on its side in a generated camera view (real YCB mesh) is one object: its grip
runs into its motor housing in a shallow fold, which the supervoxel merging keeps apart
(realsim.perception.shallow_folds joins them). The scene is bench_view_objects' seed 10, third scene."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from realsim.perception.pcd_io import read_pcd
from realsim.pipeline import run_pipeline
from realsim.synth import SceneSpec, make_scene, write_organized_view
from realsim.synth.scene import ycb_root

pytestmark = pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")
DETECT = Path(__file__).resolve().parents[1] / "bench" / "_detect_only.yaml"
OBJECTS = ("012_strawberry", "035_power_drill", "061_foam_brick", "040_large_marker", "019_pitcher_base")


def assert_found_once(tmp_path: Path, objects: tuple[str, ...], seed: int, name: str) -> None:
    """In a generated view of ``objects`` (stacked, touching, ``seed``), the object ``name`` is one
    segment holding over a tenth of its pixels, and that segment's IoU with it is over 0.8."""
    gt = make_scene(SceneSpec(layout="table", objects=objects, n_objects=len(objects), stacked=True, touching=True, seed=seed))
    target = next(o.id for o in gt.objects if o.name == name)
    write_organized_view(gt, tmp_path / "view.pcd", seed=seed)
    truth = read_pcd(tmp_path / "view.pcd").labels
    assert truth is not None
    mine = np.where(truth >= 10, truth // 10, 0) == target
    labels = run_pipeline(tmp_path / "view.pcd", pipeline=DETECT).labels
    ids, counts = np.unique(labels[mine & (labels > 0)], return_counts=True)
    assert np.count_nonzero(counts > 0.1 * mine.sum()) == 1, dict(zip(ids.tolist(), counts.tolist()))
    seg = labels == ids[np.argmax(counts)]
    assert np.count_nonzero(seg & mine) / np.count_nonzero(seg | mine) > 0.8


def test_a_lying_drill_is_found_once(tmp_path: Path) -> None:
    assert_found_once(tmp_path, OBJECTS, 10, "035_power_drill")
