"""`realsim render` and `write_preview` on a small scene folder built with MjSpec."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
from PIL import Image

from realsim import cli
from realsim.render import write_preview


@pytest.fixture()
def folder(tmp_path: Path) -> Path:
    spec = mujoco.MjSpec()
    spec.worldbody.add_light(pos=[0, 0, 3], dir=[0, 0, -1])
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[2, 2, 0.1], rgba=[0.3, 0.3, 0.35, 1], group=2)
    spec.worldbody.add_camera(name="capture", pos=[0.8, -0.8, 0.8], xyaxes=[1, 1, 0, -0.4, 0.4, 0.8])
    box = spec.worldbody.add_body(name="obj1_box", pos=[0, 0, 0.05])
    box.add_freejoint(name="obj1_box_joint")
    box.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.05, 0.05, 0.05], rgba=[0.9, 0.2, 0.1, 1], group=2)
    model = spec.compile()
    spec.add_key(name="home", qpos=model.qpos0.tolist())
    qpos = model.qpos0.copy()
    qpos[:3] = [0.3, 0.0, 0.05]  # 'initial' differs from 'home': render must use 'initial'
    spec.add_key(name="initial", qpos=qpos.tolist())
    (tmp_path / "scene.xml").write_text(spec.to_xml())
    return tmp_path


def _red_centroid_x(png: Path) -> float:
    image = np.asarray(Image.open(png).convert("RGB")).astype(int)
    red = (image[..., 0] > 120) & (image[..., 1] < 80) & (image[..., 2] < 80)
    assert red.sum() > 50, "the red box is not in the picture"
    return float(np.nonzero(red)[1].mean())


def test_render_cli_and_cameras(folder, tmp_path, capsys):
    out = tmp_path / "shots" / "preview.png"
    assert cli.main(["render", str(folder), "-o", str(out), "--width", "320", "--height", "240"]) == 0
    assert Image.open(out).size == (320, 240)
    _red_centroid_x(out)
    assert cli.main(["render", str(folder), "-o", str(tmp_path / "cap.png"), "--camera", "capture"]) == 0
    _red_centroid_x(tmp_path / "cap.png")
    assert cli.main(["render", str(folder), "-o", str(tmp_path / "x.png"), "--camera", "nope"]) == 2
    assert cli.main(["render", str(tmp_path / "missing"), "-o", str(tmp_path / "y.png")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and "capture" in err[0]


def test_write_preview_uses_keyframe_initial(folder):
    path = write_preview(folder)
    assert path == folder / "preview.png" and path.is_file()
    model = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    assert model.key("initial").qpos[0] == pytest.approx(0.3)
    assert write_preview(folder / "does-not-exist") is None
