"""realsim.perception.pcd_io: real PCL captures, round trips in every encoding, and bad input."""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np
import pytest

from realsim.errors import InputError
from realsim.perception.pcd_io import ENCODINGS, PcdData, read_pcd, write_pcd

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "pcl_scenes"
REAL_FILES = sorted(DATA.glob("*.pcd")) + sorted((DATA / "mOSD").glob("*.pcd"))
needs_data = pytest.mark.skipif(not REAL_FILES, reason="../shared/data/pcl_scenes not present")


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    return bool(np.array_equal(np.nan_to_num(a, nan=-99.0), np.nan_to_num(b, nan=-99.0)))


def _small_cloud(rng: np.random.Generator, h: int = 6, w: int = 8):
    pts = rng.uniform(-2, 2, size=(h * w, 3)).astype(np.float32).astype(np.float64)
    pts[[0, 5, 17]] = np.nan
    colors = rng.integers(0, 256, size=(h * w, 3)).astype(np.float64) / 255.0
    labels = rng.integers(0, 90, size=h * w)
    return pts, colors, labels


# -------------------------------------------------------------------------- real captures


@needs_data
@pytest.mark.parametrize("path", REAL_FILES, ids=lambda p: p.name)
def test_real_pcl_captures(path: Path) -> None:
    d = read_pcd(path)
    assert isinstance(d, PcdData)
    assert d.grid_shape == (480, 640)
    assert d.points.shape == (307200, 3) and d.points.dtype == np.float64
    assert d.encoding == "binary_compressed"
    assert d.viewpoint.shape == (7,)
    finite = d.finite_mask
    assert 0.4 < finite.mean() < 0.95  # organized: NaN rows kept in place
    # metres (milk_cartoon's frame has -z forward, so only magnitudes are checked)
    assert np.abs(d.points[finite]).max() < 10 and np.median(np.abs(d.points[finite, 2])) > 0.2
    assert d.colors is not None and d.colors.shape == (307200, 3)
    assert d.colors.min() >= 0.0 and d.colors.max() <= 1.0 and d.colors.std() > 0.05
    if path.parent.name == "mOSD":
        assert d.fields == ("label", "x", "y", "z", "rgba")
        assert d.labels is not None and d.labels.dtype == np.int64
        assert np.all(d.labels[~finite] == 0)
        ids = set(np.unique(d.labels).tolist())
        assert 1 in ids and 20 in ids
    else:
        assert d.labels is None
        assert d.fields[:3] == ("x", "y", "z")


@needs_data
def test_matches_pypcd4_on_real_file() -> None:
    pypcd4 = pytest.importorskip("pypcd4")
    path = DATA / "mOSD" / "test31.pcd"
    ref = pypcd4.PointCloud.from_path(path)
    d = read_pcd(path)
    assert _same(d.points, ref.numpy(("x", "y", "z")))
    assert np.array_equal(d.labels, ref.pc_data["label"].astype(np.int64))
    rgb = pypcd4.PointCloud.decode_rgb(ref.pc_data["rgba"].view(np.float32))
    assert np.allclose(d.colors * 255.0, rgb)


@needs_data
@pytest.mark.parametrize("encoding", ENCODINGS)
def test_real_file_round_trip(tmp_path: Path, encoding: str) -> None:
    d = read_pcd(DATA / "mOSD" / "test45.pcd")
    # an organized crop keeps the ascii case quick
    grid = np.arange(307200).reshape(480, 640)[200:320, 100:260].reshape(-1)
    out = write_pcd(tmp_path / "crop.pcd", d.points[grid], d.colors[grid], d.labels[grid],
                    grid_shape=(120, 160), encoding=encoding)
    e = read_pcd(out)
    assert e.encoding == encoding and e.grid_shape == (120, 160)
    assert e.fields == ("x", "y", "z", "rgb", "label")
    assert _same(e.points, d.points[grid])
    assert np.array_equal(e.colors, d.colors[grid])
    assert np.array_equal(e.labels, d.labels[grid])


@needs_data
def test_full_real_file_round_trip_binary_compressed(tmp_path: Path) -> None:
    d = read_pcd(DATA / "table_scene_mug_stereo_textured.pcd")
    e = read_pcd(write_pcd(tmp_path / "a.pcd", d.points, d.colors, grid_shape=d.grid_shape))
    assert e.grid_shape == (480, 640) and e.labels is None
    assert _same(e.points, d.points) and np.array_equal(e.colors, d.colors)


