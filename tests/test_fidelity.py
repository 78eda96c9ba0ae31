"""The simulated scene looks and measures like the captured one (a real Kinect scan, mOSD test0).

The scan is converted once (without the robot); the written scene is rendered from its camera
``capture`` at keyframe ``initial`` and compared with the capture's own RGB-D on every pixel
with depth. Also: the fitted intrinsics, MuJoCo's principal-point convention, the visual-only
backdrop and the output size.
"""

from __future__ import annotations

import os
from pathlib import Path

import mujoco
import numpy as np
import pytest

from conftest import MOSD
from realsim.fidelity import capture_rgbd, compare, render_rgbd
from realsim.perception.intrinsics import Intrinsics, fit_intrinsics
from realsim.perception.pcd_io import read_pcd
from realsim.pipeline import convert

NO_ROBOT = {"robot": {"enabled": False}}


@pytest.fixture(scope="module")
def scan(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("fidelity") / "test0"
    convert(MOSD / "test0.pcd", out, overrides=NO_ROBOT)
    return out


def test_fit_intrinsics_recovers_a_pinhole_grid() -> None:
    h, w, fx, fy, cx, cy = 60, 80, 70.0, 72.0, 41.3, 28.9
    v, u = np.mgrid[0:h, 0:w]
    z = 1.0 + 0.3 * np.sin(u / 9.0) + 0.1 * (v / h)
    pts = np.stack([(u - cx) / fx * z, (v - cy) / fy * z, z], axis=-1).reshape(-1, 3)
    pts[::7] = np.nan  # holes, as in a real depth image
    intr = fit_intrinsics(pts, (h, w))
    assert intr is not None
    assert np.allclose([intr.fx, intr.fy, intr.cx, intr.cy], [fx, fy, cx, cy], atol=1e-6)
    scrambled = pts.copy()
    np.random.default_rng(0).shuffle(scrambled)  # not a projective grid any more
    assert fit_intrinsics(scrambled, (h, w)) is None


def test_mujoco_camera_puts_a_point_where_the_intrinsics_say() -> None:
    intr = Intrinsics(fx=300.0, fy=310.0, cx=140.0, cy=95.0, width=320, height=240)  # principal point off centre
    point = np.array([0.08, -0.05, 1.0])  # optical frame: +x right, +y down, +z forward
    spec = mujoco.MjSpec()
    spec.visual.headlight.ambient = [1, 1, 1]
    cam = spec.worldbody.add_camera(name="capture")  # MuJoCo looks along -z with +y up
    for key, value in intr.mujoco_camera().items():
        setattr(cam, key, value)
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[0.004, 0, 0], pos=[point[0], -point[1], -point[2]], rgba=[1, 0, 0, 1])
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    with mujoco.Renderer(model, intr.height, intr.width) as renderer:
        renderer.update_scene(data, camera="capture")
        image = renderer.render()
    rows, cols = np.nonzero(image[..., 0] > 128)
    expected = intr.project(point)[0]
    assert abs(cols.mean() - expected[0]) < 0.5 and abs(rows.mean() - expected[1]) < 0.5


def test_render_from_the_capture_camera_matches_the_capture(scan: Path) -> None:
    data = read_pcd(MOSD / "test0.pcd")
    intr = fit_intrinsics(data.points, data.grid_shape)
    model = mujoco.MjModel.from_xml_path(str(scan / "scene.xml"))
    cam = model.camera("capture").id
    assert np.allclose(model.cam_intrinsic[cam][:2], [intr.fx, intr.fy], atol=0.01)  # written with the fitted intrinsics
    assert np.allclose(model.cam_resolution[cam], [640, 480])
    render, robot = render_rgbd(model, intr)
    fid = compare(render, capture_rgbd(data.points, data.colors, data.grid_shape), exclude=robot)
    assert fid.pixels > 150_000
    assert fid.psnr_db >= 22.0 and fid.ssim >= 0.85, fid
    assert fid.depth_median_mm <= 3.0 and fid.within_1cm >= 0.97, fid


def test_backdrop_and_textures_are_visual_only(scan: Path) -> None:
    model = mujoco.MjModel.from_xml_path(str(scan / "scene.xml"))
    backdrop = model.geom("backdrop_visual")
    assert backdrop.group[0] == 2 and backdrop.contype[0] == 0 and backdrop.conaffinity[0] == 0
    assert model.mesh_texcoordnum[backdrop.dataid[0]] > 0 and model.mat_texid[backdrop.matid[0]].max() >= 0
    for g in range(model.ngeom):  # every textured geom is visual only
        if model.geom_matid[g] >= 0 and model.mat_texid[model.geom_matid[g]].max() >= 0 and model.geom(g).name != "floor_visual":
            assert model.geom_contype[g] == 0 and model.geom_conaffinity[g] == 0 and model.geom_group[g] == 2, model.geom(g).name
    objects = [model.geom(g).name for g in range(model.ngeom) if model.geom(g).name.endswith("_visual") and model.geom(g).name.startswith("obj")]
    assert objects and all(model.geom_matid[model.geom(n).id] >= 0 for n in objects)  # scanned objects carry the captured colours
    size = sum(f.stat().st_size for f in scan.rglob("*") if f.is_file())
    assert size <= 25e6
    assert os.path.getsize(scan / "assets" / "backdrop_texture.png") < 1e6
