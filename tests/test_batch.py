"""`realsim batch` on a local Ray: captures in parallel, a corrupt one isolated, reruns skip.

Three captures: two object captures (a Rubik's cube; a strawberry) and a corrupt point cloud.
Two workers convert the good ones and report the bad one; a second run skips both scenes
without starting Ray, and a changed capture is converted again.
"""

from __future__ import annotations

import json
import shutil
import time
from pathlib import Path

import pytest

from conftest import YCB
from realsim import cli
from realsim.batch import expand_captures, run_batch
from realsim.errors import InputError

pytest.importorskip("ray")


def _object_capture(root: Path, folder: str) -> Path:
    cap = root / folder.split("_", 1)[1]
    dest = cap / "objects" / folder.split("_", 1)[1]
    dest.mkdir(parents=True)
    for file in (YCB / folder).glob("textured.*"):
        shutil.copyfile(file, dest / file.name)
    (cap / "capture.yaml").write_text("support: {size: [0.6, 0.8], height: 0.75}\n")
    return cap


@pytest.fixture()
def captures(tmp_path: Path) -> Path:
    root = tmp_path / "captures"
    _object_capture(root, "077_rubiks_cube")
    _object_capture(root, "012_strawberry")
    (root / "broken.pcd").write_bytes(b"# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                      b"WIDTH 1000\nHEIGHT 1\nPOINTS 1000\nDATA binary\n" + b"\x00" * 40)
    return root


def test_expand_captures_from_folder_glob_and_list(captures: Path, tmp_path: Path) -> None:
    found = expand_captures([str(captures)])
    assert [p.name for p in found] == ["broken.pcd", "rubiks_cube", "strawberry"]
    assert expand_captures([str(captures / "*_cube")]) == [(captures / "rubiks_cube").resolve()]
    listing = tmp_path / "list.txt"
    listing.write_text("# two captures\ncaptures/strawberry\ncaptures/broken.pcd\n")
    assert [p.name for p in expand_captures([str(listing)])] == ["strawberry", "broken.pcd"]
    with pytest.raises(InputError):
        expand_captures([str(tmp_path / "nothing-*")])


def test_batch_isolates_failures_and_resumes(captures: Path, tmp_path: Path, capsys) -> None:
    out = tmp_path / "scenes"
    code = cli.main(["batch", str(captures), "-o", str(out), "--workers", "2", "--no-robot"])
    assert code == 1  # one capture failed
    record = json.loads((out / "batch.json").read_text())
    status = {Path(c["capture"]).name: c for c in record["captures"]}
    assert status["rubiks_cube"]["status"] == "ok" and status["strawberry"]["status"] == "ok"
    assert status["broken.pcd"]["status"] == "failed" and status["broken.pcd"]["error"]
    assert (out / "rubiks_cube" / "scene.xml").is_file() and (out / "strawberry" / "scene.xml").is_file()
    assert not (out / "broken").exists()
    assert "2 converted, 0 unchanged (skipped), 1 failed" in capsys.readouterr().out

    started = time.perf_counter()  # a rerun: nothing changed, nothing runs (Ray is not even started)
    jobs, summary = run_batch([str(captures)], out, overrides={"robot": {"enabled": False}}, workers=2, progress=False)
    assert summary["skipped"] == 2 and summary["ok"] == 0 and summary["failed"] == 1 and time.perf_counter() - started < 10
    assert "not retried" in next(j.error for j in jobs if j.status == "failed")

    (captures / "strawberry" / "capture.yaml").write_text("support: {size: [0.7, 0.8], height: 0.75}\n")
    jobs, summary = run_batch([str(captures / "rubiks_cube"), str(captures / "strawberry")], out,
                              overrides={"robot": {"enabled": False}}, workers=2, progress=False)
    assert {j.name: j.status for j in jobs} == {"rubiks_cube": "skipped", "strawberry": "ok"}