# -------------------------------------------------------------------------- synthetic files


@pytest.mark.parametrize("encoding", ENCODINGS)
def test_round_trip_all_encodings(tmp_path: Path, encoding: str) -> None:
    pts, colors, labels = _small_cloud(np.random.default_rng(0))
    out = write_pcd(tmp_path / "c.pcd", pts, colors, labels, grid_shape=(6, 8),
                    encoding=encoding)
    d = read_pcd(out)
    assert d.encoding == encoding
    assert d.grid_shape == (6, 8)
    assert _same(d.points, pts)
    assert np.allclose(d.colors, colors) and np.array_equal(d.labels, labels)
    # same arrays -> same bytes
    again = write_pcd(tmp_path / "d.pcd", pts, colors, labels, grid_shape=(6, 8),
                      encoding=encoding)
    assert out.read_bytes() == again.read_bytes()


@pytest.mark.parametrize("encoding", ENCODINGS)
def test_xyz_only_unorganized(tmp_path: Path, encoding: str) -> None:
    pts = np.array([[0.1, 0.2, 0.3], [np.nan, np.nan, np.nan], [1.0, -2.0, 3.5]])
    d = read_pcd(write_pcd(tmp_path / "x.pcd", pts, encoding=encoding))
    assert d.fields == ("x", "y", "z")
    assert d.colors is None and d.labels is None and d.grid_shape is None
    assert _same(d.points, pts.astype(np.float32).astype(np.float64))


def test_grid_points_array(tmp_path: Path) -> None:
    pts = np.random.default_rng(1).uniform(size=(4, 5, 3))
    d = read_pcd(write_pcd(tmp_path / "g.pcd", pts))
    assert d.grid_shape == (4, 5)
    assert np.allclose(d.points.reshape(4, 5, 3), pts, atol=1e-6)


def _write_ascii(path: Path, fields: str, types: str, rows: list[str]) -> Path:
    n = len(rows)
    k = len(fields.split())
    path.write_text(
        "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n"
        f"FIELDS {fields}\nSIZE {' '.join(['4'] * k)}\nTYPE {types}\n"
        f"COUNT {' '.join(['1'] * k)}\nWIDTH {n}\nHEIGHT 1\n"
        f"VIEWPOINT 0 0 0 1 0 0 0\nPOINTS {n}\nDATA ascii\n" + "\n".join(rows) + "\n"
    )
    return path


def test_ascii_with_nan_and_packed_colours(tmp_path: Path) -> None:
    red = np.array([0xFF0000], dtype=np.uint32).view(np.float32)[0]
    p = _write_ascii(
        tmp_path / "a.pcd", "x y z rgb", "F F F F",
        [
            "0.5 0.25 1.0 16711680",  # PCL style: the packed bits as an integer (red)
            "nan nan nan 65280",  # NaN point, green
            f"1 2 3 {float(red)!r}",  # older writers print the tiny float itself
            "NaN -NaN nan 255",
        ],
    )
    d = read_pcd(p)
    assert d.encoding == "ascii"
    assert np.allclose(d.points[0], [0.5, 0.25, 1.0])
    assert np.isnan(d.points[1]).all() and np.isnan(d.points[3]).all()
    assert np.allclose(d.colors, [[1, 0, 0], [0, 1, 0], [1, 0, 0], [0, 0, 1]])


def test_rgba_uint32_and_label(tmp_path: Path) -> None:
    p = _write_ascii(
        tmp_path / "r.pcd", "label x y z rgba", "U F F F U",
        ["20 0 0 1 4278190335", "1 0 1 1 4294901760"],  # 0xFF0000FF blue, 0xFFFF0000 red
    )
    d = read_pcd(p)
    assert np.array_equal(d.labels, [20, 1])
    assert np.allclose(d.colors, [[0, 0, 1], [1, 0, 0]])


# -------------------------------------------------------------------------- bad input


def _assert_input_error(path: Path, *words: str) -> None:
    with pytest.raises(InputError) as info:
        read_pcd(path)
    msg = str(info.value)
    assert str(path) in msg and "\n" not in msg
    for w in words:
        assert w in msg.lower()


