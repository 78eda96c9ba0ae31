"""The bad-input battery: a user's data is never lost, bad input is one line and exit 2, nothing hangs.

Each case is run through the real CLI in a subprocess (as a user would) on a small real capture:
an objects capture holding the YCB Rubik's cube on a declared table.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import stat
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import REPO, YCB

BRICK = YCB / "077_rubiks_cube" / "textured.obj"  # one convex hull: cheap to convert cold


def cli(*args: str, cwd: Path = REPO, env: dict | None = None, timeout: float = 600) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(REPO / "cli.py"), *args], capture_output=True, text=True, cwd=cwd,
                          env={**os.environ, **(env or {})}, timeout=timeout)


def one_line_error(result: subprocess.CompletedProcess, needle: str, code: int = 2) -> str:
    assert result.returncode == code, (result.returncode, result.stdout[-2000:], result.stderr[-2000:])
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    assert needle.lower() in lines[0].lower(), lines[0]
    return lines[0]


def snapshot(folder: Path) -> dict[str, tuple[int, bytes]]:
    """Every file under ``folder`` with its mode and bytes, and the folder's own mode."""
    out = {".": (stat.S_IMODE(folder.stat().st_mode), b"")}
    for p in sorted(folder.rglob("*")):
        out[str(p.relative_to(folder))] = (stat.S_IMODE(p.stat().st_mode), p.read_bytes() if p.is_file() else b"")
    return out


def user_folder(path: Path) -> Path:
    path.mkdir(parents=True)
    (path / "thesis.tex").write_text("\\chapter{Months of work}\n")
    (path / "data").mkdir()
    (path / "data" / "scan.bin").write_bytes(os.urandom(256))
    return path


def brick_capture(path: Path, yaml_text: str = "support: {size: [0.6, 0.4], height: 0.7}\n") -> Path:
    folder = path / "objects" / "rubiks_cube"
    folder.mkdir(parents=True)
    for f in BRICK.parent.iterdir():
        if f.name.startswith("textured.") or f.suffix in (".mtl", ".png"):
            shutil.copy(f, folder / f.name)
    (path / "capture.yaml").write_text(yaml_text)
    return path


