"""``realsim view``: a live browser viewer of a converted scene (viser).

Physics runs in a background thread in real time (``mj_step`` paced by the wall clock); a
second thread streams the pose of every moving body to the browser at ``rate_hz`` (60 by
default). A text box sends natural-language commands to :func:`realsim.viewer.commands.on_command`.
An optional status endpoint (``status_port``) serves ``GET /status`` as JSON: simulated time,
pose frames sent, connected clients and every moving body's pose; tests and scripts use it.
"""

from __future__ import annotations

import json
import threading
import time
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from realsim.errors import InputError, SimulationDiverged
from realsim.physics.divergence import check_state
from realsim.scene_format import KEYFRAME, scene_xml
from realsim.viewer.commands import on_command
from realsim.viewer.frames import configure_up, to_viser
from realsim.viewer.geoms import add_support_outlines, add_visual_geoms
from realsim.viewer.splat import find_splat, read_splat_ply


@dataclass
class LiveSim:
    """The simulation the viewer runs, handed to ``realsim.runtime.run_command(sim, text)``.

    While a command runs (``busy``) the viewer's physics thread does not step: the command owns
    ``data`` and steps it itself; the browser keeps showing its poses. Hold ``lock`` only for
    short sections (the pose stream takes it to copy poses).
    """

    model: mujoco.MjModel
    data: mujoco.MjData
    folder: Path
    scene_json: dict[str, Any] = field(default_factory=dict)
    lock: threading.RLock = field(default_factory=threading.RLock)
    paused: bool = False
    busy: bool = False

    def reset(self) -> None:
        """Back to keyframe ``initial`` (or the model's default state)."""
        with self.lock:
            key = next((k for k in range(self.model.nkey) if self.model.key(k).name == KEYFRAME), None)
            if key is None:
                mujoco.mj_resetData(self.model, self.data)
            else:
                mujoco.mj_resetDataKeyframe(self.model, self.data, key)
            mujoco.mj_forward(self.model, self.data)


def load_live_sim(folder: Path) -> tuple[LiveSim, mujoco.MjSpec]:
    """Compile an output folder's scene.xml into a :class:`LiveSim` at keyframe ``initial``."""
    xml = scene_xml(folder)
    try:
        spec = mujoco.MjSpec.from_file(str(xml))
        model = spec.compile()
    except Exception as exc:
        raise InputError(f"{xml}: MuJoCo cannot load it ({str(exc).splitlines()[0]})") from None
    record = {}
    if (xml.parent / "scene.json").is_file():
        record = json.loads((xml.parent / "scene.json").read_text())
    sim = LiveSim(model=model, data=mujoco.MjData(model), folder=xml.parent, scene_json=record)
    sim.reset()
    return sim, spec


