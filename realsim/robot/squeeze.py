"""How hard the gripper squeezes: the position-servo gripper's pad force at a width, and the
command that squeezes a part as hard as its statics need (no harder: a hard squeeze of a thin
wall in a soft-contact simulation drives the pads into it).

The gripper actuator is MuJoCo's affine servo on the fingers' tendon: force = gain * ctrl +
b0 + b1 * length (clamped to its force range); the tendon's length is the fingers' mean travel,
half the opening, and each finger gets the tendon force times its coefficient.
"""

from __future__ import annotations

import mujoco
import numpy as np


def _coef(model: mujoco.MjModel, act: int) -> float:
    """Share of the actuator's force on each finger (1 without a tendon)."""
    if model.actuator_trntype[act] != mujoco.mjtTrn.mjTRN_TENDON:
        return 1.0
    t = model.actuator_trnid[act][0]
    return float(np.abs(model.wrap_prm[model.tendon_adr[t]: model.tendon_adr[t] + model.tendon_num[t]]).max())


def _limit(model: mujoco.MjModel, act: int) -> float:
    return float(np.abs(model.actuator_forcerange[act]).max()) if model.actuator_forcelimited[act] else np.inf


def pad_force(model: mujoco.MjModel, act: int, width: float, ctrl: float | None = None) -> float:
    """Force (N) each pad presses on a part ``width`` across with command ``ctrl`` (default: the
    lowest, the hardest squeeze)."""
    c = float(model.actuator_ctrlrange[act][0]) if ctrl is None else ctrl
    force = -(model.actuator_gainprm[act][0] * c + model.actuator_biasprm[act][0] + model.actuator_biasprm[act][1] * width / 2)
    return max(0.0, min(float(force), _limit(model, act))) * _coef(model, act)


def servo_pad(model: mujoco.MjModel, act: int, width: float) -> float:
    """Pad force (N) of the servo aiming at closed (tendon length 0) on a part ``width`` across:
    what a plain position gripper squeezes, a firm hold of a light part without driving into it."""
    return min(abs(float(model.actuator_biasprm[act][1])) * width / 2, _limit(model, act)) * _coef(model, act)


def close_ctrl(model: mujoco.MjModel, act: int, width: float, pad: float) -> float:
    """The command that presses each pad on a part ``width`` across with ``pad`` N (within the
    actuator's control range)."""
    gain, b0, b1 = model.actuator_gainprm[act][0], model.actuator_biasprm[act][0], model.actuator_biasprm[act][1]
    c = (-pad / _coef(model, act) - b0 - b1 * width / 2) / gain if gain else 0.0
    lo, hi = model.actuator_ctrlrange[act]
    return float(np.clip(c, lo, hi))


def needed_pad(need: float, can: float, at: float, mass: float, friction: float, safety: float) -> float:
    """Pad force (N) that holds a pinch: its torque ``need`` against ``can`` held at ``at`` N a pad
    (capacity grows with the squeeze), and the weight carried by two pads' friction, times ``safety``."""
    torque = need / can * at if can > 0 else at
    weight = 9.81 * mass / (2.0 * max(friction, 1e-3))
    return safety * max(torque, weight)
