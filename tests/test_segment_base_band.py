"""The base band of unorganized clouds: looked for only near object footprints
(segment_scene._near_cells), given to an object only under its outline (segment_scene._under_outline),
the outline of its foot: the support under an overhang stays the support's."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy.spatial import cKDTree

from realsim.perception.segment_scene import _near_cells, _under_outline
from realsim.pipeline import run_pipeline
from realsim.synth import SceneSpec, make_scene, write_point_cloud
from realsim.synth.scene import ycb_root


def test_near_cells_keeps_every_point_within_reach_and_drops_far_ones() -> None:
    rng = np.random.default_rng(3)
    cell, reach = 0.005, 0.0125
    objects = rng.uniform(-0.2, 0.2, size=(300, 2))
    cells = np.floor(objects / cell).astype(np.int64)
    xy = rng.uniform(-0.6, 0.6, size=(40_000, 2))
    xy[::97] = np.nan  # missing points are never near
    mask = _near_cells(xy, cells, cell, reach)
    finite = np.isfinite(xy).all(axis=1)
    dist = np.full(len(xy), np.inf)
    dist[finite] = cKDTree(objects).query(xy[finite])[0]
    assert mask[dist < reach].all()  # a superset of what the KD query can reach
    assert not mask[~finite].any()
    # and no wider than the dilation (ceil(reach / cell) + 1 cells each way, a cell's diagonal more)
    assert not mask[dist > (np.ceil(reach / cell) + 2) * np.sqrt(2) * cell].any()
    assert 0 < mask.sum() < 0.5 * len(xy)


def test_near_cells_with_nothing_to_be_near() -> None:
    assert not _near_cells(np.zeros((4, 2)), np.zeros((0, 2), dtype=np.int64), 0.01, 0.02).any()


def test_under_outline_is_the_owners_hull_grown_by_the_margin() -> None:
    rng = np.random.default_rng(7)
    box = rng.uniform([0.0, 0.0], [0.10, 0.06], size=(400, 2))  # object 1: a 10 x 6 cm footprint
    disc = rng.normal([0.3, 0.0], 0.02, size=(300, 2))  # object 2, apart
    line = np.c_[np.linspace(-0.3, -0.2, 20), np.zeros(20)]  # object 3: collinear, no outline
    all_xy = np.vstack([box, disc, line, rng.uniform(-0.5, 0.5, size=(500, 2))])
    labels = np.repeat(np.array([1, 2, 3, 0]), [400, 300, 20, 500])
    probes = np.array([[0.05, 0.03], [0.101, 0.03], [0.12, 0.03], [0.05, -0.03], [0.05, 0.03], [-0.25, 0.0]])
    owner = np.array([1, 1, 1, 1, 2, 3])
    inside = _under_outline(probes, owner, all_xy, labels, margin=0.002)
    # inside the box; just outside its hull but within the margin; a cell (2 cm) beside it: not
    # its foot; under another object's outline only for that object; a line has no inside
    assert inside[0] and inside[1]
    assert not inside[2] and not inside[3] and not inside[4] and not inside[5]


@pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")
def test_support_under_an_overhang_stays_the_supports(tmp_path: Path) -> None:
    """The support is hidden only under an object's foot: under a lying drill's body, a mug's
    handle or a pitcher's spout the scan still sees it, so its noise there is not the object's
    (a 2 mm-noise 200k cloud; with the outline of all an object's points the three took 4.0 % of
    their size in support points, the drill 7.6 %)."""
    scene_gt = make_scene(SceneSpec(layout="table", objects=("035_power_drill", "019_pitcher_base", "025_mug"),
                                    stacked=False, touching=False, seed=1))
    _, ids = write_point_cloud(scene_gt, tmp_path / "overhangs.ply", 200_000)
    detect = tmp_path / "detect.yaml"
    detect.write_text("name: detect\nstages:\n  - load\n  - planes\n  - segment\n")
    scene = run_pipeline(tmp_path / "overhangs.ply", pipeline=detect)
    taken = []
    for k in range(1, 4):
        mine = ids == k
        found = np.bincount(scene.labels[mine].clip(0)).argmax()
        assert found > 0 and (scene.labels[mine] == 0).mean() < 0.03, scene_gt.objects[k - 1].name  # feet kept
        taken.append(((scene.labels == found) & (ids == 0)).sum() / mine.sum())
    assert np.mean(taken) < 0.035, taken