class Viewer:
    """A viser server showing a :class:`LiveSim`, with physics and pose-stream threads."""

    def __init__(self, folder: Path, host: str = "127.0.0.1", port: int = 8080, *, splat: Path | None = None,
                 paused: bool = False, rate_hz: float = 60.0, status_port: int | None = None):
        import viser

        self.sim, self.spec = load_live_sim(folder)
        self.sim.paused = paused
        self.rate_hz = rate_hz
        self.frames = 0
        self.last_reply = ""
        self._stop = threading.Event()
        self.server = viser.ViserServer(host=host, port=port, verbose=False)
        self.host, self.port = host, self.server.get_port()
        configure_up(self.server)
        model, data = self.sim.model, self.sim.data
        with self.sim.lock:
            self.nodes = add_visual_geoms(self.server, model, data, self.spec, self.sim.folder)
        add_support_outlines(self.server, self.sim.scene_json.get("planes", []))
        self.splat = splat if splat is not None else find_splat(self.sim.scene_json)
        self.splat_count = self._add_splat(self.splat) if self.splat is not None else 0
        self._set_initial_camera()
        self._build_gui()
        self._threads = [threading.Thread(target=self._physics_loop, name="realsim-physics", daemon=True),
                         threading.Thread(target=self._stream_loop, name="realsim-poses", daemon=True)]
        self._status_server = _start_status_server(self, host, status_port) if status_port is not None else None

    @property
    def url(self) -> str:
        return f"http://{self.host}:{self.port}"

    # --- scene -------------------------------------------------------------------------------
    def _add_splat(self, path: Path) -> int:
        """Show the capture's Gaussian splat in the scene's world frame; returns how many splats."""
        transform = np.asarray(self.sim.scene_json.get("capture", {}).get("input_to_world", np.eye(4)), dtype=float)
        self.splats = read_splat_ply(path, transform)
        self.server.scene.add_gaussian_splats("/backdrop/splat", centers=self.splats.centers, covariances=self.splats.covariances,
                                              rgbs=self.splats.rgbs, opacities=self.splats.opacities)
        return len(self.splats.centers)

    def _set_initial_camera(self) -> None:
        model, data = self.sim.model, self.sim.data
        free = [model.jnt_bodyid[j] for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
        centre = data.xpos[free].mean(axis=0) if free else np.asarray(model.stat.center)
        spread = float(np.max(np.ptp(data.xpos[free], axis=0))) if len(free) > 1 else 0.3
        distance = max(0.8, 2.0 * spread + 0.6)
        position, _ = to_viser(centre + distance * np.array([0.75, -0.75, 0.8]), np.array([1.0, 0, 0, 0]))
        self.server.initial_camera.position = tuple(position)
        self.server.initial_camera.look_at = tuple(float(v) for v in centre)

    def _build_gui(self) -> None:
        gui = self.server.gui
        gui.add_markdown(f"**realsim** · `{self.sim.folder.name}`")
        self._time_md = gui.add_markdown("sim time 0.00 s")
        pause = gui.add_checkbox("Pause physics", initial_value=self.sim.paused)
        reset = gui.add_button("Reset to keyframe 'initial'")
        self._command = gui.add_text("Command", initial_value="", hint="e.g. pick up the mug and put it on the box")
        send = gui.add_button("Send command")
        self._reply = gui.add_markdown("")

        @pause.on_update
        def _(_event) -> None:
            self.sim.paused = bool(pause.value)

        @reset.on_click
        def _(_event) -> None:
            self.sim.reset()

        @send.on_click
        def _(_event) -> None:
            self.command(self._command.value)

    def command(self, text: str) -> str:
        """Run one command (physics thread held off meanwhile) and show the reply in the GUI."""
        self._reply.content = f"running: *{text}*"
        self.sim.busy = True
        try:
            reply = on_command(self.sim, text)
        finally:
            self.sim.busy = False
        self.last_reply = reply
        self._reply.content = reply
        return reply

    # --- threads -----------------------------------------------------------------------------
    def _physics_loop(self) -> None:
        """Step in real time: keep simulated time within a few steps of wall time."""
        model, data = self.sim.model, self.sim.data
        wall0, sim0 = time.perf_counter(), data.time
        while not self._stop.is_set():
            if self.sim.paused or self.sim.busy:
                time.sleep(0.01)
                wall0, sim0 = time.perf_counter(), data.time
                continue
            target = sim0 + (time.perf_counter() - wall0)
            with self.sim.lock:
                if data.time < sim0:  # reset meanwhile
                    wall0, sim0, target = time.perf_counter(), data.time, data.time
                budget = time.perf_counter() + 0.02
                while data.time < target and time.perf_counter() < budget:
                    mujoco.mj_step(model, data)
                try:
                    check_state(model, data, "viewer")
                except SimulationDiverged as exc:  # pause and say so; Reset brings the scene back
                    self.sim.paused = True
                    self.last_reply = str(exc)
                    self._reply.content = f"physics paused: {exc}"
            if target - data.time > 0.1:  # slower than real time: don't try to catch up
                wall0, sim0 = time.perf_counter(), data.time
            time.sleep(0.002)

    def _stream_loop(self) -> None:
        """Send every moving body's pose at ``rate_hz``; count the frames sent."""
        period = 1.0 / self.rate_hz
        tick = 0
        next_time = time.perf_counter()
        while not self._stop.is_set():
            with self.sim.lock:
                xpos = self.sim.data.xpos.copy()
                xquat = self.sim.data.xquat.copy()
                sim_time = self.sim.data.time
            with self.server.atomic():
                for node in self.nodes:
                    pos, wxyz = to_viser(xpos[node.body], xquat[node.body])
                    node.handle.position = pos
                    node.handle.wxyz = wxyz
            self.server.flush()
            self.frames += 1
            tick += 1
            if tick % max(1, int(self.rate_hz / 4)) == 0:
                self._time_md.content = f"sim time {sim_time:.2f} s"
            next_time += period
            delay = next_time - time.perf_counter()
            if delay > 0:
                time.sleep(delay)
            else:
                next_time = time.perf_counter()

    def status(self) -> dict[str, Any]:
        """Simulated time, pose frames sent, clients connected and every moving body's pose."""
        with self.sim.lock:
            poses = {n.name: [*self.sim.data.xpos[n.body].round(6).tolist(), *self.sim.data.xquat[n.body].round(6).tolist()] for n in self.nodes}
            sim_time = float(self.sim.data.time)
        return {"sim_time": sim_time, "frames": self.frames, "clients": len(self.server.get_clients()), "paused": self.sim.paused,
                "url": self.url, "splats": self.splat_count, "bodies": poses}

    def start(self) -> "Viewer":
        for thread in self._threads:
            thread.start()
        return self

    def stop(self) -> None:
        self._stop.set()
        for thread in self._threads:
            if thread.is_alive():
                thread.join(timeout=2)
        if self._status_server is not None:
            self._status_server.shutdown()
        self.server.stop()


def _start_status_server(viewer: Viewer, host: str, port: int) -> ThreadingHTTPServer:
    class Handler(BaseHTTPRequestHandler):
        def do_GET(self) -> None:  # noqa: N802 (http.server API)
            if self.path.split("?")[0] != "/status":
                self.send_error(404)
                return
            body = json.dumps(viewer.status()).encode()
            self.send_response(200)
            self.send_header("Content-Type", "application/json")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)

        def log_message(self, *args) -> None:
            pass

    server = ThreadingHTTPServer((host, port), Handler)
    threading.Thread(target=server.serve_forever, name="realsim-status", daemon=True).start()
    return server