def test_missing_file(tmp_path: Path) -> None:
    _assert_input_error(tmp_path / "nope.pcd", "no such file")


def test_directory(tmp_path: Path) -> None:
    _assert_input_error(tmp_path, "not a file")


def test_empty_file(tmp_path: Path) -> None:
    p = tmp_path / "e.pcd"
    p.write_bytes(b"")
    _assert_input_error(p, "empty")


def test_not_a_pcd(tmp_path: Path) -> None:
    p = tmp_path / "g.pcd"
    p.write_bytes(bytes(range(256)) * 10)
    _assert_input_error(p, "not a pcd")
    p.write_text("ply\nformat ascii 1.0\nend_header\n")
    _assert_input_error(p, "not a pcd")


def test_header_without_data_line(tmp_path: Path) -> None:
    p = tmp_path / "h.pcd"
    p.write_text("VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n")
    _assert_input_error(p, "data")


def test_no_xyz_fields(tmp_path: Path) -> None:
    p = _write_ascii(tmp_path / "n.pcd", "a b c", "F F F", ["1 2 3"])
    _assert_input_error(p, "'x'")


def test_zero_points(tmp_path: Path) -> None:
    p = _write_ascii(tmp_path / "z.pcd", "x y z", "F F F", [])
    _assert_input_error(p, "zero points")


def test_points_width_mismatch(tmp_path: Path) -> None:
    p = _write_ascii(tmp_path / "m.pcd", "x y z", "F F F", ["1 2 3"])
    p.write_text(p.read_text().replace("POINTS 1", "POINTS 5"))
    _assert_input_error(p, "points")


def test_ascii_truncated_and_garbage(tmp_path: Path) -> None:
    p = _write_ascii(tmp_path / "t.pcd", "x y z", "F F F", ["1 2 3", "4 5 6"])
    p.write_text(p.read_text()[:-4])
    _assert_input_error(p, "truncated")
    p = _write_ascii(tmp_path / "q.pcd", "x y z", "F F F", ["1 2 3", "4 five 6"])
    _assert_input_error(p, "corrupt")


@pytest.mark.parametrize("encoding", ["binary", "binary_compressed"])
def test_truncated_binary(tmp_path: Path, encoding: str) -> None:
    pts, colors, labels = _small_cloud(np.random.default_rng(2), 40, 50)
    p = write_pcd(tmp_path / "b.pcd", pts, colors, labels, encoding=encoding)
    raw = p.read_bytes()
    for cut in (len(raw) - 1, len(raw) - 500, raw.index(b"DATA") + 30):
        p.write_bytes(raw[:cut])
        _assert_input_error(p)


def test_corrupt_compressed_block(tmp_path: Path) -> None:
    pts, colors, labels = _small_cloud(np.random.default_rng(3), 40, 50)
    p = write_pcd(tmp_path / "c.pcd", pts, colors, labels)
    raw = bytearray(p.read_bytes())
    start = raw.index(b"DATA binary_compressed\n") + len("DATA binary_compressed\n")
    # wrong uncompressed size
    bad = bytearray(raw)
    csize, usize = struct.unpack("<II", bad[start:start + 8])
    bad[start:start + 8] = struct.pack("<II", csize, usize + 4)
    p.write_bytes(bytes(bad))
    _assert_input_error(p, "corrupt")
    # scrambled LZF stream
    bad = bytearray(raw)
    bad[start + 8:] = bytes([0xFF]) * (len(raw) - start - 8)
    p.write_bytes(bytes(bad))
    _assert_input_error(p, "corrupt")


def test_bad_type_in_header(tmp_path: Path) -> None:
    p = _write_ascii(tmp_path / "y.pcd", "x y z", "F F Q", ["1 2 3"])
    _assert_input_error(p, "type")


def test_write_rejects_bad_shapes(tmp_path: Path) -> None:
    with pytest.raises(ValueError):
        write_pcd(tmp_path / "a.pcd", np.zeros((5, 2)))
    with pytest.raises(ValueError):
        write_pcd(tmp_path / "a.pcd", np.zeros((6, 3)), grid_shape=(4, 2))
    with pytest.raises(ValueError):
        write_pcd(tmp_path / "a.pcd", np.zeros((6, 3)), encoding="lzma")
    assert not (tmp_path / "a.pcd").exists()
