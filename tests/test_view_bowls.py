"""A bowl in a generated camera view (real YCB mesh) is one object: its inside and the outer wall
under its rim, which the rim hides (realsim.perception.container_inside.join_outsides), also when a
banana touching the wall held it until the colours parted them (seed 409)."""

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


@pytest.mark.parametrize("seed", [204, 409])
def test_a_bowl_seen_from_above_is_one_object(seed: int, tmp_path: Path) -> None:
    gt = make_scene(SceneSpec(layout="table", seed=seed))  # bench_captures' held-out table:<seed>
    bowl = next(o.id for o in gt.objects if o.name == "024_bowl")
    write_organized_view(gt, tmp_path / "view.pcd")
    truth = read_pcd(tmp_path / "view.pcd").labels
    assert truth is not None
    mine = np.where(truth >= 10, truth // 10, 0) == bowl
    labels = run_pipeline(tmp_path / "view.pcd", pipeline=DETECT).labels
    ids, counts = np.unique(labels[mine], return_counts=True)
    best = int(ids[np.argmax(np.where(ids > 0, counts, 0))])
    seg = labels == best
    assert np.count_nonzero(seg & mine) > 0.95 * mine.sum(), dict(zip(ids.tolist(), counts.tolist()))  # no piece apart
    assert np.count_nonzero(seg & mine) / np.count_nonzero(seg | mine) > 0.9
