"""Steps per second of a converted scene over many worlds: MuJoCo Warp when installed, else C.

``realsim bench-sim SCENE --worlds N`` steps N copies of the scene from keyframe ``initial``
with the robot holding its posture. With the optional ``mujoco-warp`` package the worlds run as
one batch on Warp's device (a GPU when there is one; the first step compiles the kernels, which
takes minutes on a CPU and is excluded from the timing), sized by the scene's recorded
``nconmax`` / ``njmax`` and checked for overflow. Without it, the C engine steps the worlds one
after another on one core.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from realsim.errors import InputError


@dataclass(frozen=True)
class Throughput:
    """What one benchmark measured."""

    engine: str  # "mujoco_warp (<device>)" | "mujoco (C, one core)"
    worlds: int
    steps: int  # per world
    seconds: float  # wall time of the timed steps
    nconmax: int | None  # per-world capacity used (Warp), from the scene
    njmax: int | None
    peak_ncon: int  # largest contacts in one world seen
    peak_nefc: int  # largest constraint rows in one world seen
    overflow: bool  # a world needed more than the capacity (Warp)

    @property
    def steps_per_second(self) -> float:
        return self.worlds * self.steps / max(self.seconds, 1e-9)

    def x_real_time(self, timestep: float) -> float:
        return self.steps_per_second * timestep


def warp_available() -> bool:
    """Whether the optional ``mujoco-warp`` package imports."""
    try:
        import mujoco_warp  # noqa: F401
        import warp  # noqa: F401
    except Exception:
        return False
    return True


def load_initial(xml: Path) -> tuple[mujoco.MjModel, mujoco.MjData]:
    """The model of a scene and a data at keyframe ``initial`` (forward computed)."""
    try:
        model = mujoco.MjModel.from_xml_path(str(xml))
    except ValueError as exc:
        raise InputError(f"{xml}: MuJoCo cannot load it ({' '.join(str(exc).split())[:200]})") from None
    data = mujoco.MjData(model)
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, "initial")
    if key >= 0:
        mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_forward(model, data)
    return model, data


def recorded_capacity(model: mujoco.MjModel) -> tuple[int | None, int | None]:
    """The scene's ``<size nconmax njmax>`` (None when not recorded)."""
    return (int(model.nconmax) if model.nconmax > 0 else None, int(model.njmax) if model.njmax > 0 else None)


def bench_c(model: mujoco.MjModel, data: mujoco.MjData, worlds: int, steps: int) -> Throughput:
    """``worlds`` copies stepped ``steps`` times each, one after another, on one core."""
    copies = [mujoco.MjData(model) for _ in range(worlds)]
    for d in copies:
        d.qpos[:], d.qvel[:], d.ctrl[:] = data.qpos, data.qvel, data.ctrl
        mujoco.mj_forward(model, d)
    ncon = nefc = 0
    started = time.perf_counter()
    for _ in range(steps):
        for d in copies:
            mujoco.mj_step(model, d)
    seconds = time.perf_counter() - started
    for d in copies:
        ncon, nefc = max(ncon, d.ncon), max(nefc, d.nefc)
    nconmax, njmax = recorded_capacity(model)
    return Throughput("mujoco (C, one core)", worlds, steps, seconds, nconmax, njmax, ncon, nefc, False)


def bench_warp(model: mujoco.MjModel, data: mujoco.MjData, worlds: int, steps: int) -> Throughput:
    """``worlds`` worlds stepped as one MuJoCo Warp batch, sized by the scene's recorded capacity."""
    import mujoco_warp as mjw
    import warp as wp

    nconmax, njmax = recorded_capacity(model)
    mw = mjw.put_model(model)
    dw = mjw.put_data(model, data, nworld=worlds, nconmax=nconmax, njmax=njmax)
    mjw.step(mw, dw)  # compiles the kernels on first use
    wp.synchronize()
    started = time.perf_counter()
    for _ in range(steps):
        mjw.step(mw, dw)
    wp.synchronize()
    seconds = time.perf_counter() - started
    nefc = np.asarray(dw.nefc.numpy()).reshape(-1)
    nacon = int(np.asarray(dw.nacon.numpy()).reshape(-1)[0])
    overflow = nacon > int(dw.naconmax) or int(nefc.max(initial=0)) > int(dw.njmax)
    return Throughput(f"mujoco_warp ({wp.get_device()})", worlds, steps, seconds, nconmax, njmax, int(np.ceil(nacon / max(worlds, 1))), int(nefc.max(initial=0)), overflow)


def bench_scene(folder: Path, worlds: int = 1, steps: int = 200, engine: str = "auto") -> Throughput:
    """Benchmark the scene of ``folder`` (``engine``: "auto", "warp" or "c")."""
    from realsim.scene_format import scene_xml

    if worlds < 1 or steps < 1:
        raise InputError("--worlds and --steps must be at least 1")
    model, data = load_initial(scene_xml(Path(folder)))
    use_warp = engine == "warp" or (engine == "auto" and warp_available())
    if engine == "warp" and not warp_available():
        raise InputError("--engine warp: mujoco-warp is not installed; pip install 'realsim[gpu]' (or use --engine c)")
    return bench_warp(model, data, worlds, steps) if use_warp else bench_c(model, data, worlds, steps)
