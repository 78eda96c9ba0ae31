"""A thin-walled mug seen from one side: its wall where the camera saw it, its handle kept and welded."""

from __future__ import annotations

import numpy as np
from ball_drop import drop_ball

from realsim.completion.containers import ContainerParams, complete_open_container, round_rim
from realsim.completion.handles import handle_pieces

R, WALL, H = 0.04, 0.0015, 0.09  # outer radius, wall, height (m): a mug with a 1.5 mm wall (under the sensor noise)
CAMERA_XY = np.array([-0.6, 0.0])  # the camera looks along +x, from above (the near wall faces -x)
LOOP_R, LOOP_C, TUBE = 0.022, np.array([0.0, -0.052, 0.045]), 0.005  # handle loop in the plane x = 0, on the -y side


def _mug(seed: int = 0) -> np.ndarray:
    """What the camera sees: the near wall's outside, the far wall's inside over the rim, the rim,
    and the side of the handle facing it (noise 1 mm)."""
    rng = np.random.default_rng(seed)
    a = np.radians(rng.uniform(100, 260, 4000))  # facing -x
    z = rng.uniform(0.0, H, 4000)
    near = np.column_stack([R * np.cos(a), R * np.sin(a), z])
    a = np.radians(rng.uniform(-80, 80, 3000))  # the far side, seen inside
    z = rng.uniform(0.4 * H, H, 3000)
    far = np.column_stack([(R - WALL) * np.cos(a), (R - WALL) * np.sin(a), z])
    a, r = rng.uniform(0, 2 * np.pi, 1500), rng.uniform(R - WALL, R, 1500)
    rim = np.column_stack([r * np.cos(a), r * np.sin(a), np.full(1500, H)])
    t, p = rng.uniform(0, 2 * np.pi, (2, 20000))  # the handle: a tube around a circle in the plane x = 0
    centre = LOOP_C + LOOP_R * np.column_stack([np.zeros_like(t), np.cos(t), np.sin(t)])
    normal = np.cos(p)[:, None] * np.column_stack([np.zeros_like(t), np.cos(t), np.sin(t)]) + np.sin(p)[:, None] * np.array([1.0, 0.0, 0.0])
    surface = centre + TUBE * normal
    seen = (normal[:, 0] < -0.2) & (np.linalg.norm(surface[:, :2], axis=1) > R + 0.001)  # faces the camera, off the body
    pts = np.vstack([near, far, rim, surface[seen][:1500]])
    return pts + rng.normal(0, 0.001, pts.shape)


def test_a_thin_wall_is_completed_where_both_its_sides_were_seen_and_the_handle_kept() -> None:
    pts = _mug()
    rim = round_rim(pts, 0.0, H, 0.2)
    assert rim is not None
    mug = complete_open_container(pts, rim[0], rim[1], 0.0, H, camera_xy=CAMERA_XY)
    assert mug is not None
    # thinner than the least wall (3 mm): that wall, straddling the true one, straight up the side
    assert mug.wall == ContainerParams().min_wall
    outside = np.interp(np.array([0.3, 0.5, 0.8]) * H, *mug.outside)
    assert np.all(np.abs(outside - (R + (mug.wall - WALL) / 2)) < 0.001)
    handle = handle_pieces(pts, rim[0], mug.outside, CAMERA_XY)
    assert 2 <= len(handle) <= 4
    verts = np.vstack([h.vertices for h in handle])
    reach = LOOP_C[1] - LOOP_R - TUBE  # the handle's far end (-y)
    assert abs(verts[:, 1].min() - reach) < 0.004
    assert np.ptp(verts[:, 0]) > 1.5 * TUBE  # the hidden half mirrored: as thick as the tube
    assert np.linalg.norm(verts[:, :2] - rim[0], axis=1).min() < R  # welded into the wall
    opening = np.array([[0.0, LOOP_C[1] - 0.004, LOOP_C[2]]])  # inside the loop, off the body
    assert not any(h.contains(opening)[0] for h in handle)
    # still a container: a ball dropped in stays inside
    x, y, z = drop_ball([*mug.pieces, *handle], np.array([rim[0][0] + 0.01, rim[0][1], 0.15]), seconds=1.5)
    assert np.hypot(x - rim[0][0], y - rim[0][1]) < R and z < H
