"""Warm reruns do no work: the same inputs, parameters and code give the stored output back.

A first conversion fills the test's cache. A rerun into another folder must then not search a
robot pose, settle or render (those functions are replaced by ones that fail) and still write
the same bytes; with whole-conversion reuse on, it must not even run the pipeline, and every
file (scene.json included) is byte-identical. Any change to an input, the seed or a parameter
gives another key.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from conftest import YCB
from realsim import cli, rerun


def _files(folder: Path) -> dict[str, bytes]:
    return {p.relative_to(folder).as_posix(): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.fixture()
def capture(tmp_path: Path) -> Path:
    cap = tmp_path / "capture"
    for folder in ("077_rubiks_cube", "012_strawberry"):
        dest = cap / "objects" / folder.split("_", 1)[1]
        dest.mkdir(parents=True)
        for file in (YCB / folder).glob("textured.*"):
            shutil.copyfile(file, dest / file.name)
    (cap / "capture.yaml").write_text("support: {size: [0.6, 0.8], height: 0.75}\n")
    return cap


def _forbid(monkeypatch: pytest.MonkeyPatch, target: str) -> None:
    def fail(*args, **kwargs):
        raise AssertionError(f"{target} ran on a warm rerun")

    monkeypatch.setattr(target, fail)


def test_warm_rerun_reuses_everything(capture: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys) -> None:
    assert cli.main(["convert", str(capture), "-o", str(tmp_path / "first"), "--seed", "2", "-q"]) == 0
    first = _files(tmp_path / "first")

    # stage caches alone (whole-conversion reuse off): no pose search, no settling, no render
    monkeypatch.setenv("REALSIM_REUSE", "0")
    for target in ("realsim.composition.robot_mount.add_robot", "realsim.composition.settle._settle", "realsim.render.render_scene"):
        _forbid(monkeypatch, target)
    assert cli.main(["convert", str(capture), "-o", str(tmp_path / "staged"), "--seed", "2", "-q"]) == 0
    staged = _files(tmp_path / "staged")
    assert staged.keys() == first.keys()
    assert all(staged[f] == first[f] for f in first if f not in ("scene.json", ".realsim-manifest.json"))

    # whole-conversion reuse: the pipeline does not run at all, and every byte is the first run's
    monkeypatch.setenv("REALSIM_REUSE", "1")
    _forbid(monkeypatch, "realsim.pipeline.run_pipeline")
    capsys.readouterr()
    assert cli.main(["convert", str(capture), "-o", str(tmp_path / "again"), "--seed", "2"]) == 0
    assert "timings: reused" in capsys.readouterr().out
    assert _files(tmp_path / "again") == first

    # replacing an output with --force reuses too
    assert cli.main(["convert", str(capture), "-o", str(tmp_path / "first"), "--seed", "2", "--force", "-q"]) == 0
    assert _files(tmp_path / "first") == first


def test_key_follows_inputs_and_parameters(capture: Path) -> None:
    base = {"seed": 0, "overrides": {"load": {}}, "pipeline": None}
    key = rerun.conversion_key(capture, base)
    assert key == rerun.conversion_key(capture, dict(base))
    assert key != rerun.conversion_key(capture, {**base, "seed": 1})
    assert key != rerun.conversion_key(capture, {**base, "overrides": {"settle": {"max_time": 3.0}}})
    (capture / "capture.yaml").write_text("support: {size: [0.6, 0.8], height: 0.76}\n")
    assert key != rerun.conversion_key(capture, base)
