"""The writer's compile check: a written folder compiles from the files its XML names (handed to
MuJoCo with the XML) to the model ``from_xml_path`` gives; a missing file fails."""

from __future__ import annotations

import warnings
from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh

from realsim.robot.model import attach_robot
from realsim.scene_format import verify_compiles


def _folder(root: Path, mesh_file: str = "box.stl") -> Path:
    """scene.xml with a free box mesh from ``assets/box.stl`` (``mesh_file`` as the XML names it)."""
    root.mkdir(parents=True, exist_ok=True)
    (root / "assets").mkdir(exist_ok=True)
    (root / "assets" / "box.stl").write_bytes(trimesh.exchange.stl.export_stl(trimesh.creation.box([0.1, 0.2, 0.3])))
    (root / "scene.xml").write_text(
        f'<mujoco><compiler meshdir="assets"/><asset><mesh name="box" file="{mesh_file}"/></asset>'
        '<worldbody><body><freejoint/><geom type="mesh" mesh="box"/></body></worldbody></mujoco>')
    return root / "scene.xml"


def _same(a: mujoco.MjModel, b: mujoco.MjModel) -> bool:
    fields = ("mesh_vert", "mesh_face", "body_mass", "body_inertia", "geom_pos", "geom_size", "qpos0")
    return all(np.array_equal(getattr(a, f), getattr(b, f)) for f in fields)


def test_written_folder_compiles_to_the_same_model(tmp_path):
    xml = _folder(tmp_path / "out")
    model = verify_compiles(xml)
    assert _same(model, mujoco.MjModel.from_xml_path(str(xml)))
    assert model.body_mass[1] == pytest.approx(1000 * 0.1 * 0.2 * 0.3)


def test_files_are_read_where_from_xml_path_reads_them(tmp_path):
    """A name reaching outside assets/ reads that file (not assets/ one of the same base name);
    two different files of one base name, or a missing file, behave as from_xml_path."""
    outside = _folder(tmp_path / "out", mesh_file="../../box.stl")
    (tmp_path / "box.stl").write_bytes(trimesh.exchange.stl.export_stl(trimesh.creation.box([0.2, 0.2, 0.2])))
    model = verify_compiles(outside)
    assert model.body_mass[1] == pytest.approx(1000 * 0.2**3)
    assert _same(model, mujoco.MjModel.from_xml_path(str(outside)))
    clash = _folder(tmp_path / "clash")
    text = clash.read_text().replace('<mesh name="box" file="box.stl"/>',
                                     '<mesh name="box" file="box.stl"/><mesh name="other" file="../../box.stl"/>')
    clash.write_text(text.replace("</body>", '<geom type="mesh" mesh="other"/></body>'))
    assert _same(verify_compiles(clash), mujoco.MjModel.from_xml_path(str(clash)))
    with pytest.raises(ValueError):
        verify_compiles(_folder(tmp_path / "missing", mesh_file="nothing.stl"))


def test_attached_panda_writes_and_verifies(tmp_path):
    """The Panda attached to a scene spec (meshes resolved from the scene's meshdir) is written as
    scene.xml + assets/ and the folder compiles to the spec's robot."""
    spec = mujoco.MjSpec()
    spec.meshdir = "assets"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        handles = attach_robot(spec, (0.1, -0.2, 0.5), base_z=0.0, pedestal_height=0.3)
        compiled = spec.compile()
        (tmp_path / "assets").mkdir()
        for name, data in handles.assets.items():
            (tmp_path / "assets" / name).write_bytes(data)
        (tmp_path / "scene.xml").write_text(spec.to_xml())
    model = verify_compiles(tmp_path / "scene.xml")
    assert model.nmesh == compiled.nmesh > 0 and model.nbody == compiled.nbody
    assert np.array_equal(model.mesh_vert, compiled.mesh_vert)
    assert _same(model, mujoco.MjModel.from_xml_path(str(tmp_path / "scene.xml")))


def test_the_spec_written_from_names_the_files_without_parsing_again(tmp_path, monkeypatch):
    """Given the spec the XML was written from, the check reads the files it names (no second parse of
    the XML) and compiles the same model, byte for byte."""
    spec = mujoco.MjSpec()
    spec.meshdir = "assets"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        handles = attach_robot(spec, (0.1, -0.2, 0.5), base_z=0.0)
        (tmp_path / "assets").mkdir()
        for name, data in handles.assets.items():
            (tmp_path / "assets" / name).write_bytes(data)
        (tmp_path / "scene.xml").write_text(spec.to_xml())
    parsed = verify_compiles(tmp_path / "scene.xml")
    parses: list[str] = []
    real = mujoco.MjSpec.from_string
    monkeypatch.setattr(mujoco.MjSpec, "from_string", staticmethod(lambda text, *a, **k: parses.append(text) or real(text, *a, **k)))
    given = verify_compiles(tmp_path / "scene.xml", written_from=spec)
    assert parses == []

    def mjb(model: mujoco.MjModel) -> bytes:
        buffer = np.empty(mujoco.mj_sizeModel(model), np.uint8)
        mujoco.mj_saveModel(model, None, buffer)
        return buffer.tobytes()

    assert mjb(given) == mjb(parsed)
