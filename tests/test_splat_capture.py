"""A 3D Gaussian splat as a capture: generated with ground truth (realsim.synth.splat), converted
from its centres, and shown by the viewer in the converted scene's world frame."""

from __future__ import annotations

import json
import socket
from pathlib import Path

import numpy as np
import pytest

from realsim import cli
from realsim.perception.capture import load_capture
from realsim.synth import SceneSpec, make_scene, write_splat
from realsim.synth.scene import ycb_root
from realsim.viewer.splat import find_splat, read_splat_ply

pytestmark = pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")
OBJECTS = ("003_cracker_box", "077_rubiks_cube", "005_tomato_soup_can", "025_mug")
COUNT = 40_000


@pytest.fixture(scope="module")
def gt():
    return make_scene(SceneSpec(layout="table", objects=OBJECTS, seed=0, stacked=False))


@pytest.fixture(scope="module")
def splat(gt, tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict, np.ndarray]:
    folder = tmp_path_factory.mktemp("splat-capture")
    entry, ids = write_splat(gt, folder / "scan.ply", COUNT, units="cm", up="+y")
    return folder / "scan.ply", entry, ids


def test_written_splats_lie_flat_in_their_surface(gt, splat) -> None:
    path, entry, ids = splat
    s = read_splat_ply(path, entry["capture_to_world"])
    surface = ids >= 0
    assert entry["floaters"] == (~surface).sum() > 0
    # the thin axis of every surface splat is its face normal: variance across it 1 % of along it
    across = np.linalg.eigvalsh(s.covariances[surface].astype(np.float64))
    assert np.allclose(across[:, 0] / across[:, 2], 0.01, rtol=1e-3)
    assert (s.opacities[surface, 0] >= 0.6).all() and (s.opacities[~surface, 0] < 0.2).all()
    # centres (in metres after the transform back) lie on the labelled objects' surfaces
    on_objects = ids > 0
    assert np.mean(gt.label_points(s.centers[on_objects].astype(np.float64)) == ids[on_objects]) > 0.95


def test_splat_loads_as_its_surface_in_any_units(splat) -> None:
    path, _, ids = splat
    scene = load_capture(path)
    assert len(scene.points) == (ids >= 0).sum()  # the faint floaters are dropped
    assert scene.capture.units == "cm" and scene.capture.up == "+y"
    assert scene.capture.splat == path
    assert np.allclose(scene.colors.mean(axis=0), read_splat_ply(path).rgbs[ids >= 0].mean(axis=0), atol=1e-3)


def test_converted_splat_finds_objects_and_viewer_shows_the_splat(gt, splat, tmp_path: Path) -> None:
    path, entry, ids = splat
    out = tmp_path / "out"
    assert cli.main(["convert", str(path), "-o", str(out), "-q"]) == 0
    scene_json = json.loads((out / "scene.json").read_text())
    assert len(scene_json["objects"]) == len(OBJECTS)
    assert find_splat(scene_json) == path

    from realsim.viewer.server import Viewer

    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    viewer = Viewer(out, port=port, paused=True)
    try:
        assert viewer.status()["splats"] == len(ids)
        # the splat is drawn in the scene's world: the splats on the true table top are the
        # ones the viewer shows at the converted table's height
        table = max((p for p in scene_json["planes"] if p["kind"] != "floor"), key=lambda p: p["height"])
        true_z = read_splat_ply(path, entry["capture_to_world"]).centers[:, 2]
        on_true_top = (np.abs(true_z - gt.primary_support().height) < 0.01) & (ids == 0)
        on_shown_top = (np.abs(viewer.splats.centers[:, 2] - table["height"]) < 0.01) & (ids == 0)
        assert on_true_top.sum() > 1000
        assert (on_true_top & on_shown_top).sum() / (on_true_top | on_shown_top).sum() > 0.95
    finally:
        viewer.stop()
