"""Per-world contact and constraint capacity a scene needs, measured, for batched simulators.

MuJoCo Warp and MJX allocate a fixed number of contacts (``nconmax``) and constraint rows
(``njmax``) per world; their defaults overflow on realsim scenes. The scene is stepped from its
``home`` keyframe (objects released just above their supports, as when settling), then from
``initial`` through a scripted robot motion (the hand swept down towards the table with the
gripper closing, and back), and the peak ``ncon`` / ``nefc`` are kept. The recorded capacity
adds headroom for a grasp's contacts and rounds up; it is written to the MJCF ``<size>``
attributes (which MuJoCo reads into ``model.nconmax`` / ``model.njmax``) and to scene.json.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np


@dataclass(frozen=True)
class CapacityParams:
    """Headroom of the recorded capacity over the measured peaks."""

    landing_time: float = 0.4  # s stepped from keyframe home (objects landing)
    motion_time: float = 1.6  # s of the scripted robot motion from keyframe initial
    headroom: float = 1.5  # recorded = headroom * peak + a grasp's contacts
    grasp_contacts: int = 24  # contacts a closed hand on an object may add (two fingers, pads, multi-point)
    multiple: int = 16  # sizes rounded up to a multiple of this


def _rows_per_contact(model: mujoco.MjModel) -> int:
    condim = int(model.geom_condim.max()) if model.ngeom else 3
    if model.opt.cone == mujoco.mjtCone.mjCONE_ELLIPTIC:
        return condim
    return max(1, 2 * (condim - 1))


def _round_up(value: float, multiple: int) -> int:
    return int(math.ceil(value / multiple) * multiple)


def _key(model: mujoco.MjModel, name: str) -> int | None:
    for k in range(model.nkey):
        if model.key(k).name == name:
            return k
    return None


class LandingPeaks:
    """Peak contacts and constraint rows of the landing run observed in a simulation that takes
    the same states (settling: keyframe ``home`` after ``mj_forward``, then the same steps, awake),
    so :func:`measure_capacity` need not simulate them again."""

    def __init__(self, model: mujoco.MjModel, params: CapacityParams = CapacityParams()) -> None:
        self.steps = int(round(params.landing_time / model.opt.timestep))
        self.seen = 0  # states observed: the one after mj_forward, then one per step
        self.ncon = self.nefc = 0

    def observe(self, data: mujoco.MjData) -> None:
        """Take the current state into the peaks while it is one of the landing run's."""
        if self.seen <= self.steps:
            self.ncon, self.nefc = max(self.ncon, int(data.ncon)), max(self.nefc, int(data.nefc))
            self.seen += 1

    def peaks(self) -> tuple[int, int] | None:
        """(ncon, nefc) over the whole landing run, or None when fewer states were observed."""
        return (self.ncon, self.nefc) if self.seen > self.steps else None


def measure_capacity(model: mujoco.MjModel, initial: tuple[np.ndarray, np.ndarray] | None = None,
                     params: CapacityParams = CapacityParams(), landing: tuple[int, int] | None = None) -> dict[str, Any]:
    """Peak contacts and constraint rows while objects land and while the robot moves, and the
    capacity to record: ``{"nconmax", "njmax", "measured": {...}, "headroom", ...}``. ``initial`` is
    the settled state (qpos, ctrl); None reads keyframe ``initial``. ``landing`` is the landing
    run's peaks when already observed (:class:`LandingPeaks`); None simulates it. Run it with
    sleeping off (:func:`realsim.composition.settle.awake`): batched engines compute every contact."""
    peaks = {"ncon": 0, "nefc": 0}

    def run(key: str, seconds: float, scripted: bool) -> None:
        data = mujoco.MjData(model)
        k = _key(model, key)
        if key == "initial" and initial is not None:
            data.qpos[:], data.ctrl[:] = initial
        elif k is not None:
            mujoco.mj_resetDataKeyframe(model, data, k)
        else:
            return
        mujoco.mj_forward(model, data)
        peaks["ncon"], peaks["nefc"] = max(peaks["ncon"], int(data.ncon)), max(peaks["nefc"], int(data.nefc))
        home = data.ctrl.copy()
        script = _script(model, home)
        for step in range(int(round(seconds / model.opt.timestep))):
            if scripted:
                data.ctrl[:] = home
                _scripted(data, script, step * model.opt.timestep)
            mujoco.mj_step(model, data)
            peaks["ncon"] = max(peaks["ncon"], int(data.ncon))
            peaks["nefc"] = max(peaks["nefc"], int(data.nefc))

    if landing is None:
        run("home", params.landing_time, scripted=False)
    else:
        peaks["ncon"], peaks["nefc"] = landing
    run("initial", params.motion_time, scripted=True)
    rows = _rows_per_contact(model)
    return {
        "nconmax": _round_up(params.headroom * peaks["ncon"] + params.grasp_contacts, params.multiple),
        "njmax": _round_up(params.headroom * peaks["nefc"] + params.grasp_contacts * rows, params.multiple),
        "measured": {"ncon": peaks["ncon"], "nefc": peaks["nefc"], "while": "objects landing from keyframe home; scripted hand sweep from keyframe initial"},
        "headroom": params.headroom,
        "grasp_contacts": params.grasp_contacts,
    }


Script = tuple[list[tuple[int, float, float, float, float]], tuple[int, float] | None]
"""The scripted motion's actuators: (id, keyframe control, swing, lower, upper) of each swinging
joint and (id, keyframe control) of the gripper."""


def _script(model: mujoco.MjModel, home: np.ndarray) -> Script:
    """The actuators :func:`_scripted` drives, looked up once: joints 2 and 4 of the Panda (their
    swing in rad and control range) and the gripper."""
    swings = []
    for j, delta in ((2, 0.7), (4, 0.6)):
        aid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_ACTUATOR, f"panda/actuator{j}")
        if aid >= 0:
            lo, hi = model.actuator_ctrlrange[aid] if model.actuator_ctrllimited[aid] else (-np.inf, np.inf)
            swings.append((aid, float(home[aid]), delta, float(lo), float(hi)))
    grip = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_ACTUATOR, "panda/actuator8")
    return swings, ((grip, float(home[grip])) if grip >= 0 else None)


def _scripted(data: mujoco.MjData, script: Script, t: float) -> None:
    """Controls of the scripted motion at time ``t``: joints 2 and 4 swing the hand down towards
    the table and back (a smooth bump over the first second) while the gripper closes and
    reopens; every other actuator holds its keyframe control."""
    bump = math.sin(math.pi * min(max(t, 0.0), 1.0)) ** 2
    swings, grip = script
    for aid, home, delta, lo, hi in swings:
        data.ctrl[aid] = float(np.clip(home + delta * bump, lo, hi))
    if grip is not None:
        data.ctrl[grip[0]] = grip[1] * (1.0 - bump)
