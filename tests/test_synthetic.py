"""realsim.synth.tabletop: the bundled synthetic RGB-D tabletop capture and its ground truth."""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np
import pytest
import yaml

from realsim.errors import InputError
from realsim.perception.pcd_io import PcdData, read_pcd
from realsim.synth import tabletop as synthetic

FILES = ("scene.pcd", "capture.yaml", "ground_truth.json")


@pytest.fixture(scope="module")
def capture(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, float]:
    dest = tmp_path_factory.mktemp("synthetic") / "capture"
    start = time.perf_counter()
    out = synthetic.make_tabletop_capture(dest, seed=0)
    return out, time.perf_counter() - start


@pytest.fixture(scope="module")
def cloud(capture: tuple[Path, float]) -> PcdData:
    return read_pcd(capture[0] / "scene.pcd")


@pytest.fixture(scope="module")
def gt(capture: tuple[Path, float]) -> dict:
    return json.loads((capture[0] / "ground_truth.json").read_text())


def _world(cloud: PcdData, gt: dict, mask: np.ndarray) -> np.ndarray:
    pose = np.asarray(gt["camera"]["pose_optical_to_world"])
    return cloud.points[mask] @ pose[:3, :3].T + pose[:3, 3]


def test_files_and_speed(capture: tuple[Path, float]) -> None:
    dest, seconds = capture
    assert sorted(p.name for p in dest.iterdir()) == sorted(FILES)
    assert seconds < 20.0


def test_organized_kinect_like_cloud(cloud: PcdData, gt: dict) -> None:
    assert cloud.grid_shape == (480, 640)
    assert cloud.points.shape == (640 * 480, 3)
    assert cloud.fields == ("x", "y", "z", "rgb", "label")
    assert cloud.encoding == "binary_compressed"
    finite = cloud.finite_mask
    assert 0.5 < finite.mean() < 0.99  # the far floor lies beyond the range: NaN
    z = cloud.points[finite, 2]
    assert z.min() > 0.3 and z.max() <= synthetic.MAX_RANGE + 0.05  # optical frame, +z forward
    # NaN exactly where the label says "no point"
    assert np.array_equal(~finite, cloud.labels == synthetic.LABEL_NONE)
    # organized: +x grows to the right, +y grows downward in the image
    grid = cloud.points.reshape(480, 640, 3)
    row = grid[300]
    ok = np.isfinite(row[:, 0])
    assert np.all(np.diff(row[ok, 0] / row[ok, 2]) > 0)
    col = grid[:, 320]
    ok = np.isfinite(col[:, 1])
    assert np.all(np.diff(col[ok, 1] / col[ok, 2]) > 0)
    assert gt["camera"]["width"] == 640 and gt["camera"]["height"] == 480


def test_labels_follow_mosd_convention(cloud: PcdData, gt: dict) -> None:
    present = set(np.unique(cloud.labels).tolist())
    expected = {o["pcd_label"] for o in gt["objects"]} | {0, 1, 2, 3}
    assert present == expected
    for o in gt["objects"]:
        assert o["pcd_label"] // 10 == o["id"] and o["pcd_label"] >= 20
        assert np.count_nonzero(cloud.labels == o["pcd_label"]) >= 400
    assert len(gt["objects"]) == 5
    assert len({tuple(o["color"]) for o in gt["objects"]}) == 5


def test_table_pixels_lie_at_table_height(cloud: PcdData, gt: dict) -> None:
    table = _world(cloud, gt, cloud.labels == synthetic.LABEL_TABLE_TOP)
    assert len(table) > 50_000
    dz = table[:, 2] - gt["table"]["height"]
    assert abs(np.median(dz)) < 0.001
    assert np.percentile(np.abs(dz), 99) < 0.008
    # noise is there (~1-2 mm), not a perfect plane
    assert 0.0005 < dz.std() < 0.004
    half = np.asarray(gt["table"]["size"]) / 2 + 0.005
    assert np.all(np.abs(table[:, :2] - gt["table"]["center"]) <= half)
    floor = _world(cloud, gt, cloud.labels == synthetic.LABEL_FLOOR)
    assert len(floor) > 5_000
    assert abs(np.median(floor[:, 2] - gt["floor"]["height"])) < 0.002


def test_camera_like_a_kinect_on_a_tripod(gt: dict) -> None:
    pose = np.asarray(gt["camera"]["pose_optical_to_world"])
    rot = pose[:3, :3]
    assert np.allclose(rot.T @ rot, np.eye(3), atol=1e-5)
    assert np.linalg.det(rot) > 0
    forward = rot[:, 2]
    pitch = math.degrees(math.asin(-forward[2]))
    assert 35 <= pitch <= 50
    assert 45 <= gt["camera"]["fovy_deg"] <= 58
    height_above_table = pose[2, 3] - gt["table"]["height"]
    distance = height_above_table / math.sin(math.radians(pitch))
    assert 0.8 < distance < 1.4
    assert rot[2, 0] == pytest.approx(0.0, abs=1e-6)  # no roll: image x axis is horizontal


