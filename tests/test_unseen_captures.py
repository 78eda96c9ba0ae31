"""Captures no bench writes, as a new user brings them: text point lists with a header line,
empty files, infinite coordinates, scans in inches. Real data from ../shared/data/pcl_scenes."""

from __future__ import annotations

import os
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

from realsim.perception.capture import LoadParams, load_capture
from realsim.perception.pcd_io import read_pcd
from realsim.perception.text_points import read_text_points

PCL = Path(__file__).resolve().parents[2] / "shared" / "data" / "pcl_scenes"
REGION = PCL / "region_growing_rgb_tutorial.pcd"


def _real_cloud() -> tuple[np.ndarray, np.ndarray]:
    """The finite points (m) and 0-255 colours of PCL's region-growing tutorial scene."""
    if not REGION.exists():
        pytest.skip(f"{REGION} not present")
    data = read_pcd(REGION)
    keep = np.isfinite(data.points).all(axis=1)
    assert data.colors is not None
    return data.points[keep][::4], np.round(data.colors[keep][::4] * 255)


def _convert(*args: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[1])}
    return subprocess.run([sys.executable, "-c", "from realsim.cli import main; raise SystemExit(main())", "convert", *args],
                          capture_output=True, text=True, timeout=60, env=env)


@pytest.mark.parametrize("header", ["//X Y Z R G B", "x,y,z,nx,ny,nz,red,green,blue"])
def test_xyz_with_a_header_line_reads_the_named_columns(tmp_path: Path, header: str) -> None:
    pts, cols = _real_cloud()
    normals = np.tile([0.0, 0.0, 1.0], (len(pts), 1))
    table = np.hstack([pts, cols]) if "R" in header else np.hstack([pts, normals, cols])
    path = tmp_path / "export.xyz"
    np.savetxt(path, table, fmt="%.6f", delimiter="," if "," in header else " ", header=header, comments="")
    got, colours = read_text_points(path)
    assert np.abs(got - pts).max() < 1e-5
    assert colours is not None and np.abs(colours - cols / 255.0).max() < 1e-5  # the colour columns, never the normals
    scene = load_capture(path)
    assert scene.points is not None and np.isfinite(scene.points).all() and len(scene.points) == len(pts)


def test_header_naming_fewer_columns_than_the_rows_is_one_clear_error(tmp_path: Path) -> None:
    path = tmp_path / "scan.xyz"
    path.write_text("X Y Z\n" + "1 2 3 4\n" * 200)
    result = _convert(str(path), "-o", str(tmp_path / "out"))
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert "header line names columns" in result.stderr and len(result.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("name", ["scan.ply", "scan.pcd", "scene.obj"])
def test_an_empty_file_says_so(tmp_path: Path, name: str) -> None:
    path = tmp_path / name
    path.write_bytes(b"")
    result = _convert(str(path), "-o", str(tmp_path / "out"))
    assert result.returncode == 2 and result.stderr.strip().endswith("the file is empty")
    assert len(result.stderr.strip().splitlines()) == 1 and not (tmp_path / "out").exists()


def test_infinite_coordinates_are_dropped_without_numpy_warnings(tmp_path: Path) -> None:
    pts, _ = _real_cloud()
    bad = pts.copy()
    bad[::7] = np.inf
    bad[1::11, 2] = -np.inf
    bad[2::13] = np.nan
    path = tmp_path / "scan.xyz"
    np.savetxt(path, bad, fmt="%.6f")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        scene = load_capture(path, LoadParams(up="-y"))
    finite = np.isfinite(bad).all(axis=1)
    assert scene.points is not None and int(np.isfinite(scene.points).all(axis=1).sum()) == int(finite.sum())


def test_a_scan_in_inches_named_by_flag_or_capture_yaml(tmp_path: Path) -> None:
    pts, _ = _real_cloud()
    np.savetxt(tmp_path / "m.xyz", pts, fmt="%.6f")
    (tmp_path / "cap").mkdir()
    np.savetxt(tmp_path / "inch.xyz", pts / 0.0254, fmt="%.6f")
    np.savetxt(tmp_path / "cap" / "scene.xyz", pts / 0.0254, fmt="%.6f")
    (tmp_path / "cap" / "capture.yaml").write_text("units: in\nup: -y\n")
    metres = load_capture(tmp_path / "m.xyz", LoadParams(units="m", up="-y"))
    flag = load_capture(tmp_path / "inch.xyz", LoadParams(units="in", up="-y"))
    yaml = load_capture(tmp_path / "cap")
    assert metres.points is not None and flag.points is not None and yaml.points is not None
    assert np.abs(flag.points - metres.points).max() < 1e-4 and np.abs(yaml.points - metres.points).max() < 1e-4
    assert flag.capture.units == yaml.capture.units == "in"
    result = _convert(str(tmp_path / "inch.xyz"), "-o", str(tmp_path / "out"), "--units", "yards")
    assert result.returncode == 2 and "invalid choice" in result.stderr and "'in'" in result.stderr


def test_a_binary_scan_saved_as_txt_is_refused_not_read_as_words(tmp_path: Path) -> None:
    pts, _ = _real_cloud()
    path = tmp_path / "scan.txt"
    path.write_bytes(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(pts)}\nproperty float x\nproperty float y\n"
                     f"property float z\nend_header\n".encode() + pts.astype("<f4").tobytes())
    result = _convert(str(path), "-o", str(tmp_path / "out"))
    assert result.returncode == 2 and "not a text description" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1 and not (tmp_path / "out").exists()