@pytest.fixture(scope="module")
def converted(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """One real conversion (shared by the read-only checks below)."""
    root = tmp_path_factory.mktemp("converted")
    cap = brick_capture(root / "capture")
    result = cli("convert", str(cap), "-o", str(root / "scene"), "--no-robot")
    assert result.returncode == 0, result.stderr
    return root / "scene"


# --- outputs that cannot destroy anything -----------------------------------------------------------

@pytest.mark.parametrize("output", ["", " ", "."])
def test_output_empty_or_working_directory(tmp_path: Path, output: str) -> None:
    home = user_folder(tmp_path / "thesis")
    cap = brick_capture(tmp_path / "cap")
    before = snapshot(home)
    one_line_error(cli("convert", str(cap), "-o", output, cwd=home), "empty" if not output.strip() else "working directory")
    assert snapshot(home) == before


def test_output_is_parent_of_working_directory(tmp_path: Path) -> None:
    home = user_folder(tmp_path / "thesis")
    cap = brick_capture(tmp_path / "cap")
    before = snapshot(home)
    one_line_error(cli("convert", str(cap), "-o", "..", cwd=home / "data"), "working directory")
    assert snapshot(home) == before


@pytest.mark.parametrize("which", ["input", "parent"])
def test_output_is_the_input_or_its_parent(tmp_path: Path, which: str) -> None:
    cap = brick_capture(tmp_path / "project" / "cap")
    before = snapshot(tmp_path / "project")
    target = cap if which == "input" else cap.parent
    one_line_error(cli("convert", str(cap), "-o", str(target)), "input")
    assert snapshot(tmp_path / "project") == before


@pytest.mark.parametrize("output", ["/", "~"])
def test_output_root_or_home(tmp_path: Path, output: str) -> None:
    cap = brick_capture(tmp_path / "cap")
    one_line_error(cli("convert", str(cap), "-o", output, env={"HOME": str(tmp_path / "home")} if output == "~" else None),
                   "root folder" if output == "/" else "home folder")


@pytest.mark.parametrize("which", ["input", "output"])
def test_symlink_loop_is_a_one_line_error(tmp_path: Path, which: str) -> None:
    cap = brick_capture(tmp_path / "cap")
    loop = tmp_path / "loop"
    loop.symlink_to(loop)
    args = ("convert", str(loop), "-o", str(tmp_path / "out")) if which == "input" else ("convert", str(cap), "-o", str(loop))
    one_line_error(cli(*args), "symbolic links")


def test_existing_user_folder_untouched(tmp_path: Path) -> None:
    cap = brick_capture(tmp_path / "cap")
    mine = user_folder(tmp_path / "mine")
    before = snapshot(mine)
    one_line_error(cli("convert", str(cap), "-o", str(mine), "--force"), "realsim did not write")
    assert snapshot(mine) == before


def test_replace_needs_force_and_keeps_foreign_files(converted: Path, tmp_path: Path) -> None:
    scene = tmp_path / "scene"
    shutil.copytree(converted, scene)
    cap = brick_capture(tmp_path / "cap")
    before = snapshot(scene)
    one_line_error(cli("convert", str(cap), "-o", str(scene), "--no-robot"), "--force")
    assert snapshot(scene) == before
    (scene / "notes.txt").write_text("my notes")
    before = snapshot(scene)
    one_line_error(cli("convert", str(cap), "-o", str(scene), "--no-robot", "--force"), "notes.txt")
    assert snapshot(scene) == before


def test_force_replaces_atomically_with_normal_permissions(converted: Path, tmp_path: Path) -> None:
    scene = tmp_path / "scene"
    shutil.copytree(converted, scene)
    (scene / "runs").mkdir()
    (scene / "runs" / "run_1.json").write_text("{}")  # what `realsim run` writes may be replaced
    cap = brick_capture(tmp_path / "cap")
    result = cli("convert", str(cap), "-o", str(scene), "--no-robot", "--force", "--seed", "1")
    assert result.returncode == 0, result.stderr
    assert json.loads((scene / "scene.json").read_text())["seed"] == 1
    assert not (scene / "runs").exists()
    umask = os.umask(0)
    os.umask(umask)
    assert stat.S_IMODE(scene.stat().st_mode) == 0o777 & ~umask
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".scene.")], "build folder left behind"


def test_export_into_its_own_scene_refused(converted: Path, tmp_path: Path) -> None:
    scene = tmp_path / "scene"
    shutil.copytree(converted, scene)
    (scene / "runs").mkdir()
    (scene / "runs" / "run_1.json").write_text("{}")
    before = snapshot(scene)
    one_line_error(cli("export", str(scene), "--format", "mjcf", "-o", str(scene)), "input")
    one_line_error(cli("export", str(scene), "--format", "mjcf", "-o", str(tmp_path)), "input")
    assert snapshot(scene) == before


def test_export_replaces_only_with_force(converted: Path, tmp_path: Path) -> None:
    dest = tmp_path / "export"
    assert cli("export", str(converted), "--format", "mjcf", "-o", str(dest)).returncode == 0
    one_line_error(cli("export", str(converted), "--format", "mjcf", "-o", str(dest)), "--force")
    assert cli("export", str(converted), "--format", "mjcf", "-o", str(dest), "--force").returncode == 0
    usd = tmp_path / "scene.usda"
    usd.write_text("#usda 1.0\n(my own stage)\n")
    one_line_error(cli("export", str(converted), "--format", "usd", "-o", str(usd)), "--force")
    assert usd.read_text() == "#usda 1.0\n(my own stage)\n"


