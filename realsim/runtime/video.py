"""Record what the robot does as an MP4, in simulated time.

:class:`VideoRecorder` hooks into the :class:`Robot`'s stepping (``step_hook`` every N physics
steps), renders an offscreen frame (``MUJOCO_GL=egl`` headless) and streams it to ffmpeg (the
binary shipped by ``imageio-ffmpeg``). N is chosen so frames are ``fps`` per *simulated* second,
so a video shows the motion at real speed whatever the machine's speed.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from realsim.errors import InputError


def _camera(model: mujoco.MjModel, data: mujoco.MjData, object_names: list[str], base_pos: np.ndarray) -> mujoco.MjvCamera:
    """A free camera looking at the objects and the robot from the front-left, above the table."""
    cam = mujoco.MjvCamera()
    cam.type = mujoco.mjtCamera.mjCAMERA_FREE
    pts = [data.xpos[model.body(n).id] for n in object_names] or [base_pos + np.array([0.5, 0, 0])]
    objs = np.asarray(pts, float)
    centre = 0.7 * objs.mean(axis=0) + 0.3 * np.asarray(base_pos, float)
    spread = float(np.linalg.norm(np.vstack([objs, base_pos[None]])[:, :2] - centre[:2], axis=1).max())
    cam.lookat[:] = [centre[0], centre[1], float(objs[:, 2].mean()) + 0.05]
    cam.distance = max(1.2, 2.2 * spread + 0.4)
    cam.azimuth = 150.0
    cam.elevation = -30.0
    return cam


class VideoRecorder:
    """Streams offscreen frames of ``sim`` to ``path`` while primitives run.

    Use as a context manager around the run::

        with VideoRecorder(sim, "run.mp4") as rec:
            ...  # primitives step the physics; frames are captured every N steps
        rec.frames  # how many were written
    """

    def __init__(self, sim: Any, path: str | Path, fps: float = 30.0, width: int = 640, height: int = 480):
        self.sim = sim
        self.path = Path(path)
        if self.path.suffix.lower() != ".mp4":
            raise InputError(f"--video {self.path}: the video is written as MP4; name it *.mp4")
        model = sim.model
        width = min(width, int(model.vis.global_.offwidth))
        height = min(height, int(model.vis.global_.offheight))
        self.width, self.height = width - width % 16, height - height % 16
        dt = float(model.opt.timestep)
        self.every = max(1, int(round(1.0 / (fps * dt))))
        self.fps = 1.0 / (self.every * dt)
        self.frames = 0
        self._renderer: mujoco.Renderer | None = None
        self._writer: Any = None
        self._camera: mujoco.MjvCamera | None = None
        self._tmp = self.path.with_name(f".{self.path.name}.part.mp4")

    def __enter__(self) -> VideoRecorder:
        self.start()
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close(keep=True)  # a failed run's video is still worth watching

    def start(self) -> None:
        import imageio_ffmpeg

        self.path.parent.mkdir(parents=True, exist_ok=True)
        try:
            self._renderer = mujoco.Renderer(self.sim.model, self.height, self.width)
        except Exception as exc:  # no GL context (headless without EGL/OSMesa)
            raise InputError(f"cannot render offscreen for --video ({type(exc).__name__}: {exc}); "
                             "set MUJOCO_GL=egl (GPU/EGL) or MUJOCO_GL=osmesa") from None
        self._camera = _camera(self.sim.model, self.sim.data, self.sim.object_names(), self.sim.robot.base_pos)
        self._writer = imageio_ffmpeg.write_frames(
            str(self._tmp), (self.width, self.height), fps=self.fps, codec="libx264", pix_fmt_out="yuv420p",
            quality=7, macro_block_size=16, ffmpeg_log_level="error", output_params=["-movflags", "+faststart"],
        )
        self._writer.send(None)  # start ffmpeg
        self.attach(self.sim.robot)
        self.capture(self.sim.model, self.sim.data)  # the first frame: the initial state

    def attach(self, robot: Any) -> None:
        """Hook into ``robot``'s stepping (call again after the sim made a new robot)."""
        robot.step_hook = self.capture
        robot.hook_every = self.every

    def capture(self, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        assert self._renderer is not None and self._writer is not None
        self._renderer.update_scene(data, camera=self._camera)
        frame = self._renderer.render()
        self._writer.send(np.ascontiguousarray(frame))
        self.frames += 1

    def close(self, keep: bool = True) -> None:
        if self.sim.robot.step_hook == self.capture:
            self.sim.robot.step_hook = None
        if self._writer is not None:
            self._writer.close()
            self._writer = None
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None
        if keep and self._tmp.exists():
            os.replace(self._tmp, self.path)
        elif self._tmp.exists():
            self._tmp.unlink()


def probe(path: str | Path) -> tuple[int, float]:
    """(frames, seconds) of a video as ffmpeg decodes it; raises when it does not play."""
    import imageio_ffmpeg

    frames, seconds = imageio_ffmpeg.count_frames_and_secs(str(path))
    return int(frames), float(seconds)
