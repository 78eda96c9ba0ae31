"""When settling calls a body at rest: slow now, or staying in place over a window (rocking in place
is rest, moving on is not), on generated motions and small simulated scenes."""

from __future__ import annotations

from collections import deque

import mujoco
import numpy as np

from realsim.composition.settle import SettleParams, _stayed, simulate_to_rest
from realsim.scene_format import free_joint_bodies


def _window(poses: list[np.ndarray]) -> deque[np.ndarray]:
    window: deque[np.ndarray] = deque(maxlen=len(poses))
    window.extend(poses)
    return window


def _pose(x: float, angle: float) -> np.ndarray:
    return np.array([[x, 0.0, 0.1, np.cos(angle / 2), np.sin(angle / 2), 0.0, 0.0]])


def test_rocking_in_place_is_rest_and_moving_on_is_not() -> None:
    t = np.linspace(0.0, 0.25, 6)
    rocking = [_pose(1e-5 * np.sin(40 * s), 2e-4 * np.sin(40 * s)) for s in t]  # 0.2 mrad chatter, no net motion
    assert _stayed(_window(rocking), 2e-3 * 0.25)
    creeping = [_pose(3e-3 * s, 0.0) for s in t]  # 3 mm/s steady
    assert not _stayed(_window(creeping), 2e-3 * 0.25)
    turning = [_pose(0.0, 4e-3 * s) for s in t]  # 4 mrad/s steady
    assert not _stayed(_window(turning), 2e-3 * 0.25)
    assert not _stayed(deque(rocking[:3], maxlen=6), 2e-3 * 0.25)  # a window not yet full says nothing


def _model(tilt_deg: float, friction: float) -> mujoco.MjModel:
    spec = mujoco.MjSpec()
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[1, 1, 0.1], friction=[friction, 0.005, 0.0001],
                            quat=[np.cos(np.radians(tilt_deg) / 2), 0.0, np.sin(np.radians(tilt_deg) / 2), 0.0])
    box = spec.worldbody.add_body(name="box", pos=[0, 0, 0.021])
    box.add_freejoint()
    box.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.02, 0.02, 0.02], friction=[friction, 0.005, 0.0001])
    return spec.compile()


def _settle_time(model: mujoco.MjModel) -> float:
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return simulate_to_rest(model, data, free_joint_bodies(model), SettleParams(max_time=2.0))


def test_a_box_on_a_level_plane_rests_and_one_sliding_down_a_slope_does_not() -> None:
    assert _settle_time(_model(0.0, 1.0)) < 1.0
    assert _settle_time(_model(20.0, 0.05)) >= 2.0  # sliding the whole time: never called at rest
