"""Capture loading: formats, unit and up-axis detection, the recorded input-to-world transform."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from conftest import MOSD
from realsim.errors import InputError
from realsim.perception.capture import LoadParams, load_capture, up_rotation
from realsim.perception.pcd_io import read_pcd
from realsim.pipeline import run_pipeline


def _table_height(scene) -> float:
    return max((p for p in scene.planes if p.kind != "floor"), key=lambda p: p.inlier_count).height


@pytest.fixture(scope="module")
def mosd_world() -> tuple[np.ndarray, np.ndarray]:
    """test0 in its camera frame, and the world points realsim makes of it."""
    data = read_pcd(MOSD / "test0.pcd")
    scene = run_pipeline(MOSD / "test0.pcd", pipeline=_planes_only())
    return data.points, scene.points


def _planes_only() -> Path:
    path = Path(__file__).parent / "_planes_only.yaml"
    return path


@pytest.mark.parametrize("up", ["+x", "-x", "+y", "-y", "+z", "-z"])
def test_up_rotation_is_proper_and_maps_axis_to_z(up: str) -> None:
    r = up_rotation(up)
    axis = np.zeros(3)
    axis["xyz".index(up[1])] = 1 if up[0] == "+" else -1
    assert np.allclose(r @ axis, [0, 0, 1])
    assert np.isclose(np.linalg.det(r), 1.0)


def test_organized_pcd_is_a_camera_view() -> None:
    scene = load_capture(MOSD / "test0.pcd")
    assert scene.capture.up == "-y" and scene.capture.up_detected
    assert scene.capture.units == "m" and scene.grid_shape == (480, 640)
    assert len(scene.points) == 640 * 480


def test_transform_maps_input_points_to_world(mosd_world) -> None:
    raw, world = mosd_world
    scene = run_pipeline(MOSD / "test0.pcd", pipeline=_planes_only())
    t = scene.capture.input_to_world
    finite = np.isfinite(raw).all(axis=1)
    assert np.allclose(raw[finite] @ t[:3, :3].T + t[:3, 3], world[finite], atol=1e-9)
    assert abs(_table_height(scene) - 0.75) < 1e-3


def test_millimetres_and_z_up_mesh_capture_are_detected(tmp_path: Path, mosd_world) -> None:
    """The same scan as a Z-up PLY point cloud in millimetres lands on the same table height."""
    _, world = mosd_world
    finite = world[np.isfinite(world).all(axis=1)]
    trimesh.PointCloud(finite * 1000.0).export(tmp_path / "scan.ply")
    scene = run_pipeline(tmp_path / "scan.ply", pipeline=_planes_only())
    assert scene.capture.units == "mm" and scene.capture.units_detected
    assert scene.capture.up == "+z" and scene.capture.up_detected
    assert abs(_table_height(scene) - 0.75) < 0.003


def test_gltf_is_y_up_and_overrides_win(tmp_path: Path) -> None:
    box = trimesh.creation.box((2.0, 0.05, 1.5))  # a 2 x 1.5 m floor slab in a Y-up file
    box.apply_translation([0, -0.025, 0])
    block = trimesh.creation.box((0.2, 0.3, 0.2))
    block.apply_translation([0, 0.15, 0])
    trimesh.util.concatenate([box, block]).export(tmp_path / "room.glb")
    scene = load_capture(tmp_path / "room.glb")
    assert scene.capture.up == "+y" and scene.capture.kind == "mesh"
    pts = scene.points
    assert np.ptp(pts[:, 2]) == pytest.approx(0.35, abs=0.01)  # the block stands 0.3 m up along +Z
    forced = load_capture(tmp_path / "room.glb", LoadParams(up="+z", units="mm"))
    assert forced.capture.up == "+z" and not forced.capture.up_detected
    assert np.ptp(forced.points[:, 2]) == pytest.approx(0.0015, abs=1e-4)


def test_capture_folder_reads_yaml(tmp_path: Path) -> None:
    folder = tmp_path / "cap"
    folder.mkdir()
    (folder / "scene.pcd").write_bytes((MOSD / "test0.pcd").read_bytes())
    (folder / "capture.yaml").write_text("units: m\nup: '-y'\nlabels: {1: cereal_box}\n")
    scene = load_capture(folder)
    assert scene.capture.environment_file == folder / "scene.pcd"
    assert not scene.capture.up_detected and scene.capture.config.labels == {1: "cereal_box"}


def test_bad_capture_yaml(tmp_path: Path) -> None:
    folder = tmp_path / "cap"
    folder.mkdir()
    (folder / "scene.pcd").write_bytes((MOSD / "test0.pcd").read_bytes())
    (folder / "capture.yaml").write_text("units: [unclosed\n")
    with pytest.raises(InputError, match="capture.yaml"):
        load_capture(folder)


def test_wrong_units_given_are_named_when_no_support_is_found() -> None:
    from realsim.perception.planes import detect_planes

    scene = load_capture(MOSD / "test0.pcd", LoadParams(units="mm"))  # a metre scan read as millimetres: 3 mm across
    with pytest.raises(InputError, match=r"--units: read in mm the capture is 0\.00\d+ m across"):
        detect_planes(scene)
