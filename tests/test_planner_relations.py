"""Goal checks that are true: relations judged on settled MuJoCo scenes built for each case.

Objects lie inside, on top of, beside, leaning on and between their targets; every goal is
evaluated on the live surfaces and contacts (:class:`SceneGeometry`) after the physics settled.
"""

from __future__ import annotations

import mujoco
import pytest

from realsim.planner.goals import Between, Inside, NextTo, On, SideOf
from realsim.robot.world import SceneGeometry

TABLE = '<geom name="table" type="box" size="0.6 0.6 0.02" pos="0 0 -0.02"/>'
BIN = """
<body name="bin" pos="{x} {y} 0"><freejoint/>
  <geom type="box" size="0.07 0.07 0.004" pos="0 0 0.004" mass="0.2"/>
  <geom type="box" size="0.004 0.07 0.04" pos="0.066 0 0.044" mass="0.05"/>
  <geom type="box" size="0.004 0.07 0.04" pos="-0.066 0 0.044" mass="0.05"/>
  <geom type="box" size="0.07 0.004 0.04" pos="0 0.066 0.044" mass="0.05"/>
  <geom type="box" size="0.07 0.004 0.04" pos="0 -0.066 0.044" mass="0.05"/>
</body>"""


def box(name: str, pos: tuple[float, float, float], half: tuple[float, float, float], euler: str = "0 0 0") -> str:
    return (f'<body name="{name}" pos="{pos[0]} {pos[1]} {pos[2]}" euler="{euler}"><freejoint/>'
            f'<geom type="box" size="{half[0]} {half[1]} {half[2]}" mass="0.1"/></body>')


class World:
    """A settled scene as goals see it (surfaces and contacts; robot facing +x)."""

    def __init__(self, bodies: str, seconds: float = 1.0):
        xml = f'<mujoco><option timestep="0.002"/><worldbody>{TABLE}{bodies}</worldbody></mujoco>'
        self.model = mujoco.MjModel.from_xml_string(xml)
        self.data = mujoco.MjData(self.model)
        while self.data.time < seconds:
            mujoco.mj_step(self.model, self.data)
        mujoco.mj_forward(self.model, self.data)
        self.geometry = SceneGeometry(self.model, self.data)

    def robot_yaw(self) -> float:
        return 0.0

    def z(self, name: str) -> float:
        return float(self.data.xpos[self.model.body(name).id][2])


def ok(goal, world: World) -> bool:
    return goal.evaluate(world).ok


def test_block_inside_the_bin() -> None:
    w = World(BIN.format(x=0.0, y=0.0) + box("block", (0.0, 0.0, 0.05), (0.02, 0.02, 0.02)))
    assert ok(Inside("block", "bin"), w)
    assert not ok(NextTo("block", "bin"), w)
    res = Inside("block", "bin").evaluate(w)
    assert "touching bin" in res.measured and "world" not in res.measured


def test_stick_lying_across_the_table_beside_the_bin_is_not_inside() -> None:
    """The hammer case: a long object on the table whose box centre is near the container."""
    w = World(BIN.format(x=0.0, y=0.0) + box("stick", (0.0, 0.12, 0.015), (0.15, 0.015, 0.015)))
    res = Inside("stick", "bin").evaluate(w)
    assert not res.ok and "touching world" in res.measured
    assert ok(NextTo("stick", "bin"), w)


def test_stick_leaning_on_the_bin_is_neither_in_nor_on() -> None:
    w = World(BIN.format(x=0.0, y=0.0) + box("stick", (0.12, 0.0, 0.06), (0.1, 0.012, 0.012), euler="0 -25 0"), seconds=1.5)
    assert not ok(Inside("stick", "bin"), w)
    assert not ok(On("stick", "bin"), w)


def test_block_on_top_of_a_box_and_beside_it() -> None:
    w = World(box("base", (0.0, 0.0, 0.04), (0.05, 0.05, 0.04)) + box("top", (0.0, 0.0, 0.1), (0.02, 0.02, 0.02))
              + box("side", (0.0, 0.1, 0.02), (0.02, 0.02, 0.02)))
    assert ok(On("top", "base"), w)
    assert not ok(Inside("top", "base"), w)  # a closed box has no cavity
    assert not ok(NextTo("top", "base"), w)  # on it, not beside it
    assert ok(NextTo("side", "base"), w) and not ok(On("side", "base"), w)
    assert ok(SideOf("side", "base", "left"), w)  # +y is the robot's left when it faces +x
    assert not ok(SideOf("side", "base", "right"), w) and not ok(SideOf("side", "base", "behind"), w)


def test_far_away_is_not_next_to() -> None:
    w = World(box("a", (0.0, 0.0, 0.02), (0.02, 0.02, 0.02)) + box("b", (0.0, 0.3, 0.02), (0.02, 0.02, 0.02)))
    assert not ok(NextTo("a", "b"), w)
    assert not ok(SideOf("b", "a", "left"), w)  # 26 cm away: further than "left of" allows


@pytest.mark.parametrize(("x", "expected"), [(0.0, True), (0.3, False)])
def test_between_two_boxes(x: float, expected: bool) -> None:
    w = World(box("a", (0.0, -0.15, 0.03), (0.03, 0.03, 0.03)) + box("b", (0.0, 0.15, 0.03), (0.03, 0.03, 0.03))
              + box("m", (x, 0.0, 0.02), (0.02, 0.02, 0.02)))
    assert ok(Between("m", "a", "b"), w) is expected


def test_in_front_and_behind_follow_the_robot() -> None:
    w = World(box("ref", (0.0, 0.0, 0.03), (0.03, 0.03, 0.03)) + box("near", (-0.1, 0.0, 0.02), (0.02, 0.02, 0.02)))
    assert ok(SideOf("near", "ref", "front"), w)  # nearer the robot (at -x) is in front
    assert not ok(SideOf("near", "ref", "behind"), w)