def test_read_only_destination_fails_before_any_work(tmp_path: Path) -> None:
    """A read-only file system (a tmpfs mounted read-only in a private user and mount namespace)."""
    if shutil.which("unshare") is None or subprocess.run(["unshare", "-rm", "true"]).returncode != 0:
        pytest.skip("needs unshare -rm (user namespaces) for a private read-only mount")
    cap = brick_capture(tmp_path / "cap")
    ro = tmp_path / "ro"
    ro.mkdir()
    script = (f"mount -t tmpfs -o ro tmpfs {ro} && cd {REPO} && "
              f"{sys.executable} cli.py convert {cap} -o {ro}/out --no-robot")
    started = time.monotonic()
    result = subprocess.run(["unshare", "-rm", "sh", "-c", script], capture_output=True, text=True, timeout=120)
    one_line_error(result, "read-only file system")
    assert time.monotonic() - started < 30, "the check must come before the work"


# --- validation at the door ------------------------------------------------------------------------

@pytest.mark.parametrize("flags, needle", [
    (["--seed", "-1"], "--seed"),
    (["--seed", "1.5"], "--seed"),
    (["--robot-pose", "nan,0,0"], "finite"),
    (["--robot-pose", "1,2"], "x,y,yaw"),
    (["--set", "planes.distance_threshold=abc"], "valid number"),
    (["--set", "planes.distance_threshold=-1"], "positive"),
    (["--set", "planes.distance_threshold=.inf"], "finite"),
    (["--set", "planes.distance_treshold=0.01"], "did you mean 'distance_threshold'"),
    (["--set", "plane.distance_threshold=0.01"], "did you mean 'planes'"),
    (["--set", "objects.assets.nonsense=1"], "nonsense"),
    (["--units", "km"], "--units"),
])
def test_bad_flags_exit_2_at_once(tmp_path: Path, flags: list[str], needle: str) -> None:
    cap = tmp_path / "scan.pcd"
    shutil.copy(REPO.parent / "shared" / "data" / "pcl_scenes" / "mOSD" / "test0.pcd", cap)
    started = time.monotonic()
    one_line_error(cli("convert", str(cap), "-o", str(tmp_path / "out"), *flags), needle)
    assert time.monotonic() - started < 20
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("yaml_text, needle", [
    ("support_height: abc\n", "support_height"),
    ("support_height: -3\n", "greater than or equal to 0"),
    ("support_height: 12\n", "less than or equal to 3"),
    ("suport_height: 0.7\n", "did you mean 'support_height'"),
    ("labels: [1, 2]\n", "labels"),
    ("support: {size: [0.6, 0.001], height: 0.7}\n", "support.size"),
    ("support: {size: [0.6, 0.4], hieght: 0.7}\n", "did you mean 'height'"),
    ("units: km\n", "units"),
    ("- just\n- a list\n", "mapping"),
    ("a: [unclosed\n", "invalid yaml"),
])
def test_bad_capture_yaml_exit_2_before_work(tmp_path: Path, yaml_text: str, needle: str) -> None:
    cap = brick_capture(tmp_path / "cap", yaml_text)
    started = time.monotonic()
    one_line_error(cli("convert", str(cap), "-o", str(tmp_path / "out")), needle)
    assert time.monotonic() - started < 20


def test_check_validates_without_running(tmp_path: Path) -> None:
    cap = brick_capture(tmp_path / "cap")
    result = cli("convert", str(cap), "-o", str(tmp_path / "out"), "--check")
    assert result.returncode == 0 and "nothing was run" in result.stdout, result.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("pose, needle", [("0,0,0", "inside the table"), ("100,0,0", "reaches")])
def test_robot_pose_inside_furniture_or_out_of_reach(tmp_path: Path, pose: str, needle: str) -> None:
    cap = brick_capture(tmp_path / "cap")
    one_line_error(cli("convert", str(cap), "-o", str(tmp_path / "out"), f"--robot-pose={pose}"), needle)
    assert not (tmp_path / "out").exists()


# --- honest reports --------------------------------------------------------------------------------

def test_missing_texture_is_warned(tmp_path: Path) -> None:
    cap = brick_capture(tmp_path / "cap")
    for png in (cap / "objects").rglob("*.png"):  # (the cube's scan ships without its texture image)
        png.unlink()
    result = cli("convert", str(cap), "-o", str(tmp_path / "out"), "--no-robot")
    assert result.returncode == 0, result.stderr
    assert "missing" in result.stderr and "texture_map.png" in result.stderr
    warnings = json.loads((tmp_path / "out" / "scene.json").read_text())["warnings"]
    assert any("texture_map.png" in w for w in warnings)
    assert "labels.npy" not in result.stdout  # an objects capture has no per-point labels
    assert not (tmp_path / "out" / "labels.npy").exists()


