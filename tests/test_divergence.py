"""Simulation loops stop with a message when the physics diverges (real MuJoCo, no mocks)."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from realsim.composition.settle import SettleParams, simulate_to_rest
from realsim.errors import SimulationDiverged
from realsim.physics.divergence import check_state
from realsim.scene_format import free_joint_bodies


def falling_box() -> tuple[mujoco.MjModel, mujoco.MjData]:
    spec = mujoco.MjSpec()
    floor = spec.worldbody.add_geom()
    floor.type, floor.size = mujoco.mjtGeom.mjGEOM_PLANE, [1, 1, 0.1]
    body = spec.worldbody.add_body(pos=[0, 0, 0.2])
    body.add_freejoint()
    box = body.add_geom()
    box.type, box.size = mujoco.mjtGeom.mjGEOM_BOX, [0.05, 0.05, 0.05]
    model = spec.compile()
    return model, mujoco.MjData(model)


def test_a_calm_simulation_passes() -> None:
    model, data = falling_box()
    assert simulate_to_rest(model, data, free_joint_bodies(model), SettleParams()) < SettleParams().max_time
    check_state(model, data, "test")


@pytest.mark.parametrize("field", ["qpos", "qvel"])
def test_non_finite_state_stops_settling(field: str, tmp_path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)  # MuJoCo logs its bad-state warning to MUJOCO_LOG.TXT in the working directory
    model, data = falling_box()
    getattr(data, field)[2] = np.nan
    with pytest.raises(SimulationDiverged, match="settling: the simulation diverged"):
        simulate_to_rest(model, data, free_joint_bodies(model), SettleParams())


def test_runaway_speed_is_divergence() -> None:
    model, data = falling_box()
    data.qvel[0] = 1e4  # finite, but nothing on a table moves at 10 km/s
    mujoco.mj_forward(model, data)
    with pytest.raises(SimulationDiverged, match="m/s"):
        check_state(model, data, "test")
