"""A converted scene runs anywhere: `run`, `view`, `render` and `export` need only the folder.

A scene is converted (with the Menagerie available, as converting needs it), moved to another
path, and then commanded from fresh processes in which the Menagerie cannot be reached:
``MENAGERIE_ROOT`` unset, the mujoco-menagerie package pointed at an empty cache and at a
download URL that refuses connections. The same holds for a folder made by
``realsim export --format mjcf``. The Menagerie cache must still be empty at the end: nothing
even tried to fetch the robot.
"""

from __future__ import annotations

import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from conftest import REPO, YCB
from realsim import cli

COMMAND = "put the strawberry next to the rubiks cube"


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def offline(tmp_path_factory: pytest.TempPathFactory) -> tuple[dict[str, str], Path]:
    """An environment in which the Menagerie cannot be found or downloaded, and its (empty) cache."""
    cache = tmp_path_factory.mktemp("menagerie-empty-cache")
    env = {k: v for k, v in os.environ.items() if k not in ("MENAGERIE_ROOT", "ANTHROPIC_API_KEY")}
    env.update(MENAGERIE_CACHE_DIR=str(cache), MENAGERIE_BASE_URL=f"http://127.0.0.1:{_free_port()}/no-network",
               MUJOCO_GL="egl", PYTHONPATH=str(REPO))
    probe = subprocess.run([sys.executable, "-c", "import mujoco_menagerie as m; m.get('franka_emika_panda').path(progress=None)"],
                           env=env, capture_output=True, text=True, timeout=120)
    assert probe.returncode != 0 and "DownloadError" in probe.stderr, "the Menagerie is still reachable: the test proves nothing"
    shutil.rmtree(cache)
    cache.mkdir()
    return env, cache


@pytest.fixture(scope="module")
def moved_scene(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A strawberry and a Rubik's cube on a table, converted, then moved to another folder."""
    root = tmp_path_factory.mktemp("anywhere")
    capture = root / "capture"
    for folder in ("077_rubiks_cube", "012_strawberry"):
        dest = capture / "objects" / folder.split("_", 1)[1]
        dest.mkdir(parents=True)
        for file in (YCB / folder).glob("textured.*"):
            shutil.copyfile(file, dest / file.name)
    (capture / "capture.yaml").write_text("support: {size: [0.6, 0.8], height: 0.75}\n")
    assert cli.main(["convert", str(capture), "-o", str(root / "out"), "-q"]) == 0
    moved = root / "elsewhere" / "kitchen"
    moved.parent.mkdir()
    shutil.move(root / "out", moved)
    return moved


def _cli(env: dict[str, str], *argv: str, timeout: float = 300) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(REPO / "cli.py"), *argv], env=env, capture_output=True, text=True,
                          timeout=timeout, cwd=str(Path(argv[1]).parent))


def _run_view_render(folder: Path, env: dict[str, str], tmp_path: Path) -> None:
    """`realsim run` reaches its goal, `realsim view` serves its status, `realsim render` writes a picture."""
    log = tmp_path / "run.json"
    done = _cli(env, "run", str(folder), COMMAND, "--planner", "rules", "--log", str(log))
    assert done.returncode == 0, done.stdout + done.stderr
    record = json.loads(log.read_text())
    assert record["verdict"] == "met" and all(g["ok"] for g in record["goals"])
    assert record["calls"] and all(c["success"] for c in record["calls"])
    berry = next(n for n in record["objects_before"] if "strawberry" in n)
    moved = np.subtract(record["objects_after"][berry], record["objects_before"][berry])
    assert np.linalg.norm(moved[:2]) > 0.03  # picked up and put down elsewhere

    png = tmp_path / "render.png"
    done = _cli(env, "render", str(folder), "-o", str(png), "--width", "160", "--height", "120")
    assert done.returncode == 0, done.stdout + done.stderr
    image = np.asarray(Image.open(png).convert("RGB")).astype(int)
    assert image.shape == (120, 160, 3) and image.std() > 10

    port, status_port = _free_port(), _free_port()
    server = subprocess.Popen([sys.executable, str(REPO / "cli.py"), "view", str(folder), "--port", str(port),
                               "--status-port", str(status_port)], env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True)
    try:
        status = None
        deadline = time.monotonic() + 90
        while status is None and time.monotonic() < deadline and server.poll() is None:
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{status_port}/status", timeout=2) as response:
                    status = json.loads(response.read())
            except OSError:
                time.sleep(0.3)
        assert status is not None, f"the viewer did not answer (exit {server.poll()})"
        assert status["url"] == f"http://127.0.0.1:{port}"
        assert any(n.startswith("panda/") for n in status["bodies"]) and any("strawberry" in n for n in status["bodies"])
    finally:
        server.terminate()
        try:
            output, _ = server.communicate(timeout=15)
        except subprocess.TimeoutExpired:
            server.kill()
            output, _ = server.communicate()
    assert server.returncode == 0 and "Traceback" not in output, output


def test_moved_scene_runs_offline(moved_scene: Path, offline: tuple[dict[str, str], Path], tmp_path: Path) -> None:
    env, menagerie_cache = offline
    _run_view_render(moved_scene, env, tmp_path)
    assert not any(menagerie_cache.iterdir()), "something asked mujoco-menagerie for the robot"


def test_exported_mjcf_runs_offline(moved_scene: Path, offline: tuple[dict[str, str], Path], tmp_path: Path) -> None:
    env, menagerie_cache = offline
    exported = tmp_path / "exported"
    done = _cli(env, "export", str(moved_scene), "--format", "mjcf", "-o", str(exported))
    assert done.returncode == 0, done.stdout + done.stderr
    relocated = tmp_path / "copied" / "scene"
    relocated.parent.mkdir()
    shutil.move(exported, relocated)
    _run_view_render(relocated, env, tmp_path)
    assert not any(menagerie_cache.iterdir()), "something asked mujoco-menagerie for the robot"


def test_robot_is_read_from_the_scene(moved_scene: Path) -> None:
    """The IK model copied out of scene.xml has the Menagerie Panda's kinematics (within the
    XML's printed precision), and scene.json names every robot element the runtime looks up."""
    import mujoco

    from realsim.robot.model import describe_robot, robot_kinematics, robot_only_model

    scene = mujoco.MjModel.from_xml_path(str(moved_scene / "scene.xml"))
    record = json.loads((moved_scene / "scene.json").read_text())["robot"]
    robot = describe_robot(scene, record)
    assert robot.tcp_site == record["tcp_site"] == "panda/tcp" and len(robot.arm_joints) == 7
    assert robot.home_arm == pytest.approx(record["home_arm"]) and robot.gripper_max_opening == pytest.approx(0.08)
    ours = robot_kinematics(scene, robot.base_body)
    reference = robot_only_model(np.zeros(3), np.array([1.0, 0.0, 0.0, 0.0]))
    np.testing.assert_allclose(ours.jnt_range, reference.jnt_range)
    a, b = mujoco.MjData(ours), mujoco.MjData(reference)
    rng = np.random.default_rng(0)
    for _ in range(20):
        q = rng.uniform(reference.jnt_range[:, 0], reference.jnt_range[:, 1])
        a.qpos[:], b.qpos[:] = q, q
        mujoco.mj_kinematics(ours, a)
        mujoco.mj_kinematics(reference, b)
        np.testing.assert_allclose(a.site("panda/tcp").xpos, b.site("panda/tcp").xpos, atol=1e-5)
        np.testing.assert_allclose(a.site("panda/tcp").xmat, b.site("panda/tcp").xmat, atol=1e-5)
