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


def _sequence(folder: Path, frames: int = 3) -> None:
    """A minimal Stray Scanner folder: a slanted wall about 1.1 m ahead, seen from near the origin."""
    from PIL import Image

    (folder / "rgb").mkdir(parents=True)
    (folder / "depth").mkdir()
    for i in range(frames):
        Image.fromarray(np.full((48, 64, 3), 120, np.uint8)).save(folder / "rgb" / f"{i:06d}.png")
        Image.fromarray((1000 + np.arange(64) * 3 + np.arange(48)[:, None]).astype(np.uint16)).save(folder / "depth" / f"{i:06d}.png")
    (folder / "camera_matrix.csv").write_text("50,0,32\n0,50,24\n0,0,1\n")
    rows = ["timestamp, frame, x, y, z, qx, qy, qz, qw"] + [f"{i / 30}, {i}, {0.01 * i}, 0, 0, 0, 0, 0, 1" for i in range(frames)]
    (folder / "odometry.csv").write_text("\n".join(rows) + "\n")


@pytest.mark.parametrize("damage", ["truncated depth", "truncated colour", "no depth", "missing frames", "missing poses"])
def test_broken_sequence_is_an_input_error(tmp_path: Path, damage: str) -> None:
    from PIL import Image

    from realsim.perception.rgbd import fuse_sequence

    folder = tmp_path / "seq"
    _sequence(folder, 4)
    first = {"truncated depth": folder / "depth" / "000000.png", "truncated colour": folder / "rgb" / "000000.png"}
    if damage in first:
        raw = first[damage].read_bytes()
        first[damage].write_bytes(raw[: len(raw) // 3])
    elif damage == "no depth":
        for p in (folder / "depth").glob("*.png"):
            Image.fromarray(np.zeros((48, 64), np.uint16)).save(p)
    elif damage == "missing frames":
        for p in sorted((folder / "depth").glob("*.png"))[1:]:
            p.unlink()
    else:
        lines = (folder / "odometry.csv").read_text().splitlines()
        (folder / "odometry.csv").write_text("\n".join(lines[:2]) + "\n")
    with pytest.raises(InputError):
        fuse_sequence(folder)


def test_sequence_with_a_blank_frame_fuses(tmp_path: Path) -> None:
    """A frame without depth (lens covered, out of range) is skipped; it used to crash the fusion."""
    from PIL import Image

    from realsim.perception.rgbd import fuse_sequence

    _sequence(tmp_path / "seq", 4)
    Image.fromarray(np.zeros((48, 64), np.uint16)).save(tmp_path / "seq" / "depth" / "000002.png")
    pts, _ = fuse_sequence(tmp_path / "seq")
    assert len(pts) > 100 and -1.3 < np.median(pts[:, 2]) < -1.0  # ARKit: the camera looks along -z


@pytest.mark.parametrize("suffix", [".usda", ".usdz"])
def test_truncated_usd_is_an_input_error(tmp_path: Path, suffix: str) -> None:
    from realsim.perception.usd_mesh import read_usd_mesh

    path = tmp_path / f"room{suffix}"
    path.write_bytes(b"#usda 1.0\n(\n    metersPerUnit = 0.01\n" if suffix == ".usda" else b"PK\x03\x04\x14\x00\x00")
    with pytest.raises(InputError, match="cannot open the USD stage"):
        read_usd_mesh(path)


def _counter_under_wall(seed: int = 0, ledge_width: float = 0.08, noise: float = 0.001) -> np.ndarray:
    """A 1.5 x 0.6 m counter top at 0.9 m, a 3 m wide wall behind it (larger than the counter,
    from 0.85 to 1.65 m, its top a ledge ``ledge_width`` wide) and a 10 cm box on the counter; no floor."""
    rng = np.random.default_rng(seed)
    top = np.c_[rng.uniform([-0.75, -0.3], [0.75, 0.3], (9000, 2)), np.full(9000, 0.9)]
    wall = np.c_[rng.uniform(-1.5, 1.5, 24000), np.full(24000, 0.32), rng.uniform(0.85, 1.65, 24000)]
    ledge = np.c_[rng.uniform([-1.5, 0.32], [1.5, 0.32 + ledge_width], (2400, 2)), np.full(2400, 1.65)]
    box = rng.uniform([0, -0.1, 0.9], [0.1, 0.0, 1.0], (3000, 3))
    return np.vstack([top, wall, ledge, box]) + rng.normal(0, noise, (38400, 3))


@pytest.mark.parametrize(("ledge_width", "noise"), [(0.08, 0.001), (0.1, 0.005)])
def test_counter_under_a_wall_without_floor_is_up_and_alone(tmp_path: Path, ledge_width: float, noise: float) -> None:
    """The wall is the largest plane, yet the box rests on the counter: +z is up; the wall's top is
    a ledge 8-10 cm wide, not a support 0.75 m over a 'floor' (the counter taken for the floor),
    also where 5 mm noise scatters its edge points a centimetre or two past it."""
    from realsim.perception.planes import detect_planes

    (tmp_path / "cap").mkdir()
    _write_ply_double(tmp_path / "cap" / "scene.ply", _counter_under_wall(ledge_width=ledge_width, noise=noise))
    (tmp_path / "cap" / "capture.yaml").write_text("support_height: 0.9\n")
    scene = detect_planes(load_capture(tmp_path / "cap"))
    assert scene.capture.up == "+z"
    observed = [p for p in scene.planes if p.observed]
    assert len(observed) == 1 and abs(observed[0].height - 0.9) < 0.01


def _video(folder: Path, frames: int, codec: str = "libx265") -> None:
    """Replace the sequence's rgb/ by an rgb.mp4 of ``frames`` frames (HEVC, as Stray Scanner writes)."""
    import imageio.v3 as iio
    from PIL import Image

    pictures = [np.asarray(Image.open(p)) for p in sorted((folder / "rgb").glob("*.png"))][:frames]
    iio.imwrite(folder / "rgb.mp4", np.stack(pictures), fps=30, codec=codec)
    for p in (folder / "rgb").glob("*.png"):
        p.unlink()
    (folder / "rgb").rmdir()


@pytest.mark.parametrize("codec", ["libx265", "libx264"])
def test_sequence_with_a_colour_video_fuses_like_its_frames(tmp_path: Path, codec: str) -> None:
    """Stray Scanner's rgb.mp4 in place of rgb/: the same surface as the PNG frames, coloured from the video."""
    from realsim.perception.rgbd import fuse_sequence

    _sequence(tmp_path / "png", 4)
    _sequence(tmp_path / "mp4", 4)
    _video(tmp_path / "mp4", 4, codec)
    pts_png, _ = fuse_sequence(tmp_path / "png")
    pts, cols = fuse_sequence(tmp_path / "mp4")
    assert np.array_equal(pts, pts_png)  # colour never moves the surface
    assert abs(float(np.median(cols)) - 120 / 255) < 0.03  # the frames' grey, through the codec


@pytest.mark.parametrize("damage", ["junk", "truncated", "too short"])
def test_broken_colour_video_is_an_input_error(tmp_path: Path, damage: str) -> None:
    from realsim.perception.rgbd import fuse_sequence

    folder = tmp_path / "seq"
    _sequence(folder, 6)
    _video(folder, 2 if damage == "too short" else 6)
    video = folder / "rgb.mp4"
    if damage == "junk":
        video.write_bytes(b"not a video")
    elif damage == "truncated":
        video.write_bytes(video.read_bytes()[: video.stat().st_size // 3])
    with pytest.raises(InputError, match="rgb.mp4"):
        fuse_sequence(folder)
