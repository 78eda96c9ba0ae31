"""Release poses: the footprint a spot must keep over its support, spots within a free area."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from realsim.robot.params import PlaceParams
from realsim.robot.placing import ReleaseParams, footprint_ring, long_axis, release_poses, side_spots, spots, underside


def test_footprint_ring_reaches_half_way_to_the_edge_in_every_direction() -> None:
    rng = np.random.default_rng(0)
    box = rng.uniform([-0.1, -0.02, 0.0], [0.1, 0.02, 0.05], (2000, 3)) + [0.3, 0.2, 0.0]  # a 20 x 4 cm banana-like footprint
    ring = footprint_ring(box)
    assert np.allclose(ring[0], 0.0)
    assert np.abs(ring[:, 0]).max() == pytest.approx(0.05, abs=0.002)  # half of the 10 cm half-length
    assert np.abs(ring[:, 1]).max() == pytest.approx(0.01, abs=0.002)


def test_spots_and_poses_try_the_centre_first_then_nearer_the_robot() -> None:
    base = np.array([0.0, -1.0])
    near = spots(np.zeros(2), 0.04, base, ring=6)
    assert np.allclose(near[0], 0.0) and len(near) == 13
    assert np.linalg.norm(near[1] - base) <= np.linalg.norm(near[6] - base)
    poses = release_poses(near, ReleaseParams())
    assert len(poses) == 6 + 6 + 12 * 3 <= ReleaseParams().max_poses
    assert {round(y, 3) for _, y, _ in poses[:6]} == {round(y, 3) for y in ReleaseParams().yaws}  # every yaw at the first spot
    assert all(d == ReleaseParams().drops[0] for _, _, d in poses[:42])  # the other spots before any higher release
    assert all(np.allclose(xy, 0.0) and d > ReleaseParams().drops[0] for xy, _, d in poses[42:])  # higher releases last, within the limit


def test_underside_keeps_the_lowest_point_of_every_cell() -> None:
    rng = np.random.default_rng(1)
    xy = rng.uniform(-0.1, 0.1, (5000, 2))
    rod = np.column_stack([xy, 0.2 * xy[:, 0] + rng.uniform(0.0, 0.02, len(xy))])  # a tipped slab, 2 cm thick
    low = underside(rod, 0.02)
    assert 90 <= len(low) <= 110  # one point per 2 cm cell of the 20 x 20 cm footprint
    cells = np.floor(rod[:, :2] / 0.02).astype(int)
    for p in low[:10]:
        same = np.all(cells == np.floor(p[:2] / 0.02).astype(int), axis=1)
        assert p[2] == pytest.approx(rod[same, 2].min())


def test_long_axis_follows_the_footprint() -> None:
    rng = np.random.default_rng(2)
    local = rng.uniform([-0.1, -0.02, 0.0], [0.1, 0.02, 0.03], (3000, 3))
    for angle in (0.0, 0.7, 2.0):
        c, s = np.cos(angle), np.sin(angle)
        pts = local @ np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]]) + [0.4, -0.1, 0.75]
        axis = long_axis(pts)
        assert abs(float(axis @ [c, s])) == pytest.approx(1.0, abs=1e-3)  # either end


def test_the_free_part_of_an_occupied_opening() -> None:
    from realsim.robot.placing import free_first, free_radius, narrowest

    ang = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    can = 0.034 * np.column_stack([np.cos(ang), np.sin(ang)])  # a can's outline in the middle of a 7 cm opening (its inside counts as filled)
    assert free_radius(np.zeros(2), 0.07, []) == pytest.approx(0.07, abs=0.004)
    assert free_radius(np.zeros(2), 0.07, [can]) == pytest.approx(0.018, abs=0.004)  # the ring around it
    assert free_radius(np.zeros(2), 0.07, [can + [0.036, 0.0]]) == pytest.approx(0.036, abs=0.004)  # pushed to one side
    near = spots(np.zeros(2), 0.03, np.array([0.0, -1.0]))
    ordered = free_first(near, can + [0.036, 0.0])
    assert ordered[0][0] == pytest.approx(-0.027, abs=1e-6)  # the spot farthest from it first
    assert free_first(near, np.zeros((0, 2))) == near
    rng = np.random.default_rng(3)
    rod = rng.uniform([-0.1, -0.02, 0.0], [0.1, 0.02, 0.03], (3000, 3))
    assert narrowest(rod) == pytest.approx(0.04, abs=0.002)


def _disc(centre: tuple[float, float], radius: float) -> np.ndarray:
    """Points filling a disc (rings 5 mm apart, 64 points each, one on every axis)."""
    ang = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    pts = [(rr * np.cos(a) + centre[0], rr * np.sin(a) + centre[1], 0.0) for rr in np.linspace(0.0, radius, int(radius / 0.005) + 1) for a in ang]
    return np.array(pts)


def test_side_spots_reach_down_to_the_least_gap_the_relation_accepts_off_a_round_corner() -> None:
    pl = PlaceParams()
    bowl, mug = _disc((0.0, 0.0), 0.08), _disc((0.3, 0.3), 0.045)
    d = np.array([1.0, 0.0])
    cands = side_spots(mug, bowl, d, pl.beside_gap, pl)
    assert np.allclose(cands[0][1], [0.08 + pl.beside_gap + 0.045, 0.0], atol=2e-3)  # straight out at the asked gap first
    gaps = np.array([xy[0] - 0.045 - 0.08 for _, xy in cands])
    assert gaps.min() == pytest.approx(pl.overlap_margin - pl.side_overlap, abs=2e-3)  # never nearer than the relation accepts
    tree = cKDTree(bowl[:, :2])
    near = [xy for (_, xy), g in zip(cands, gaps) if g < min(pl.beside_along) + pl.beside_gap - 1e-6]
    clear = [xy for xy in near if tree.query(_disc(tuple(xy), 0.045)[:, :2])[0].min() >= 0.01]
    assert clear and all(abs(xy[1]) > 0.02 for xy in clear)  # the nearer spots that clear the bowl lie off the line, past its round corner


def _walled_pad(half: float, gap: float):
    """A 5 cm cube to place, a square pad ``half`` a side wide and four 12 cm walls ``gap`` off its edges."""
    from test_robot import box_object, build, loaded

    tx, ty, t, w = 0.05, 0.15, half + gap + 0.025, 2 * (half + gap) + 0.10
    walls = [((tx + t, ty), (0.05, w, 0.12)), ((tx - t, ty), (0.05, w, 0.12)),
             ((tx, ty + t), (2 * (half + gap), 0.05, 0.12)), ((tx, ty - t), (2 * (half + gap), 0.05, 0.12))]
    objs = [box_object(1, "cube", (0.1, -0.15), (0.05, 0.05, 0.05)), box_object(2, "pad", (tx, ty), (2 * half, 2 * half, 0.02), mass=0.3)]
    objs += [box_object(3 + i, f"wall{i}", xy, ext, mass=0.3) for i, (xy, ext) in enumerate(walls)]
    return loaded(build(objs))


@pytest.mark.parametrize(("half", "gap"), [(0.05, 0.005), (0.03, 0.002)])
def test_place_on_never_lands_the_object_on_a_taller_neighbour(half: float, gap: float) -> None:
    """A pad walled in by taller neighbours: on a 10 cm pad, walls 5 mm off its edges, the
    fingers' sweep cannot keep 1 cm from them but the cube can, and it is placed; on a 6 cm pad,
    walls 2 mm off, no pose keeps the cube itself 1 cm clear, so nothing is released (released
    anyway, it would land on a wall's edge and shove it). No wall ever moves."""
    from realsim.planner import relations
    from realsim.robot import Robot

    model, data = _walled_pad(half, gap)
    robot = Robot(model, data)
    start = {f"wall{i}": data.xpos[model.body(f"wall{i}").id].copy() for i in range(4)}
    assert robot.grasp("cube").success
    res = robot.place_on("cube", "pad")
    if half > 0.04:
        assert res.success, res.reason
        assert relations.on(robot.object_points("cube"), robot.object_points("pad"), robot.geometry.touching("cube"), "pad").ok
    else:
        assert not res.success and "leaves 10 mm" in res.reason
        assert robot.held == "cube" and robot.holding("cube")
    for name, p0 in start.items():
        assert np.linalg.norm(data.xpos[model.body(name).id] - p0) < 0.003, name
