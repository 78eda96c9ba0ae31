"""Open tops judged by what the camera could see inside: a deep mug at a grazing angle is hollow, a
lidded jug with a recessed top stays solid, a top the camera is below is not opened."""

from __future__ import annotations

import numpy as np
import open3d as o3d
import trimesh
from ball_drop import drop_ball

from realsim.completion.containers import cavity_floor, complete_open_container, round_rim

R, H = 0.042, 0.081  # the YCB mug's body: outer radius and height (m)


def _revolved(profile: list[tuple[float, float]]) -> trimesh.Trimesh:
    """The solid of revolution of a closed (r, z) profile about the z axis."""
    mesh = trimesh.creation.revolve(np.array(profile), sections=96)
    if mesh.volume < 0:
        mesh.invert()
    return mesh


def _mug(wall: float = 0.004, bottom: float = 0.006) -> trimesh.Trimesh:
    return _revolved([(0.0, 0.0), (R, 0.0), (R, H), (R - wall, H), (R - wall, bottom), (0.0, bottom)])


def _lidded_jug(radius: float = 0.07, height: float = 0.24, recess: float = 0.018) -> trimesh.Trimesh:
    """A tall closed jug whose lid sits ``recess`` below its rim (the YCB pitcher's scan)."""
    return _revolved([(0.0, 0.0), (radius, 0.0), (radius, height), (radius - 0.006, height),
                      (radius - 0.012, height - recess), (0.0, height - recess)])


def _view(mesh: trimesh.Trimesh, elevation_deg: float, distance: float = 1.2, seed: int = 0,
          mixed: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """(points seen, camera centre): ``mesh`` on z = 0 seen from ``distance`` away along -x, the camera
    ``elevation_deg`` above its top; a 2 mm grid of rays at the object, depth noise 1 mm, and where the
    depth jumps between neighbouring rays (over a rim), with ``mixed``, pixels between the two depths (a Kinect's)."""
    top = float(mesh.bounds[1][2])
    camera = np.array([-distance, 0.0, top + distance * np.tan(np.radians(elevation_deg))])
    lo, hi = mesh.bounds
    ys, zs = np.meshgrid(np.arange(lo[1] - 0.01, hi[1] + 0.01, 0.002), np.arange(lo[2], hi[2] + 0.03, 0.002))
    targets = np.column_stack([np.zeros(ys.size), ys.ravel(), zs.ravel()])
    directions = targets - camera
    directions /= np.linalg.norm(directions, axis=1, keepdims=True)
    scene = o3d.t.geometry.RaycastingScene()
    scene.add_triangles(o3d.core.Tensor(np.asarray(mesh.vertices, np.float32)), o3d.core.Tensor(np.asarray(mesh.faces, np.uint32)))
    rays = np.column_stack([np.repeat(camera[None], len(directions), axis=0), directions]).astype(np.float32)
    t = scene.cast_rays(o3d.core.Tensor(rays))["t_hit"].numpy()
    rng = np.random.default_rng(seed)
    grid = t.reshape(ys.shape)
    with np.errstate(invalid="ignore"):
        jump = np.isfinite(grid[1:]) & np.isfinite(grid[:-1]) & (np.abs(grid[1:] - grid[:-1]) > 0.02)
    rows, cols = np.nonzero(jump)
    t = t.copy()
    for k in (1, 2, 3) if mixed else ():  # the pixels past the edge take depths between the two
        past = rows + k < ys.shape[0]
        near, far = np.minimum(grid[rows, cols], grid[rows + 1, cols])[past], np.maximum(grid[rows, cols], grid[rows + 1, cols])[past]
        t[(rows[past] + k) * ys.shape[1] + cols[past]] = near + rng.uniform(0, 1, past.sum()) * (far - near)
    hit = np.isfinite(t)
    depth = t[hit] + rng.normal(0.0, 0.001, hit.sum())
    return camera + directions[hit] * depth[:, None], camera


def _complete(points: np.ndarray, camera: np.ndarray):
    top = float(np.percentile(points[:, 2], 98))
    rim = round_rim(points, 0.0, top, 0.2)
    assert rim is not None
    return rim, top, complete_open_container(points, rim[0], rim[1], 0.0, top, camera_xy=camera[:2], camera_z=float(camera[2]))


def test_a_deep_mug_seen_at_a_grazing_angle_is_hollow_and_holds_a_ball() -> None:
    points, camera = _view(_mug(), 27.0)
    rim, top, mug = _complete(points, camera)
    # over the near rim the camera sees the far wall's inside about 2 R tan(27 deg) = 43 mm down, never the floor
    assert mug is not None
    assert mug.floor_z < top - 0.02 and mug.visual.volume < 0.9 * mug.outer.volume  # a cavity at least as deep as the far wall seen
    x, y, z = drop_ball(mug.pieces, np.array([rim[0][0], rim[0][1], top + 0.05]), seconds=1.5)
    assert np.hypot(x - rim[0][0], y - rim[0][1]) < rim[1] and z < top - 0.005  # in the cavity, below the rim


def test_a_lidded_jug_or_can_seen_from_above_keeps_its_closed_top() -> None:
    # the jug's lid 18 mm under its rim: the camera, 33 degrees up, would see 90 mm into an open jug this wide
    for mesh, radius, elevation in ((_lidded_jug(), 0.07, 33.0), (_lidded_jug(), 0.07, 45.0),
                                    (_lidded_jug(R, H, 0.008), R, 11.0)):  # a can's lid 8 mm down, seen grazing
        points, camera = _view(mesh, elevation, mixed=False)  # no mixed pixels: only the lid's relief
        top = float(np.percentile(points[:, 2], 98))
        assert cavity_floor(points, np.zeros(2), radius, top, camera_xy=camera[:2], camera_z=float(camera[2])) is None


def test_an_opening_the_camera_is_below_is_not_seen() -> None:
    points, camera = _view(_mug(), 27.0)
    top = float(np.percentile(points[:, 2], 98))
    rim = round_rim(points, 0.0, top, 0.2)
    assert rim is not None
    assert cavity_floor(points, rim[0], rim[1], top, camera_xy=camera[:2], camera_z=float(camera[2])) is not None
    assert cavity_floor(points, rim[0], rim[1], top, camera_xy=camera[:2], camera_z=top - 0.01) is None
