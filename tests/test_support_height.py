"""Supports as a room capture shows them: a floor whose fit leans a little, seen metres from the
capture's origin, still gives every table its height above the floor there; a table top's
underside, sampled by a capture from around, joins no lower table beside it."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import open3d as o3d

from realsim.perception.capture import LoadParams, load_capture
from realsim.perception.planes import detect_planes, height_where_seen


def _top(rng: np.random.Generator, x: tuple[float, float], y: tuple[float, float], spacing: float = 0.01) -> np.ndarray:
    """Points ``spacing`` apart over the rectangle ``x`` by ``y`` at height 0."""
    xy = np.stack(np.meshgrid(np.arange(*x, spacing), np.arange(*y, spacing)), axis=-1).reshape(-1, 2)
    xy = xy + rng.uniform(-spacing / 3, spacing / 3, xy.shape)
    return np.column_stack([xy, np.zeros(len(xy))])


def test_height_where_seen_is_the_plane_at_the_points_centroid() -> None:
    normal = np.array([np.sin(np.radians(0.5)), 0.0, np.cos(np.radians(0.5))])
    points = np.array([[3.0, 1.0, 0.0], [4.0, 1.0, 0.0], [3.5, 2.0, 0.0]])
    d = -float(normal @ np.array([3.5, 4.0 / 3.0, 0.02]))  # the plane passes 2 cm above the centroid
    assert abs(height_where_seen(points, normal, d) - 0.02) < 1e-12


def test_a_floor_leaning_far_from_the_origin_gives_the_table_its_height_above_it(tmp_path: Path) -> None:
    """The floor is seen 2.5-4.5 m from the origin and leans 0.15 deg (a far, noisy floor's fit):
    under the origin its plane lies 9 mm off where it was seen; the table stands 0.75 m above the
    floor where the floor was seen."""
    rng = np.random.default_rng(0)
    table = _top(rng, (-0.6, 0.6), (-0.4, 0.4), 0.006) + [0.0, 0.0, 0.75]
    floor = _top(rng, (2.5, 4.5), (-0.5, 0.5), 0.025)
    lean = np.tan(np.radians(0.15))
    floor[:, 2] = (floor[:, 0] - 3.5) * lean  # 0 at the floor's centre, leaning along x
    points = np.vstack([table, floor]) + rng.normal(0.0, 0.0005, (len(table) + len(floor), 3))
    path = tmp_path / "room.ply"
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    o3d.io.write_point_cloud(str(path), cloud)
    scene = detect_planes(load_capture(path, LoadParams(units="m", up="+z")))
    floor_plane = next(p for p in scene.planes if p.kind == "floor")
    tables = [p for p in scene.planes if p.kind != "floor"]
    assert floor_plane.observed and len(tables) == 1
    assert abs(tables[0].height - floor_plane.height - 0.75) < 0.002  # under the origin: 9 mm off


def _write(tmp_path: Path, points: np.ndarray) -> Path:
    path = tmp_path / "room.ply"
    o3d.io.write_point_cloud(str(path), o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points)))
    return path


def test_a_table_underside_level_with_a_lower_table_beside_it_is_no_support(tmp_path: Path) -> None:
    """A 4 cm thick table top at 0.75 m, its underside at 0.71 m; a small table beside it with its
    top at 0.71 m, 40 cm away. The underside joined to the small table spread it under the big
    one, whose top was then taken for an object standing on it (rooms:414's 200k cloud)."""
    rng = np.random.default_rng(1)
    top = _top(rng, (-0.6, 0.6), (-0.4, 0.4), 0.006) + [0.0, 0.0, 0.75]
    under = _top(rng, (-0.6, 0.6), (-0.4, 0.4), 0.015) + [0.0, 0.0, 0.71]
    side = _top(rng, (1.0, 1.5), (-0.25, 0.25), 0.006) + [0.0, 0.0, 0.71]
    floor = _top(rng, (-1.5, 2.0), (-1.5, 1.5), 0.03)
    points = np.vstack([top, under, side, floor])
    points = points + rng.normal(0.0, 0.0005, points.shape)
    scene = detect_planes(load_capture(_write(tmp_path, points), LoadParams(units="m", up="+z")))
    tables = sorted((p for p in scene.planes if p.kind != "floor"), key=lambda p: p.height)
    assert [round(p.height, 2) for p in tables] == [0.71, 0.75]
    assert max(tables[0].rect_size) < 0.6  # the small table alone, not spread under the big one
