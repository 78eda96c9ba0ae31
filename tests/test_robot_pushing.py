"""Push strokes: the asked one first, shorter or askew ones within the move's tolerance, and
which neighbours a swept footprint shoves (generated footprints); what may ride along a push."""

from __future__ import annotations

import numpy as np
from test_robot import box_object, build, loaded

from realsim.planner.relations import moved
from realsim.robot import Robot
from realsim.robot.pushing import first_contact, strokes
from realsim.runtime.primitives import carried


def _square(centre: tuple[float, float], half: float, n: int = 30) -> np.ndarray:
    g = np.linspace(-half, half, n)
    return np.array([(x, y) for x in g for y in g]) + np.asarray(centre)


def test_strokes_start_with_the_asked_one_and_all_end_within_the_tolerance() -> None:
    d = np.array([0.0, 1.0])
    options = strokes(d, 0.05)
    assert np.allclose(options[0][0], d) and options[0][1] == 0.05
    assert len(options) > 5
    for u, length in options:  # a stroke followed exactly ends where the goal check accepts it
        assert moved((0.0, 0.0), tuple(u * length), d, 0.05).ok
        assert abs(float(np.linalg.norm(u)) - 1.0) < 1e-9


def test_a_neighbour_touched_at_the_start_is_shoved_only_when_the_push_runs_into_it() -> None:
    box = _square((0.0, 0.0), 0.05)
    neighbour = _square((0.1005, 0.0), 0.05)  # touching the box's +x face
    # into it: shoved; away from it or along the face they share: no new contact
    for d, shoved in ((np.array([1.0, 0.0]), True), (np.array([-1.0, 0.0]), False), (np.array([0.0, 1.0]), False)):
        hit = first_contact(box, neighbour, d, 0.05, 0.002, 0.01, 0.015)
        assert (hit is not None) == shoved, d
    hit = first_contact(box, _square((0.13, 0.0), 0.05), np.array([1.0, 0.0]), 0.08, 0.002, 0.01, 0.015)
    assert hit is not None and 0.02 <= hit[0] <= 0.04  # a 2.5 cm gap closes after 2-3 cm


def test_an_askew_stroke_clears_a_neighbour_the_straight_one_runs_into() -> None:
    box = _square((0.0, 0.0), 0.03)
    neighbour = _square((-0.05, 0.1), 0.03)  # 4 cm ahead of a push along +y, overlapping the box's path by 1 cm on its -x side
    d = np.array([0.0, 1.0])
    assert first_contact(box, neighbour, d, 0.05, 0.002, 0.01, 0.0) is not None
    clear = [(u, s) for u, s in strokes(d, 0.05) if first_contact(box, neighbour, u, s, 0.002, 0.01, 0.0) is None]
    full = [u for u, s in clear if abs(float(u[1]) * s - 0.05) < 1e-6]  # the whole 5 cm along: only askew away from it
    assert full and all(float(u[0]) > 0.0 for u in full)
    assert any(abs(float(u[0])) < 1e-9 and float(u[1]) * s < 0.04 for u, s in clear)  # or straight, stopping short of it


def test_what_the_command_put_in_or_on_an_object_may_ride_along_and_nothing_else() -> None:
    put = {"mug": "bowl", "cube": "mug", "can": "plate"}
    assert carried(put, "bowl") == {"mug", "cube"}
    assert carried(put, "mug") == {"cube"} and carried(put, "box") == set()
    assert carried({"a": "b", "b": "a"}, "a") == {"b"}  # a stale loop ends


def test_a_push_that_would_carry_an_object_stacked_on_it_is_refused_before_moving() -> None:
    base = box_object(1, "base_box", (0.05, 0.0), (0.12, 0.12, 0.06), mass=0.4)
    top = box_object(2, "top_box", (0.05, 0.0), (0.05, 0.05, 0.04), mass=0.1)
    top.position[2] += 0.06  # resting on the base box
    model, data = loaded(build([base, top]))
    robot = Robot(model, data)
    start = data.qpos.copy()
    res = robot.push("base_box", (1.0, 0.0), 0.05)
    assert not res.success and "top_box rests on base_box" in res.reason
    assert np.allclose(data.qpos, start)  # refused before anything moved


def test_what_an_object_stands_on_does_not_ride_along_when_it_is_pushed() -> None:
    base = box_object(1, "base_box", (0.05, 0.0), (0.16, 0.16, 0.04), mass=0.4)
    top = box_object(2, "top_box", (0.05, 0.0), (0.05, 0.05, 0.04), mass=0.1)
    top.position[2] += 0.04  # resting on the base box, the base's centre under the top's footprint
    model, data = loaded(build([base, top]))
    robot = Robot(model, data)
    assert robot._riding("base_box", robot.object_points("base_box")) == {"top_box"}
    assert robot._riding("top_box", robot.object_points("top_box")) == set()  # the base is under it, not on it


def test_a_push_rises_only_within_the_height_that_cannot_tip_the_object_or_catch_the_palm() -> None:
    tall = box_object(1, "tall_box", (0.05, 0.0), (0.06, 0.20, 0.20), mass=0.3)
    model, data = loaded(build([tall]))
    robot = Robot(model, data)
    pts = robot.object_points("tall_box")
    bottom, top = float(pts[:, 2].min()), float(pts[:, 2].max())
    pp = robot.params.push
    along = robot._contact_heights(pts, bottom + 0.035, np.array([0.0, 1.0, 0.0]))  # 20 cm long this way: every lift
    assert along == [bottom + 0.035 + lift for lift in (0.0, *pp.reach_lifts)]
    across = robot._contact_heights(pts, bottom + 0.035, np.array([1.0, 0.0, 0.0]))  # 6 cm: no higher than 3 cm
    assert across == [bottom + 0.035]
    low = box_object(2, "low_box", (0.05, 0.0), (0.2, 0.2, 0.09), mass=0.3)
    model, data = loaded(build([low]))
    robot = Robot(model, data)
    pts = robot.object_points("low_box")
    top = float(pts[:, 2].max())
    for zc in robot._contact_heights(pts, float(pts[:, 2].min()) + 0.035, np.array([0.0, 1.0, 0.0]))[1:]:
        assert not -pp.palm_clearance < top - (zc + pp.palm_height) < pp.palm_catch  # the palm never meets its top edge


def test_a_push_that_would_take_the_object_over_the_table_edge_is_refused_before_moving() -> None:
    near_edge = box_object(1, "edge_box", (0.1, 0.29), (0.05, 0.05, 0.06), mass=0.2)  # its far face 3.5 cm from the table's +y edge
    model, data = loaded(build([near_edge]))
    robot = Robot(model, data)
    start = data.qpos.copy()
    assert robot._stays_on("edge_box", robot.object_points("edge_box"), np.zeros(2))
    assert not robot._stays_on("edge_box", robot.object_points("edge_box"), np.array([0.0, 0.06]))  # its centre past the edge
    res = robot.push("edge_box", (0.0, 1.0), 0.10)  # even the shortest stroke within the tolerance (7.2 cm) ends over the edge
    assert not res.success and "over the edge of what it stands on" in res.reason
    assert np.allclose(data.qpos, start)
