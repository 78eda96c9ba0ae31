"""Settle the composed scene and write the rest state into keyframe ``initial``.

Objects are released at their captured poses and simulated until they stop (or a time limit);
that state becomes the keyframe. A check then resets to the keyframe and simulates again,
measuring how far each object still moves: the figure the conversion report shows (a forked
helper runs it while the contact capacity is measured). Both are cached under the compiled model
(its MJB bytes), the parameters and the code digest, so a rerun reuses them.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from realsim.cache import DiskCache, model_digest, output_key
from realsim.forkmap import Ahead
from realsim.physics.capacity import CapacityParams, LandingPeaks, measure_capacity
from realsim.physics.divergence import check_state
from realsim.scene import Scene
from realsim.scene_format import HOME_KEYFRAME, KEYFRAME, free_joint_bodies


@dataclass(frozen=True)
class SettleParams:
    """Parameters of settling and of the rest check."""

    min_time: float = 0.5  # simulated seconds before testing for rest
    max_time: float = 8.0  # simulated seconds: a scene whose pieces fall far (a chair's parts off its seat) needs them to land
    rest_speed: float = 2e-3  # m/s (and rad/s) below which every object is at rest
    rest_window: float = 0.25  # s: an object that stayed within rest_speed * rest_window of its pose this long is at rest too
    check_time: float = 2.0  # simulated seconds of the rest check
    max_drift: float = 0.005  # m an object may move during the check
    max_capture_move: float = 0.02  # m a captured object may move while settling before it is reported as not where the capture shows it
    capacity: CapacityParams = field(default_factory=CapacityParams)  # nconmax / njmax recorded for batched engines


def _max_speed(data: mujoco.MjData, free: list[tuple[str, int, int]]) -> float:
    if not free:
        return 0.0
    return float(max(np.abs(data.qvel[d : d + 6]).max() for _, _, d in free))


def _poses(data: mujoco.MjData, free: list[tuple[str, int, int]]) -> np.ndarray:
    """(B, 7) position and unit quaternion of every free body."""
    return np.array([data.qpos[q : q + 7] for _, q, _ in free]).reshape(len(free), 7)


def _stayed(poses: deque[np.ndarray], reach: float) -> bool:
    """Whether every body stayed within ``reach`` (m, and rad of rotation) of its latest pose at every
    earlier pose in ``poses`` (a full window): still, or rocking in place (contact chatter), not moving on."""
    if len(poses) < (poses.maxlen or 0):
        return False
    now = poses[-1]
    for then in list(poses)[:-1]:
        if np.any(np.linalg.norm(now[:, :3] - then[:, :3], axis=1) > reach):
            return False
        cos = np.clip(np.abs(np.einsum("bk,bk->b", now[:, 3:], then[:, 3:])) / (np.linalg.norm(now[:, 3:], axis=1) * np.linalg.norm(then[:, 3:], axis=1)), 0.0, 1.0)
        if np.any(2.0 * np.arccos(cos) > reach):
            return False
    return True


def simulate_to_rest(model: mujoco.MjModel, data: mujoco.MjData, free: list[tuple[str, int, int]], params: SettleParams,
                     watch: Callable[[mujoco.MjData], None] | None = None) -> float:
    """Step until every free body is at rest (after ``min_time``): slower than ``rest_speed``, or
    within ``rest_speed * rest_window`` of its pose over the last ``rest_window`` (a body rocking in
    place never passes the speed test); return the simulated time. ``watch`` sees the state after
    every step."""
    start = data.time
    check_every = max(1, int(0.05 / model.opt.timestep))
    poses: deque[np.ndarray] = deque(maxlen=max(1, int(round(params.rest_window / (check_every * model.opt.timestep)))) + 1)
    step = 0
    while data.time - start < params.max_time:
        mujoco.mj_step(model, data)
        step += 1
        if watch is not None:
            watch(data)
        if step % check_every:
            continue
        check_state(model, data, "settling")
        poses.append(_poses(data, free))
        if data.time - start >= params.min_time and (_max_speed(data, free) < params.rest_speed
                                                     or _stayed(poses, params.rest_speed * params.rest_window)):
            break
    return float(data.time - start)


def rest_check(model: mujoco.MjModel, duration: float, key: str = KEYFRAME,
               state: tuple[np.ndarray, np.ndarray] | None = None) -> dict[str, Any]:
    """Reset to ``key`` (or to ``state`` = (qpos, ctrl)), simulate ``duration`` s and report each
    free body's displacement."""
    with awake(model):
        return _rest_check(model, duration, key, state)


@contextmanager
def awake(model: mujoco.MjModel) -> Iterator[mujoco.MjModel]:
    """``model`` with MuJoCo's sleeping off for the block: settling and rest checks measure every
    body's motion (a sleeping body would read as perfectly still)."""
    flags = model.opt.enableflags
    model.opt.enableflags = flags & ~int(mujoco.mjtEnableBit.mjENBL_SLEEP)
    try:
        yield model
    finally:
        model.opt.enableflags = flags


