"""A container's inside seen past its rim joins the rim; convex, untouched or barely touching segments stay apart."""

from __future__ import annotations

import numpy as np
import pytest

from realsim.perception.container_inside import concavity, join_insides


def _cap(inward: bool, n: int = 400) -> tuple[np.ndarray, np.ndarray]:
    """Points of a spherical cap of radius 5 cm at 1 m and unit normals toward the camera (at -z):
    the far half seen from inside (a bowl's inside) or the near half from outside (a ball)."""
    rng = np.random.default_rng(0)
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    d[:, 2] = np.abs(d[:, 2]) if inward else -np.abs(d[:, 2])
    return 0.05 * d + [0.0, 0.0, 1.0], (-d if inward else d)


def test_concavity_tells_inside_outside_and_flat() -> None:
    inside, n_in = _cap(True)
    outside, n_out = _cap(False)
    flat = np.c_[np.random.default_rng(1).uniform(-0.05, 0.05, (400, 2)), np.full(400, 1.0)]
    pts = np.vstack([inside, outside, flat])
    normals = np.vstack([n_in, n_out, np.tile([0.0, 0.0, -1.0], (400, 1))])
    c = concavity(np.repeat([0, 1, 2], 400), pts, normals)
    assert c[0] > 0.3 and c[1] < -0.3 and abs(c[2]) < 1e-9


