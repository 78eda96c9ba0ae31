"""`realsim view`: the browser viewer draws the scene and streams poses while physics runs.

The end-to-end test starts `realsim view` in a subprocess on free ports, opens it in headless
Chromium (Debian's `chromium`, WebGL through SwiftShader) driven over the DevTools protocol,
checks a screenshot shows the scene, and reads the viewer's /status endpoint twice.
"""

from __future__ import annotations

import base64
import io
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
import types
import urllib.request
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from conftest import REPO, YCB
from realsim import cli

CHROMIUM = Path("/usr/bin/chromium")
WIDTH, HEIGHT = 800, 600  # SwiftShader renders on the CPU: a small viewport keeps the test quick


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _get_json(url: str, timeout: float = 2.0) -> dict:
    with urllib.request.urlopen(url, timeout=timeout) as response:
        return json.loads(response.read())


def _wait_for(predicate, timeout: float, what: str):
    deadline = time.monotonic() + timeout
    last = None
    while time.monotonic() < deadline:
        try:
            last = predicate()
            if last:
                return last
        except OSError:
            pass
        time.sleep(0.2)
    raise AssertionError(f"timed out waiting for {what} (last: {last!r})")


class DevTools:
    """A minimal Chrome DevTools Protocol client over one page's websocket."""

    def __init__(self, ws_url: str):
        from websockets.sync.client import connect

        self.ws = connect(ws_url, max_size=None, open_timeout=10)
        self.next_id = 0

    def call(self, method: str, timeout: float = 30.0, **params) -> dict:
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        deadline = time.monotonic() + timeout
        while True:
            message = json.loads(self.ws.recv(timeout=max(0.1, deadline - time.monotonic())))
            if message.get("id") == self.next_id:
                if "error" in message:
                    raise AssertionError(f"{method}: {message['error']}")
                return message.get("result", {})

    def close(self) -> None:
        self.ws.close()


def _screenshot(page: DevTools) -> np.ndarray:
    # SwiftShader renders WebGL on the CPU: on a loaded 2-core machine one frame took over 30 s
    shot = page.call("Page.captureScreenshot", timeout=120.0, format="png")
    return np.asarray(Image.open(io.BytesIO(base64.b64decode(shot["data"]))).convert("RGB")).astype(int)