def _rest_check(model: mujoco.MjModel, duration: float, key: str, state: tuple[np.ndarray, np.ndarray] | None) -> dict[str, Any]:
    data = mujoco.MjData(model)
    if state is None:
        mujoco.mj_resetDataKeyframe(model, data, model.key(key).id)
    else:
        data.qpos[:] = state[0]
        data.ctrl[:] = state[1]
    mujoco.mj_forward(model, data)
    free = free_joint_bodies(model)
    start = {name: data.qpos[q : q + 3].copy() for name, q, _ in free}
    lowest = {name: data.qpos[q + 2] for name, q, _ in free}
    steps = int(round(duration / model.opt.timestep))
    check_every = max(1, int(0.05 / model.opt.timestep))
    for step in range(steps):
        mujoco.mj_step(model, data)
        if step % check_every == 0:
            check_state(model, data, "rest check")
        for name, q, _ in free:
            lowest[name] = min(lowest[name], data.qpos[q + 2])
    moved = {name: float(np.linalg.norm(data.qpos[q : q + 3] - start[name])) for name, q, _ in free}
    sunk = {name: float(start[name][2] - lowest[name]) for name, _, _ in free}
    return {"duration": duration, "displacement": moved, "max_displacement": max(moved.values(), default=0.0), "max_sink": max(sunk.values(), default=0.0)}


def settle_scene(scene: Scene, params: SettleParams = SettleParams(), model: mujoco.MjModel | None = None) -> Scene:
    """Simulate the composed spec to rest, store keyframe ``initial``, and run the rest check.
    ``model`` is ``scene.spec`` compiled as it is now, when the caller has it (else compiled here)."""
    spec = scene.spec
    model = spec.compile() if model is None else model
    cache = DiskCache()
    cache_id = output_key("settle", data=model_digest(model), params=params)
    settled = cache.get(cache_id)  # this very model settled before: reuse its rest state and check
    if settled is None:
        with awake(model):
            settled = _settle(model, params)
        settled.pop("landing")  # measure_capacity's input, already in the capacity
        cache.put(cache_id, settled)
    spec.nconmax, spec.njmax = settled["capacity"]["nconmax"], settled["capacity"]["njmax"]  # read by MJX / MuJoCo Warp users
    qpos, key_qpos, key_ctrl, report = settled["qpos"], settled["key_qpos"], settled["key_ctrl"], dict(settled["report"])
    free = free_joint_bodies(model)
    for key in list(spec.keys):
        if key.name == KEYFRAME:
            spec.delete(key)
    key = spec.add_key(name=KEYFRAME, qpos=key_qpos.tolist(), qvel=np.zeros(model.nv).tolist())
    if model.nu:
        key.ctrl = key_ctrl.tolist()
    report["moved_during_settling"] = {}
    report["capacity"] = settled["capacity"]  # per-world contacts and constraint rows (scene.json settle.capacity)
    for obj in scene.objects:
        for name, q, _ in free:
            if name == obj.name:
                settled = qpos[q : q + 3]
                report["moved_during_settling"][name] = float(np.linalg.norm(settled - obj.position))
                obj.position = settled.copy()
                obj.quat = qpos[q + 3 : q + 7].copy()
    moved = {n: d for n, d in report["moved_during_settling"].items() if d > params.max_capture_move}
    if moved and scene.labels is not None:  # a captured object (not a generated one) stood still where it was seen
        scene.warn(f"{len(moved)} object(s) moved more than {params.max_capture_move * 1000:.0f} mm while settling, so they are not "
                   f"where the capture shows them (their completed shapes or supports do not hold them as seen): "
                   + ", ".join(f"{n} {d * 1000:.0f} mm" for n, d in sorted(moved.items())))
    unstable = [n for n, d in report["displacement"].items() if d > params.max_drift]
    if unstable:
        scene.warn(f"{len(unstable)} object(s) still move more than {params.max_drift * 1000:.0f} mm after settling: {', '.join(unstable)}")
    scene.keyframe_qpos = qpos
    scene.settle_report = report
    return scene


def _settle(model: mujoco.MjModel, params: SettleParams) -> dict[str, Any]:
    """Simulate from keyframe ``home`` to rest and check the rest state: the keyframe's qpos
    (canonical quaternion signs) and ctrl, the rest-check report, the contact capacity and the
    landing run's peaks read off the settling (None when it was shorter)."""
    data = mujoco.MjData(model)
    home = _home_key(model)
    if home is not None:
        mujoco.mj_resetDataKeyframe(model, data, home)
    mujoco.mj_forward(model, data)
    free = free_joint_bodies(model)
    landing = LandingPeaks(model, params.capacity) if home is not None else None  # capacity's landing run: these very states
    if landing is not None:
        landing.observe(data)
    settle_time = simulate_to_rest(model, data, free, params, watch=None if landing is None else landing.observe)
    qpos = data.qpos.copy()
    for _, q, _ in free:  # canonical quaternion sign for byte-stable output
        quat = qpos[q + 3 : q + 7]
        qpos[q + 3 : q + 7] = quat / np.linalg.norm(quat) * (1 if quat[0] >= 0 else -1)
    key_qpos, key_ctrl = np.round(qpos, 6), np.round(data.ctrl, 6)
    # The same state the keyframe holds, checked on the model already compiled (the written
    # scene.xml is compiled again by the writer), by a forked helper while the capacity is measured here.
    with Ahead(lambda _: rest_check(model, params.check_time, state=(key_qpos, key_ctrl)), 1) as check:
        capacity = measure_capacity(model, (key_qpos, key_ctrl), params.capacity, landing=None if landing is None else landing.peaks())
        report = check.results()[0]
    report["settle_time"] = settle_time
    return {"qpos": qpos, "key_qpos": key_qpos, "key_ctrl": key_ctrl, "report": report, "capacity": capacity,
            "landing": None if landing is None else landing.peaks()}


def _home_key(model: mujoco.MjModel) -> int | None:
    """Id of a ``home`` keyframe (the robot's posture) if the model has one."""
    for k in range(model.nkey):
        if model.key(k).name == HOME_KEYFRAME:
            return k
    return None
