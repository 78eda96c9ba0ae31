"""Which side of a patch a scan saw (realsim.perception.visibility): rays escape from outside."""

from __future__ import annotations

import numpy as np

from realsim.perception.visibility import escape_directions, visibility_score


def _box(lo: np.ndarray, hi: np.ndarray, step: float) -> np.ndarray:
    """Points on the five faces of a box standing on the ground (no bottom)."""
    axes = [np.arange(lo[i], hi[i] + 1e-9, step) for i in range(3)]
    faces = []
    for axis in range(3):
        for value in (lo[axis], hi[axis]):
            if axis == 2 and value == lo[2]:
                continue
            u, v = np.meshgrid(*[axes[i] for i in range(3) if i != axis], indexing="ij")
            pts = np.empty((u.size, 3))
            pts[:, axis] = value
            pts[:, [i for i in range(3) if i != axis]] = np.stack([u.ravel(), v.ravel()], axis=1)
            faces.append(pts)
    return np.vstack(faces)


def _cup(radius: float, height: float, step: float) -> np.ndarray:
    """An open cylinder (a cup without a handle): wall and bottom, open at the top."""
    ang = np.arange(0.0, 2 * np.pi, step / radius)
    z = np.arange(0.0, height, step)
    a, zz = np.meshgrid(ang, z)
    wall = np.stack([radius * np.cos(a.ravel()), radius * np.sin(a.ravel()), zz.ravel()], axis=1)
    g = np.arange(-radius, radius, step)
    gx, gy = np.meshgrid(g, g)
    inside = gx.ravel() ** 2 + gy.ravel() ** 2 < radius**2
    bottom = np.stack([gx.ravel()[inside], gy.ravel()[inside], np.full(inside.sum(), 0.005)], axis=1)
    return np.vstack([wall, bottom])


def test_directions_cover_the_upper_hemisphere() -> None:
    dirs = escape_directions()
    assert np.allclose(np.linalg.norm(dirs, axis=1), 1.0)
    assert dirs[:, 2].min() >= 0.0 and dirs[:, 2].max() == 1.0


def test_closed_box_is_seen_from_outside_only() -> None:
    step = 0.003
    pts = _box(np.array([0.0, 0.0, 0.0]), np.array([0.08, 0.06, 0.07]), step)
    centres = np.array([[0.08, 0.03, 0.035], [0.0, 0.03, 0.035], [0.04, 0.06, 0.035], [0.04, 0.03, 0.07]])
    outward = np.array([[1.0, 0, 0], [-1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]])
    assert (visibility_score(pts, centres, outward, step, 0.3) > 0).all()
    assert (visibility_score(pts, centres, -outward, step, 0.3) < 0).all()


def test_thin_wall_faces_its_more_open_side() -> None:
    """A cup's wall is seen from inside (through its opening) and from outside; the outside is
    open over more of the hemisphere, and the score says by how much, not just its sign."""
    step = 0.003
    pts = _cup(0.04, 0.09, step)
    centres = np.array([[0.04, 0.0, 0.04], [0.0, -0.04, 0.04]])
    to_axis = np.array([[-1.0, 0, 0], [0, 1.0, 0]])
    score = visibility_score(pts, centres, to_axis, step, 0.3)
    assert (score < 0).all() and np.array_equal(visibility_score(pts, centres, -to_axis, step, 0.3), -score)
    assert (np.abs(score) < len(escape_directions())).all()  # the inside sees out too (through the opening)


def test_sides_facing_across_a_crack_see_out_of_it() -> None:
    """Two boxes 1.5 cm apart: the side of each that faces the other is its outside."""
    step = 0.003
    a = _box(np.array([0.0, 0.0, 0.0]), np.array([0.06, 0.06, 0.06]), step)
    b = _box(np.array([0.075, -0.02, 0.0]), np.array([0.16, 0.08, 0.09]), step)
    pts = np.vstack([a, b])
    centres = np.array([[0.06, 0.03, 0.03], [0.075, 0.03, 0.045]])
    outward = np.array([[1.0, 0, 0], [-1.0, 0, 0]])  # a faces +x towards b, b faces -x towards a
    assert (visibility_score(pts, centres, outward, step, 0.3) > 0).all()


def test_grouped_points_of_a_cup_keep_their_sides() -> None:
    """Scored in groups two cells across, every point of a cup's wall gets the side it gets alone
    (the wall's outside and inside fall in different groups by their normals' octants)."""
    step = 0.004
    pts = _cup(0.04, 0.09, step)
    wall = pts[pts[:, 2] > 0.02][::3]
    outward = np.c_[wall[:, :2] / np.linalg.norm(wall[:, :2], axis=1, keepdims=True), np.zeros(len(wall))]
    for normals in (outward, -outward):
        alone = visibility_score(pts, wall, normals, step, 0.3)
        grouped = visibility_score(pts, wall, normals, step, 0.3, group=2 * step)
        assert len(grouped) == len(wall)
        assert (np.sign(grouped) == np.sign(alone)).mean() > 0.95


def test_empty_blocks_are_skipped_without_changing_counts() -> None:
    """Rays jump over blocks with no occupied cell; the counts equal a march through every cell."""
    from realsim.perception.visibility import _escapes, _Occupancy

    rng = np.random.default_rng(5)
    # a checkerboard of 16-cell blocks: scattered cells (1..14 into their block, so that the
    # dilation stays inside it) in every other block, empty blocks between them
    blocks = np.array([(i, j, k) for i in range(5) for j in range(5) for k in range(5) if (i + j + k) % 2 == 0])
    local = rng.integers(1, 15, size=(len(blocks), 20, 3))
    occupied = _Occupancy((blocks[:, None, :] * 16 + local).reshape(-1, 3))
    origin = rng.uniform(-10.0, 90.0, size=(400, 3))
    dirs = escape_directions()
    reach_cells = 90.0

    def plain(o: np.ndarray, d: np.ndarray) -> bool:
        ijk = np.floor(o + np.arange(0.0, reach_cells + 1e-9)[:, None] * d).astype(np.int64)
        return not occupied.data[occupied.flat(ijk)].any()

    expected = np.array([sum(plain(o, d) for d in dirs) for o in origin])
    counts = _escapes(occupied, origin, dirs, 1.0, reach_cells)
    assert np.array_equal(counts, expected)
    assert 0 < expected.mean() < len(dirs)  # some rays blocked, some free