def test_runaway_program_reason_on_stderr(converted: Path, tmp_path: Path) -> None:
    scene = tmp_path / "scene"
    shutil.copytree(converted, scene)
    program = tmp_path / "spin.py"
    program.write_text("while True:\n    pass\n")
    result = cli("run", str(scene), "--program", str(program), timeout=120)
    assert result.returncode == 2, result.stderr
    assert "runaway" in result.stderr.strip().splitlines()[-1]


# --- faults: kill -9, concurrent runs ------------------------------------------------------------------

def _convert_process(cap: Path, out: Path, *extra: str, cache: Path) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, str(REPO / "cli.py"), "convert", str(cap), "-o", str(out), "--no-robot", *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=REPO,
                            env={**os.environ, "REALSIM_CACHE": str(cache)})


def test_kill_during_conversion_leaves_old_output_and_cache_usable(converted: Path, tmp_path: Path) -> None:
    scene = tmp_path / "scene"
    shutil.copytree(converted, scene)
    before = snapshot(scene)
    cap = brick_capture(tmp_path / "cap")
    cache = tmp_path / "cache"
    proc = _convert_process(cap, scene, "--force", "--seed", "3", cache=cache)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and not any(p.name.startswith(".scene.realsim-tmp") for p in tmp_path.iterdir()):
        time.sleep(0.01)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    assert snapshot(scene) == before, "the old output changed"
    result = cli("convert", str(cap), "-o", str(scene), "--no-robot", "--force", "--seed", "3", env={"REALSIM_CACHE": str(cache)})
    assert result.returncode == 0, result.stderr
    assert json.loads((scene / "scene.json").read_text())["seed"] == 3
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".scene.")], "a killed run's build folder was left"


def test_concurrent_conversions_share_a_cache_and_an_output(tmp_path: Path) -> None:
    cap = brick_capture(tmp_path / "cap")
    cache = tmp_path / "cache"
    a = _convert_process(cap, tmp_path / "a", cache=cache)
    b = _convert_process(cap, tmp_path / "b", cache=cache)
    assert a.wait(timeout=600) == 0 and b.wait(timeout=600) == 0, (a.stderr.read(), b.stderr.read())
    assert (tmp_path / "a" / "scene.xml").read_bytes() == (tmp_path / "b" / "scene.xml").read_bytes()
    # Two runs into one output folder: each result is whole (one of them wins), never a mixture.
    same = [_convert_process(cap, tmp_path / "same", "--force", "--seed", str(s), cache=cache) for s in (5, 6)]
    codes = [p.wait(timeout=600) for p in same]
    assert codes.count(0) >= 1 and set(codes) <= {0, 2}, [p.stderr.read() for p in same]
    manifest = json.loads((tmp_path / "same" / ".realsim-manifest.json").read_text())
    files = sorted(str(p.relative_to(tmp_path / "same")) for p in (tmp_path / "same").rglob("*") if p.is_file())
    assert sorted(manifest["files"] + [".realsim-manifest.json"]) == files
    seed = json.loads((tmp_path / "same" / "scene.json").read_text())["seed"]
    assert seed in (5, 6)


def test_render_and_run_files_replaced_only_with_force(converted: Path, tmp_path: Path) -> None:
    png = tmp_path / "shot.png"
    png.write_bytes(b"my own picture")
    one_line_error(cli("render", str(converted), "-o", str(png), "--width", "64", "--height", "48"), "--force")
    assert png.read_bytes() == b"my own picture"
    assert cli("render", str(converted), "-o", str(png), "--width", "64", "--height", "48", "--force").returncode == 0
    assert png.read_bytes() != b"my own picture"
    log = tmp_path / "log.json"
    log.write_text("mine")
    one_line_error(cli("run", str(converted), "go home", "--log", str(log)), "--force")
    assert log.read_text() == "mine"