def serve(folder: Path, host: str = "127.0.0.1", port: int = 8080, *, splat: Path | None = None, paused: bool = False,
          duration: float | None = None, status_port: int | None = None) -> None:
    """Serve the viewer until Ctrl-C / SIGTERM (or ``duration`` seconds)."""
    import signal
    import sys

    if splat is not None and not Path(splat).is_file():
        raise InputError(f"--splat {splat}: no such file")
    # SIGTERM asks to stop: a flag, not an exception, so one arriving while the viewer still starts
    # (its status may already answer) stops it cleanly too, never as an interrupt (exit 130)
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_args: stop.set())
    viewer = Viewer(Path(folder), host=host, port=port, splat=splat, paused=paused, status_port=status_port)
    if viewer.port != port:
        print(f"realsim: warning: port {port} is taken; serving on {viewer.port} instead", file=sys.stderr)

    try:
        viewer.start()
        status = f", status at http://{host}:{status_port}/status" if status_port is not None else ""
        print(f"realsim view: serving {viewer.url} (Ctrl-C to stop){status}", flush=True)
        deadline = None if duration is None else time.monotonic() + duration
        while not stop.is_set() and (deadline is None or time.monotonic() < deadline):
            stop.wait(0.2)
    except KeyboardInterrupt:
        pass
    finally:
        viewer.stop()
