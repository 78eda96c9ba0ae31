"""Two segments meeting at a depth step are one body when the nearer one's rim, turned from the camera,
lies on the farther one's surface and no contact crease is seen; a body farther back, a face seen
head-on or a crease along the border keeps them apart."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from realsim.perception.pcd_io import read_pcd
from realsim.perception.step_joins import join_hidden_steps, step_measures
from realsim.pipeline import run_pipeline
from realsim.synth import SceneSpec, make_scene, write_organized_view
from realsim.synth.scene import ycb_root

H, W = 30, 40
PIXEL = 0.002  # m between neighbouring pixels
AXIS = np.array([0.0, 0.0, -1.0])  # the camera looks down: nearer is higher
DETECT = Path(__file__).resolve().parents[1] / "bench" / "_detect_only.yaml"


def _step(rise: float, facing: float, crease_rows: int = 0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Points, normals and labels of a flat surface (label 0, left half, z = 0) beside a nearer piece
    (label 1) whose rim ``rise`` (m) above it turns from the camera (its normals' |n . view| is
    ``facing``); on the first ``crease_rows`` rows the nearer piece comes down to the surface (a crease)."""
    rows, cols = np.mgrid[0:H, 0:W]
    right = cols >= W // 2
    z = np.where(right, rise, 0.0)
    z[:crease_rows] = np.where(right[:crease_rows], 0.001 * (cols[:crease_rows] - W // 2), 0.0)
    points = np.stack([cols * PIXEL, rows * PIXEL, z], axis=-1).reshape(-1, 3)
    tilt = np.sqrt(1.0 - facing**2)
    normals = np.where(right.reshape(-1, 1), [tilt, 0.0, facing], [0.0, 0.0, 1.0])
    return points, normals, right.astype(np.int64).reshape(-1)


def _join(points: np.ndarray, normals: np.ndarray, labels: np.ndarray) -> np.ndarray:
    return join_hidden_steps(labels, points, normals, (H, W), AXIS, 0.008, max_gap=0.012, max_facing=0.6, min_links=6,
                             consistent_share=0.9)


def test_the_measures_are_the_step_seen_from_the_nearer_side() -> None:
    points, normals, labels = _step(0.010, 0.5)
    total, steps, share, facing, gap = step_measures(labels, points, normals, (H, W), AXIS, 0.008)[(0, 1)]
    assert (total, steps, share) == (H, H, 1.0)
    assert abs(facing - 0.5) < 1e-9 and abs(gap - 0.010) < 1e-9


def test_a_rim_on_the_farther_surface_joins_the_two_pieces() -> None:
    assert len(np.unique(_join(*_step(0.010, 0.5)))) == 1


def test_a_piece_far_above_the_surface_stays_apart() -> None:
    assert len(np.unique(_join(*_step(0.030, 0.5)))) == 2


def test_a_face_seen_head_on_stays_apart() -> None:
    assert len(np.unique(_join(*_step(0.010, 0.95)))) == 2


def test_a_contact_crease_along_the_border_keeps_them_apart() -> None:
    assert len(np.unique(_join(*_step(0.010, 0.5, crease_rows=8)))) == 2


@pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")
def test_a_lying_drill_whose_battery_hides_its_grip_is_found_once(tmp_path: Path) -> None:
    """bench_view_objects' seed 4, first scene: the battery's rim hides the grip's foot (a depth step)."""
    objects = ("012_strawberry", "003_cracker_box", "010_potted_meat_can", "037_scissors", "035_power_drill")
    gt = make_scene(SceneSpec(layout="table", objects=objects, n_objects=len(objects), stacked=True, touching=True, seed=4))
    drill = next(o.id for o in gt.objects if o.name == "035_power_drill")
    write_organized_view(gt, tmp_path / "view.pcd", seed=4)
    truth = read_pcd(tmp_path / "view.pcd").labels
    assert truth is not None
    mine = np.where(truth >= 10, truth // 10, 0) == drill
    labels = run_pipeline(tmp_path / "view.pcd", pipeline=DETECT).labels
    ids, counts = np.unique(labels[mine & (labels > 0)], return_counts=True)
    assert np.count_nonzero(counts > 0.1 * mine.sum()) == 1, dict(zip(ids.tolist(), counts.tolist()))
    seg = labels == ids[np.argmax(counts)]
    assert np.count_nonzero(seg & mine) / np.count_nonzero(seg | mine) > 0.8