def _to_object_frame(points: np.ndarray, obj: dict) -> np.ndarray:
    c, s = math.cos(obj["yaw"]), math.sin(obj["yaw"])
    rel = points - np.asarray(obj["position"])
    return np.stack([c * rel[:, 0] + s * rel[:, 1], -s * rel[:, 0] + c * rel[:, 1], rel[:, 2]],
                    axis=1)


def test_object_points_sit_where_ground_truth_says(cloud: PcdData, gt: dict) -> None:
    tol = 0.008
    for obj in gt["objects"]:
        local = _to_object_frame(_world(cloud, gt, cloud.labels == obj["pcd_label"]), obj)
        sx, sy, sz = obj["size"]
        assert local[:, 2].min() > -tol and local[:, 2].max() < sz + tol, obj["label"]
        assert np.percentile(local[:, 2], 99.5) > sz - tol, obj["label"]  # the top is seen
        if obj["shape"] == "box":
            assert np.all(np.abs(local[:, 0]) < sx / 2 + tol), obj["label"]
            assert np.all(np.abs(local[:, 1]) < sy / 2 + tol), obj["label"]
        else:
            r = np.hypot(local[:, 0], local[:, 1])
            assert np.all(r < sx / 2 + tol), obj["label"]


def test_scene_structure(gt: dict) -> None:
    objs = {o["id"]: o for o in gt["objects"]}
    table_h = gt["table"]["height"]
    stacked = [o for o in objs.values() if o["resting_on"] is not None]
    assert len(stacked) == 1
    top, base = stacked[0], objs[stacked[0]["resting_on"]]
    assert top["position"][2] == pytest.approx(base["position"][2] + base["size"][2], abs=1e-5)
    for o in objs.values():
        if o["resting_on"] is None:
            assert o["position"][2] == pytest.approx(table_h)
    # the touching pair: a cylinder against a box side, zero gap
    (a, b), = gt["touching"]
    box, can = objs[a], objs[b]
    assert box["shape"] == "box" and can["shape"] == "cylinder"
    local = _to_object_frame(np.asarray([can["position"]]), box)[0]
    assert abs(local[0]) - box["size"][0] / 2 - can["size"][0] / 2 == pytest.approx(0, abs=1e-3)
    # every other pair of table-standing objects is apart
    from realsim.geometry import polygons_apart
    from realsim.synth.tabletop_layout import _footprint

    feet = {i: _footprint(o["shape"], o["size"], np.asarray(o["position"][:2]), o["yaw"])
            for i, o in objs.items() if o["resting_on"] is None}
    ids = sorted(feet)
    for i in ids:
        for j in ids:
            if i < j and sorted((i, j)) != sorted((a, b)):
                assert polygons_apart(feet[i], feet[j], 0.01), (i, j)


def test_capture_yaml(capture: tuple[Path, float], gt: dict) -> None:
    meta = yaml.safe_load((capture[0] / "capture.yaml").read_text())
    assert meta["units"] == "m" and meta["up"] == "-y"
    assert meta["labels"] == {o["id"]: o["label"] for o in gt["objects"]}
    assert {"cereal_box", "can", "mug"} <= set(meta["labels"].values())


def test_same_seed_same_bytes_other_seed_differs(capture: tuple[Path, float],
                                                 tmp_path: Path) -> None:
    again = synthetic.make_tabletop_capture(tmp_path / "again", seed=0)
    for name in FILES:
        assert (again / name).read_bytes() == (capture[0] / name).read_bytes(), name
    synthetic.make_tabletop_capture(tmp_path / "other", seed=5)
    other = json.loads((tmp_path / "other" / "ground_truth.json").read_text())
    assert other["seed"] == 5
    assert (tmp_path / "other" / "scene.pcd").read_bytes() != (again / "scene.pcd").read_bytes()


def test_depth_is_linear_metres_along_the_axis() -> None:
    """MuJoCo's depth image is distance along the optical axis in metres (not a z-buffer)."""
    layout = synthetic.sample_layout(0)
    model = synthetic.build_spec(layout, 160, 120).compile()
    _, depth, geom = synthetic.render_rgbd(model, 160, 120)
    pts = synthetic.backproject(depth, layout.camera.fovy_deg)
    world = pts.reshape(-1, 3) @ layout.camera.rotation.T + layout.camera.position
    table_geom = [g for g in range(model.ngeom)
                  if model.geom(g).name == "table_top"][0]
    on_table = geom.reshape(-1) == table_geom
    assert on_table.sum() > 1000
    # all but the slab's front edge lands on the top plane to a tenth of a millimetre
    err = np.abs(world[on_table, 2] - layout.table_height)
    assert np.mean(err < 1e-4) > 0.95


def test_bad_destination(tmp_path: Path) -> None:
    f = tmp_path / "file"
    f.write_text("x")
    with pytest.raises(InputError):
        synthetic.make_tabletop_capture(f)