def _view(inward: bool, rim_cols: int, touching: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """A 20 x 20 image: rows 0-9 a cap seen from inside or outside (segment 1 but its first and last
    columns, at about 1 m), rows 10-19 under ``rim_cols`` columns a rim 1 cm nearer than the cap's
    row 9 (segment 0; in plan the near half of a circle round the cap), the rest no segment; with
    ``touching``, the rim's column 1 lies on the cap (a lip)."""
    h = w = 20
    cap, cap_normals = _cap(inward, 200)
    pts = np.full((h, w, 3), np.nan)
    normals = np.full((h, w, 3), np.nan)
    order = np.lexsort((cap[:, 0], cap[:, 1]))  # the cap laid out in the image by its x, y
    pts[:10] = cap[order].reshape(10, 20, 3)
    normals[:10] = cap_normals[order].reshape(10, 20, 3)
    labels = np.full((h, w), -1, dtype=np.int64)
    labels[:10, 1:-1] = 1  # the cap's outline: its sides and its lower edge
    labels[10:, :rim_cols] = 0
    theta = np.linspace(0.0, np.pi, w)[:rim_cols]  # the rim: the near half of a 5 cm circle round the cap
    pts[10:, :rim_cols] = np.c_[0.05 * np.cos(theta), -0.05 * np.sin(theta), pts[9, :rim_cols, 2] - 0.01]
    normals[10:, :rim_cols] = [0.0, 0.0, -1.0]
    if touching:
        pts[10, 1] = pts[9, 1] + [0.0, 0.002, 0.0]
    return labels.ravel(), pts.reshape(-1, 3), normals.reshape(-1, 3), pts.reshape(-1, 3)[:, 2]


def test_an_inside_hidden_by_a_rim_it_touches_joins_it() -> None:
    labels, pts, normals, depth = _view(inward=True, rim_cols=20, touching=True)
    out = join_insides(labels, (20, 20), pts, normals, depth, min_jump=0.008, min_concavity=0.05, min_share=0.1)
    assert (out[labels >= 0] == 0).all() and (out[labels < 0] == -1).all()


def test_a_convex_segment_behind_stays_apart() -> None:
    labels, pts, normals, depth = _view(inward=False, rim_cols=20, touching=True)  # a ball behind a box
    out = join_insides(labels, (20, 20), pts, normals, depth, 0.008, 0.05, 0.1)
    assert len(np.unique(out[labels >= 0])) == 2


def test_an_inside_that_touches_nothing_stays_apart() -> None:
    labels, pts, normals, depth = _view(inward=True, rim_cols=20, touching=False)  # a bowl wholly behind a box
    out = join_insides(labels, (20, 20), pts, normals, depth, 0.008, 0.05, 0.1)
    assert len(np.unique(out[labels >= 0])) == 2


def test_an_inside_touched_over_a_few_pixels_stays_apart() -> None:
    labels, pts, normals, depth = _view(inward=True, rim_cols=3, touching=True)  # a neighbour leaning on a bowl
    out = join_insides(labels, (20, 20), pts, normals, depth, 0.008, 0.05, 0.1)
    assert len(np.unique(out[labels >= 0])) == 2


def _bowl_from_above(wall_shift: tuple[float, float] = (0.0, 0.0), wall_back: float = 0.0) -> tuple[np.ndarray, ...]:
    """A 15 x 20 image of a bowl seen from the front and above (world Z up, camera toward +y, 30 deg
    down): rows 0-9 its inside (a 5 cm hemisphere seen from inside, its front rim in row 9), rows
    10-14 its outer wall under the front rim (about 1 cm inside the rim in plan, 2-4 cm lower). The wall
    is moved by ``wall_shift`` (m) in plan and pushed ``wall_back`` (m) along the view."""
    w = 20
    axis = np.array([0.0, np.cos(np.radians(30)), -np.sin(np.radians(30))])  # the viewing direction
    u, v = np.meshgrid(np.linspace(-0.8, 0.8, w), np.linspace(0.8, -0.95, 10))  # v: +y (back) .. -y (front rim)
    r = np.minimum(np.hypot(u, v), 0.98)
    xy = 0.05 * np.stack([u, v], axis=-1) * (r / np.maximum(np.hypot(u, v), 1e-9))[..., None]
    cap = np.concatenate([xy, 0.05 - np.sqrt(0.05**2 - (xy**2).sum(axis=-1, keepdims=True))], axis=-1)
    inside_normals = np.array([0.0, 0.0, 0.05]) - cap  # toward the sphere's centre: seen from inside
    xs, zs = np.meshgrid(np.linspace(-0.025, 0.025, w), np.linspace(0.02, 0.005, 5))
    wall = np.stack([xs, np.full_like(xs, -0.04), zs], axis=-1) + [*wall_shift, 0.0]
    wall_normals = np.broadcast_to([0.0, -1.0, -0.3], wall.shape)
    pts = np.concatenate([cap, wall]).reshape(-1, 3)
    normals = np.concatenate([inside_normals, wall_normals]).reshape(-1, 3)
    normals = normals / np.linalg.norm(normals, axis=1, keepdims=True)
    depth = pts @ axis
    depth[10 * w:] += wall_back
    labels = np.repeat([0, 1], [10 * w, 5 * w]).astype(np.int64)
    return labels, pts, normals, depth


def test_a_wall_under_a_bowls_rim_joins_its_inside() -> None:
    from realsim.perception.container_inside import join_outsides

    labels, pts, normals, depth = _bowl_from_above()
    assert join_insides(labels, (15, 20), pts, normals, depth, 0.008, 0.05, 0.1).max() == 1  # not an inside's case
    out = join_outsides(labels, (15, 20), pts, normals, depth, 0.008, 0.05, 0.1)
    assert (out == 0).all()


@pytest.mark.parametrize("shift, back", [((0.12, 0.0), 0.0), ((0.0, 0.0), 0.1)])
def test_what_a_bowls_rim_hides_beside_or_behind_it_stays_apart(shift: tuple[float, float], back: float) -> None:
    """Out of the bowl's plan (beside it) or farther than its inside (behind it): another object."""
    from realsim.perception.container_inside import join_outsides

    labels, pts, normals, depth = _bowl_from_above(shift, back)
    out = join_outsides(labels, (15, 20), pts, normals, depth, 0.008, 0.05, 0.1)
    assert len(np.unique(out)) == 2
