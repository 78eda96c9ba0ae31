"""Parts of one open round container are joined; neighbours that are not one container are not
(generated surfaces: a bowl's wall and floor, cups, a ball)."""

from __future__ import annotations

import numpy as np
import pytest

from realsim.completion.containers import round_rim
from realsim.completion.parts import one_container, outer_wall_part
from realsim.composition.layout import declared_support
from realsim.scene import Scene, SceneObject


def _bowl(centre: tuple[float, float], radius: float = 0.07, height: float = 0.055, seed: int = 0) -> np.ndarray:
    """Points on a bowl's wall (r growing with height, inside and outside a 4 mm wall), floor and
    rounded lip; every other one of the first 4000 points is on the outside of the wall."""
    rng = np.random.default_rng(seed)
    t = rng.uniform(0, 2 * np.pi, 4000)
    z = rng.uniform(0.005, height, 4000)
    r = 0.045 + (radius - 0.045) * np.sqrt(z / height) + np.tile([0.002, -0.002], 2000)
    wall = np.column_stack([centre[0] + r * np.cos(t), centre[1] + r * np.sin(t), z])
    fr, ft = 0.045 * np.sqrt(rng.random(800)), rng.uniform(0, 2 * np.pi, 800)
    floor = np.column_stack([centre[0] + fr * np.cos(ft), centre[1] + fr * np.sin(ft), np.full(800, 0.006)])
    lr, lt = rng.uniform(-0.002, 0.002, 600), rng.uniform(0, 2 * np.pi, 600)  # the lip: rounded, highest mid-wall
    lip = np.column_stack([centre[0] + (radius + lr) * np.cos(lt), centre[1] + (radius + lr) * np.sin(lt), height + 0.001 * (1 - (lr / 0.002) ** 2)])
    return np.vstack([wall, floor, lip]) + rng.normal(0, 0.0003, (5400, 3))


def test_two_halves_of_a_bowl_are_one_container_and_their_rim_is_its_rim() -> None:
    bowl = _bowl((0.3, 0.1))
    left, right = bowl[bowl[:, 0] < 0.3], bowl[bowl[:, 0] >= 0.3]
    assert round_rim(left[left[:, 1] < 0.1], 0.0, 0.055, 0.2) is None  # a quarter of a rim is no circle to complete alone
    assert one_container(left, right, 0.0, 0.2)
    centre, radius = round_rim(bowl, 0.0, 0.055, 0.2) or (np.zeros(2), 0.0)
    assert np.linalg.norm(centre - [0.3, 0.1]) < 0.002 and abs(radius - 0.07) < 0.003


def test_a_rim_fitted_to_its_crest_is_not_pulled_toward_the_camera() -> None:
    bowl = _bowl((0.0, 0.0), seed=1)
    outside = np.zeros(len(bowl), bool)
    outside[:4000:2] = True
    inside = ~outside
    inside[4800:] = True  # the lip is seen all round
    seen = bowl[((bowl[:, 0] < 0) & outside) | ((bowl[:, 0] >= 0) & inside) | (np.arange(len(bowl)) >= 4800)]  # a camera at -x
    centre, _ = round_rim(seen, 0.0, 0.055, 0.2) or (np.full(2, np.inf), 0.0)
    assert np.linalg.norm(centre) < 0.0004  # the whole top band: 0.9 mm toward the camera


def test_neighbours_that_are_not_one_container_stay_apart() -> None:
    a, b = _bowl((0.0, 0.0), seed=2), _bowl((0.155, 0.0), seed=3)
    assert not one_container(a, b, 0.0, 0.2)  # two bowls side by side: two rims
    rng = np.random.default_rng(4)
    d = rng.normal(size=(600, 3))
    ball = 0.02 * d / np.linalg.norm(d, axis=1, keepdims=True) + [0.0, 0.0, 0.03]
    assert not one_container(a, ball, 0.0, 0.2)  # a ball lying in the bowl has no point on its rim


