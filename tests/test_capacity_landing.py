"""The capacity's landing run is read off settling (the same states) instead of simulated again:
the recorded capacity is the one a separate landing run gives, and a settle shorter than the
landing run leaves it to measure_capacity."""

from __future__ import annotations

import numpy as np
from test_robot import box_object, table_scene

from realsim.composition.compose import compose_scene
from realsim.composition.robot_placement import add_robot
from realsim.composition.settle import SettleParams, _settle, awake
from realsim.physics.capacity import measure_capacity


def _model():
    objects = [box_object(1, "obj1_box", (0.1, 0.05), [0.05, 0.05, 0.1]), box_object(2, "obj2_box", (-0.1, 0.0), [0.06, 0.04, 0.08])]
    scene = compose_scene(table_scene(objects))
    for obj in scene.objects:  # released a little above the table: contacts appear while landing
        body = scene.spec.body(obj.name)
        body.pos = [body.pos[0], body.pos[1], body.pos[2] + 0.01]
    add_robot(scene, (-0.75, 0.0, 0.0))
    return scene.spec.compile()


def test_landing_peaks_from_settling_equal_a_separate_landing_run():
    model = _model()
    with awake(model):
        settled = _settle(model, SettleParams())
        assert settled["landing"] is not None and settled["landing"][0] > 0
        state = (settled["key_qpos"], settled["key_ctrl"])
        assert measure_capacity(model, state, landing=settled["landing"]) == measure_capacity(model, state)


def test_short_settle_leaves_the_landing_run_to_measure_capacity():
    model = _model()
    short = SettleParams(min_time=0.1, max_time=0.2)
    with awake(model):
        settled = _settle(model, short)
    assert settled["landing"] is None  # 0.2 s of settling do not cover the 0.4 s landing run
    assert np.isfinite(settled["report"]["max_displacement"])
