"""Stop a simulation loop the moment its state stops being physical."""

from __future__ import annotations

import mujoco
import numpy as np

from realsim.errors import SimulationDiverged

BAD_STATE_WARNINGS = (mujoco.mjtWarning.mjWARN_BADQPOS, mujoco.mjtWarning.mjWARN_BADQVEL, mujoco.mjtWarning.mjWARN_BADQACC)
MAX_SPEED = 100.0  # m/s or rad/s: nothing in a tabletop scene moves this fast


def check_state(model: mujoco.MjModel, data: mujoco.MjData, where: str) -> None:
    """Raise :class:`SimulationDiverged` when the state is non-finite, MuJoCo reset it for a bad
    position, velocity or acceleration, or a body moves faster than :data:`MAX_SPEED`."""
    bad_qacc = sum(int(data.warning[w].number) for w in BAD_STATE_WARNINGS)
    finite = bool(np.isfinite(data.qpos).all() and np.isfinite(data.qvel).all())
    speed = float(np.abs(data.qvel).max(initial=0.0)) if finite else float("inf")
    if not finite or bad_qacc or speed > MAX_SPEED:
        reason = "non-finite state" if not finite else ("MuJoCo reset a non-finite or huge state" if bad_qacc else f"a body at {speed:.0f} m/s")
        raise SimulationDiverged(f"{where}: the simulation diverged at t = {data.time:.3f} s ({reason}); "
                                 "the scene is not physically consistent (check the capture's units and the --set values)")
