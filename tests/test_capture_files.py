"""Capture files as apps export them: PTS point lists, captures far from their origin."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from realsim.errors import InputError
from realsim.perception.capture import load_capture
from realsim.perception.resolution import distant_origin
from realsim.perception.text_points import read_text_points


def _room(seed: int = 0) -> np.ndarray:
    """A 3 x 3 m floor, a 1 x 0.7 m table top at 0.75 m and a 10 cm box on it (metres, Z up)."""
    rng = np.random.default_rng(seed)
    floor = np.c_[rng.uniform(-1.5, 1.5, (20000, 2)), np.zeros(20000)]
    top = np.c_[rng.uniform([-0.5, -0.35], [0.5, 0.35], (8000, 2)), np.full(8000, 0.75)]
    box = rng.uniform([0, 0, 0.75], [0.1, 0.1, 0.85], (2000, 3))
    return np.vstack([floor, top, box]) + rng.normal(0, 0.001, (30000, 3))


def _write_ply_double(path: Path, pts: np.ndarray) -> None:
    header = f"ply\nformat binary_little_endian 1.0\nelement vertex {len(pts)}\n" + "".join(
        f"property double {a}\n" for a in "xyz") + "end_header\n"
    path.write_bytes(header.encode() + pts.astype("<f8").tobytes())


def test_pts_with_count_line_and_intensity(tmp_path: Path) -> None:
    pts = _room()
    body = np.c_[pts, np.full(len(pts), 0.3), np.tile([200, 100, 50], (len(pts), 1))]
    path = tmp_path / "scan.pts"
    np.savetxt(path, body, fmt=["%.6f"] * 4 + ["%d"] * 3, header=str(len(pts)), comments="")
    got, colours = read_text_points(path)
    assert got.shape == pts.shape and np.abs(got - pts).max() < 1e-6
    assert colours is not None and np.allclose(colours[0], [200 / 255, 100 / 255, 50 / 255])
    scene = load_capture(path)
    assert len(scene.points) == len(pts) and scene.capture.units == "m" and scene.capture.up == "+z"


def test_ragged_point_list_is_an_input_error(tmp_path: Path) -> None:
    path = tmp_path / "bad.xyz"
    path.write_text("0 0 0\n1 2\n1 2 3 4 5\nfoo bar baz\n")
    with pytest.raises(InputError):
        read_text_points(path)


@pytest.mark.parametrize("offset", [(1200.0, -1600.0, 35.0), (350000.0, 357000.0, 120.0)])
def test_far_origin_is_moved_near_and_recorded(tmp_path: Path, offset: tuple[float, float, float]) -> None:
    pts = _room()
    far = pts + np.asarray(offset)
    _write_ply_double(tmp_path / "far.ply", far)
    scene = load_capture(tmp_path / "far.ply")
    assert np.abs(scene.points).max() < 10.0  # near the origin: float32 keeps sub-millimetre detail
    t = scene.capture.input_to_world
    mapped = far @ t[:3, :3].T + t[:3, 3]
    assert np.abs(mapped - scene.points).max() < 1e-6
    assert np.abs(scene.points.astype(np.float32) - scene.points).max() < 1e-5


def test_near_capture_keeps_its_origin() -> None:
    assert distant_origin(_room()) is None
    assert distant_origin(_room() + [0.0, 0.0, 3.0]) is None
