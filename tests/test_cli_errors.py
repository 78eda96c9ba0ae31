"""Bad input: one line on stderr, exit code 2, no traceback, no output folder left behind."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from conftest import REPO
from realsim.perception.pcd_io import write_pcd


def run_cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(REPO / "cli.py"), *args], capture_output=True, text=True, cwd=REPO)


def _assert_user_error(result: subprocess.CompletedProcess, out: Path, needle: str) -> None:
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    assert needle in lines[0].lower(), lines[0]
    assert not out.exists()
    assert not [p for p in out.parent.iterdir() if p.name.startswith(f".{out.name}")], "temporary folder left behind"


def _plane_free_cloud(path: Path) -> None:
    rng = np.random.default_rng(0)
    pts = rng.normal(size=(5000, 3)) * 0.3  # a gaussian blob: no flat surface
    write_pcd(path, pts, encoding="binary")


@pytest.mark.parametrize(
    "make, needle",
    [
        (lambda p: None, "no such file"),
        (lambda p: p.write_bytes(b""), "empty"),
        (lambda p: p.write_bytes(b"# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 100\nHEIGHT 1\nPOINTS 100\nDATA binary\n\x00\x01"), "pcd"),
        (lambda p: write_pcd(p, np.full((640, 3), np.nan), encoding="binary"), "nan"),
        (_plane_free_cloud, "plane"),
    ],
    ids=["missing", "empty", "truncated", "all-nan", "no-plane"],
)
def test_bad_point_clouds(tmp_path: Path, make, needle: str) -> None:
    src = tmp_path / "scan.pcd"
    make(src)
    out = tmp_path / "out"
    _assert_user_error(run_cli("convert", str(src), "-o", str(out)), out, needle)


def test_unsupported_format(tmp_path: Path) -> None:
    src = tmp_path / "scan.docx"
    src.write_text("hello")
    out = tmp_path / "out"
    _assert_user_error(run_cli("convert", str(src), "-o", str(out)), out, "unsupported")


def test_corrupt_mesh(tmp_path: Path) -> None:
    src = tmp_path / "room.glb"
    src.write_bytes(b"glTF\x02\x00\x00\x00garbage")
    out = tmp_path / "out"
    _assert_user_error(run_cli("convert", str(src), "-o", str(out)), out, "room.glb")


def test_bad_override(tmp_path: Path) -> None:
    out = tmp_path / "out"
    src = tmp_path / "scan.pcd"
    _plane_free_cloud(src)
    _assert_user_error(run_cli("convert", str(src), "-o", str(out), "--set", "planes.nonsense=3"), out, "nonsense")


def test_usage_error_exit_code() -> None:
    assert run_cli("convert").returncode == 2


def test_params_lists_every_stage_parameter_with_its_meaning() -> None:
    out = run_cli("params", "planes")
    assert out.returncode == 0
    line = next(x for x in out.stdout.splitlines() if x.startswith("planes.distance_threshold "))
    assert "float" in line and "0.01" in line and "RANSAC inlier distance" in line
    nested = run_cli("params", "--pipeline", "objects").stdout
    assert "objects.layout.clearance" in nested and "planes." not in nested  # nested groups flattened; only that pipeline
    bad = run_cli("params", "plane")
    assert bad.returncode == 2 and "did you mean 'planes'" in bad.stderr


def test_output_cut_short_by_the_reader_is_no_error() -> None:
    proc = subprocess.run(f"{sys.executable} {REPO / 'cli.py'} params | head -1", shell=True, capture_output=True, text=True, cwd=REPO)
    assert proc.stderr == "" and proc.stdout.count("\n") == 1