def _scene_drawn(image: np.ndarray) -> str | None:
    """None when the screenshot shows the scene, else what is missing."""
    if image.shape[:2] != (HEIGHT, WIDTH):
        return f"screenshot is {image.shape[1]}x{image.shape[0]}, not {WIDTH}x{HEIGHT}"
    canvas = image[150:, : WIDTH - 340]  # left of and below the GUI panel
    if canvas.std() < 15:
        return "the canvas is blank"
    colours = len({tuple(c) for c in (canvas[::4, ::4] // 16).reshape(-1, 3)})
    if colours < 20:
        return f"only {colours} colours: the scene is not drawn"
    r, g, b = canvas[..., 0], canvas[..., 1], canvas[..., 2]
    table = (r - b > 15) & (r > g) & (g > b)  # the support box (brown, lit brightly by viser)
    if table.mean() < 0.01:
        return "the support box is not visible"
    return None


@pytest.fixture(scope="module")
def scene(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("viewer-scene")
    capture = root / "capture"
    (capture / "objects" / "077_rubiks_cube").mkdir(parents=True)
    for file in ("textured.obj", "textured.mtl"):
        shutil.copyfile(YCB / "077_rubiks_cube" / file, capture / "objects" / "077_rubiks_cube" / file)
    (capture / "capture.yaml").write_text("support: {size: [1.0, 0.7], height: 0.75}\n")
    assert cli.main(["convert", str(capture), "-o", str(root / "out"), "-q"]) == 0
    return root / "out"


@pytest.mark.skipif(not CHROMIUM.exists(), reason="needs Debian's chromium at /usr/bin/chromium (apt-get install -y chromium)")
def test_view_draws_scene_and_streams_poses(scene, tmp_path):
    port, status_port = _free_port(), _free_port()
    env = {**os.environ, "MUJOCO_GL": "egl"}
    server = subprocess.Popen([sys.executable, str(REPO / "cli.py"), "view", str(scene), "--port", str(port), "--status-port", str(status_port)],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env, text=True)
    browser = None
    try:
        status_url = f"http://127.0.0.1:{status_port}/status"
        first = _wait_for(lambda: _get_json(status_url), 60, "the viewer's status endpoint")
        assert first["url"] == f"http://127.0.0.1:{port}"
        profile = tmp_path / "chromium-profile"
        browser = subprocess.Popen(
            [str(CHROMIUM), "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync", "--use-angle=swiftshader",
             "--enable-unsafe-swiftshader", f"--user-data-dir={profile}", f"--window-size={WIDTH},{HEIGHT}", "--remote-debugging-port=0",
             "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        active = profile / "DevToolsActivePort"
        devtools_port = _wait_for(lambda: active.exists() and active.read_text().split("\n")[0].strip(), 30, "chromium's DevTools port")
        pages = _wait_for(lambda: [t for t in _get_json(f"http://127.0.0.1:{devtools_port}/json/list") if t["type"] == "page"], 10, "a page")
        page = DevTools(pages[0]["webSocketDebuggerUrl"])
        page.call("Page.enable")
        page.call("Emulation.setDeviceMetricsOverride", width=WIDTH, height=HEIGHT, deviceScaleFactor=1, mobile=False)
        page.call("Page.navigate", url=f"http://127.0.0.1:{port}/")
        _wait_for(lambda: _get_json(status_url)["clients"] >= 1, 30, "the browser to connect over the websocket")
        deadline = time.monotonic() + 120  # meshes arrive, SwiftShader compiles shaders and fades the scene in (slow on a loaded CPU)
        while True:
            time.sleep(1.5)
            image = _screenshot(page)
            drawn = _scene_drawn(image)
            if drawn is None or time.monotonic() > deadline:
                break
        Image.fromarray(image.astype(np.uint8)).save(tmp_path / "view.png")
        assert drawn is None, f"{drawn} (screenshot: {tmp_path / 'view.png'})"
        a = _get_json(status_url)
        time.sleep(1.0)
        b = _get_json(status_url)
        page.close()

        assert b["clients"] >= 1
        assert b["frames"] - a["frames"] >= 30, "poses stream at less than 30 Hz"
        assert 0.5 < b["sim_time"] - a["sim_time"] < 2.0, "physics does not run in real time"
        assert "obj1_rubiks_cube" in b["bodies"] and any(n.startswith("panda/") for n in b["bodies"])
        assert np.isfinite(b["bodies"]["obj1_rubiks_cube"]).all()
    finally:
        if browser is not None:
            os.killpg(browser.pid, signal.SIGTERM)
            browser.wait(timeout=10)
        server.terminate()
        try:
            output, _ = server.communicate(timeout=15)
        except subprocess.TimeoutExpired:
            server.kill()
            output, _ = server.communicate()
    assert server.returncode == 0, output
    assert "Traceback" not in output


def test_view_rejects_a_folder_without_scene(tmp_path, capsys):
    assert cli.main(["view", str(tmp_path), "--port", str(_free_port())]) == 2
    assert capsys.readouterr().err.strip().startswith("realsim: error:")


def test_on_command_uses_runtime_when_present(monkeypatch):
    from realsim.viewer import NEEDS_RUNTIME, on_command

    monkeypatch.setitem(sys.modules, "realsim.runtime", types.ModuleType("realsim.runtime"))
    assert on_command(object(), "pick up the mug") == NEEDS_RUNTIME
    runtime = types.ModuleType("realsim.runtime")
    runtime.run_command = lambda sim, text: f"ran {text!r} on {sim}"
    monkeypatch.setitem(sys.modules, "realsim.runtime", runtime)
    assert on_command("sim", "pick up the mug") == "ran 'pick up the mug' on sim"
    runtime.run_command = lambda sim, text: 1 / 0
    assert on_command("sim", "x").startswith("command failed: ZeroDivisionError")


def test_command_box_runs_the_robot_on_the_viewers_state(scene):
    """The text box's hook plans and runs a sentence on the live sim: the cube ends up lifted."""
    from realsim.viewer import on_command
    from realsim.viewer.server import load_live_sim

    live, _ = load_live_sim(scene)
    body = next(n for n in (live.model.body(b).name for b in range(live.model.nbody)) if "rubiks" in n)
    z0 = float(live.data.body(body).xpos[2])
    reply = on_command(live, "pick up the rubiks cube")
    assert reply.startswith("met"), reply
    assert float(live.data.body(body).xpos[2]) > z0 + 0.03  # the viewer's own data moved


def test_mujoco_poses_pass_to_viser_unchanged():
    from realsim.viewer import to_viser

    pos, quat = to_viser(np.array([1.0, 2.0, 3.0]), np.array([2.0, 0.0, 0.0, 0.0]))
    np.testing.assert_array_equal(pos, [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(quat, [1.0, 0.0, 0.0, 0.0])