def test_the_lower_outside_of_a_near_wall_is_the_container_and_a_ball_in_it_is_not() -> None:
    camera = np.array([-0.6, 0.0, 0.5])  # at -x, above: it sees the near wall's outside and the far wall's inside
    bowl = _bowl((0.0, 0.0), seed=5)
    outside = np.zeros(len(bowl), bool)
    outside[:4000:2] = True
    wall = np.arange(len(bowl)) < 4000
    near, low = bowl[:, 0] < 0, bowl[:, 2] <= 0.03
    part = bowl[wall & outside & near & low]  # split off where the wall curves in under the rim
    seen = (wall & outside & near & ~low) | (wall & ~outside & ~near) | (np.arange(len(bowl)) >= 4000)
    container = bowl[seen & ~(wall & outside & near & low)]
    assert not one_container(container, part, 0.0, 0.2)  # no point of the part on the rim
    assert outer_wall_part(container, part, 0.0, 0.2, camera)
    rng = np.random.default_rng(6)
    d = rng.normal(size=(1500, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    ball = 0.015 * d + [-0.03, 0.0, 0.03]  # lying in the bowl against its near wall: seen over the rim
    ball = ball[(d @ (camera - [-0.03, 0.0, 0.03]) > 0) & (d[:, 2] > 0.3)]
    assert not outer_wall_part(container, ball, 0.0, 0.2, camera)
    assert not outer_wall_part(container, part + [0.25, 0.0, 0.0], 0.0, 0.2, camera)  # a neighbour beyond the rim


def test_two_arcs_of_a_bowl_with_the_middle_hidden_are_one_container() -> None:
    bowl = _bowl((0.1, -0.2), seed=7)
    bowl = bowl[bowl[:, 2] > 0.02]  # the upper wall and the lip
    angle = np.degrees(np.arctan2(bowl[:, 1] + 0.2, bowl[:, 0] - 0.1))
    a, b = bowl[(angle > -160) & (angle < -20)], bowl[(angle > 50) & (angle < 130)]  # objects in front hide the rest
    gap = np.maximum(a[:, :2].min(axis=0) - b[:, :2].max(axis=0), b[:, :2].min(axis=0) - a[:, :2].max(axis=0))
    assert np.any(gap > 0.02)  # their footprints' bounds lie apart
    assert one_container(a, b, 0.0, 0.2)
    assert not one_container(bowl[(angle > -160) & (angle < -60)], bowl[(angle > 50) & (angle < 100)], 0.0, 0.2)  # less than half a turn


def test_every_first_verdict_is_shared_with_a_helper_and_the_merges_are_the_same(monkeypatch: pytest.MonkeyPatch) -> None:
    import realsim.completion.parts as parts

    bowl, cup = _bowl((0.3, 0.1), seed=8), _bowl((-0.2, 0.0), radius=0.04, height=0.08, seed=9)
    ball = np.random.default_rng(10).normal(size=(800, 3))
    ball = 0.03 * ball / np.linalg.norm(ball, axis=1, keepdims=True) + [0.0, 0.3, 0.03]
    points = np.vstack([bowl, cup, ball])
    points[:, 2] += declared_support(None).height  # standing on the table
    halves = np.where(bowl[:, 0] < 0.3, 1, 2)  # the bowl in two, the cup and the ball whole
    labels = np.r_[halves, np.full(len(cup), 3), np.full(len(ball), 4)].astype(np.int32)

    def merged(workers: str) -> tuple[list[tuple[int, int]], np.ndarray, list[int]]:
        monkeypatch.setenv("REALSIM_WORKERS", workers)
        plane = declared_support(None)
        scene = Scene.unread(None)
        scene.points, scene.labels, scene.planes = points, labels.copy(), [plane]
        scene.objects = [SceneObject(id=k, name=f"obj{k}", label="object", position=np.zeros(3), quat=np.array([1.0, 0, 0, 0]),
                                     size=np.full(3, 0.1), support_id=plane.id, point_count=int((labels == k).sum())) for k in (1, 2, 3, 4)]
        pairs = parts.merge_container_parts(scene, 0.2, camera=np.array([-0.6, 0.0, 1.25]))
        return pairs, scene.labels, [o.id for o in scene.objects]

    alone = merged("1")
    shared: list[int] = []
    fork_map = parts.fork_map
    monkeypatch.setattr(parts, "fork_map", lambda fn, n, least: shared.append(n) or fork_map(fn, n, least=least))
    monkeypatch.setattr(parts, "SHARED_PAIRS", 2)  # shared however few the pairs (a real scene shares from 16)
    together = merged("2")
    assert shared[0] == 6  # the four objects' six pairs at once
    assert alone[0] == together[0] and sorted(alone[0][0]) == [1, 2]  # the bowl's halves joined
    assert np.array_equal(alone[1], together[1]) and alone[2] == together[2]
