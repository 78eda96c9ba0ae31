"""One object mesh file as the whole capture: placed on a table, like a capture's objects/."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import trimesh

from conftest import YCB
from realsim.errors import InputError
from realsim.perception.lone_object import is_lone_object
from realsim.pipeline import convert, pipeline_for


def test_an_object_mesh_alone_becomes_an_object_scene(tmp_path: Path) -> None:
    mesh = YCB / "077_rubiks_cube" / "textured.obj"
    assert is_lone_object(mesh) and pipeline_for(mesh) == "objects"
    scene = convert(mesh, tmp_path / "out", overrides={"robot": {"enabled": False}})
    record = json.loads((tmp_path / "out" / "scene.json").read_text())
    assert [o["label"] for o in record["objects"]] == ["rubiks_cube"]
    (obj,) = scene.objects
    assert 0.05 < max(obj.size) < 0.1  # the cube stays its own size


@pytest.mark.parametrize("name", ["003_cracker_box", "024_bowl", "019_pitcher_base", "035_power_drill"])
def test_object_meshes_10_to_60_cm_are_objects_not_scenes(name: str) -> None:
    """These are 0.1-0.6 m in metres: once read as tiny scenes (a box top taken for a table, or
    "no horizontal support"); a scene needs a support larger than any object."""
    assert is_lone_object(YCB / name / "textured.obj")


def test_a_closed_body_in_millimetres_is_an_object_and_a_tabletop_in_centimetres_a_scene(tmp_path: Path) -> None:
    """Both read as 1-60 cm objects in one unit and 0.6-60 m scenes in another: one closed body
    decides (a scene scan is open or made of several bodies)."""
    from realsim.synth import SceneSpec, make_scene, write_mesh

    bottle = trimesh.load(YCB / "006_mustard_bottle" / "textured.obj", force="mesh")
    bottle.apply_scale(1000.0)
    bottle.export(tmp_path / "bottle_mm.stl")
    assert is_lone_object(tmp_path / "bottle_mm.stl")
    write_mesh(make_scene(SceneSpec(layout="table", n_objects=3, seed=3)), tmp_path / "tabletop_cm.glb", units="cm", up="+y")
    assert not is_lone_object(tmp_path / "tabletop_cm.glb")
    open_top = trimesh.creation.box(extents=(0.3, 0.2, 0.1))
    open_top.update_faces(open_top.face_normals[:, 2] < 0.5)  # a tray scanned from above: open, in metres
    open_top.export(tmp_path / "tray.obj")
    assert is_lone_object(tmp_path / "tray.obj")  # 30 cm in metres: no reading makes it a scene


def test_scene_sized_or_speck_sized_meshes_are_not_objects(tmp_path: Path) -> None:
    room = trimesh.creation.box(extents=(3.0, 3.0, 0.05))
    room.export(tmp_path / "room.obj")
    assert not is_lone_object(tmp_path / "room.obj")
    table = trimesh.util.concatenate([trimesh.creation.box(extents=(0.8, 0.6, 0.04)),
                                      trimesh.creation.box(extents=(0.07, 0.07, 0.1), transform=trimesh.transformations.translation_matrix((0, 0, 0.07)))])
    table.export(tmp_path / "tabletop.obj")
    assert not is_lone_object(tmp_path / "tabletop.obj")  # 80 cm: a tabletop scan, not one object
    speck = trimesh.creation.box(extents=(1e-4, 1e-4, 1e-4))
    speck.export(tmp_path / "speck.obj")
    assert not is_lone_object(tmp_path / "speck.obj")
    with pytest.raises(InputError, match="--units"):
        convert(tmp_path / "speck.obj", tmp_path / "out")


def test_a_scene_mesh_is_read_once_for_the_object_check_and_the_sampling(tmp_path, monkeypatch) -> None:
    """Telling a lone object from a scene and sampling the scene share one read of the file."""
    import trimesh

    from realsim.perception import formats
    from realsim.perception.capture import load_capture

    room = trimesh.creation.box((3.0, 3.0, 0.05))
    room.apply_translation((0, 0, -0.025))
    table = trimesh.creation.box((1.2, 0.8, 0.75))
    table.apply_translation((0, 0, 0.375))
    path = tmp_path / "room_cm.obj"
    trimesh.util.concatenate([room, table]).apply_scale(100.0).export(path)  # centimetres: 3 mm as an object, so both checks run
    reads = []
    real_load = trimesh.load
    monkeypatch.setattr(trimesh, "load", lambda *a, **k: reads.append(a[0]) or real_load(*a, **k))
    scene = load_capture(path)
    assert scene.capture.units == "cm" and len(reads) == 1
    assert formats._read_mesh_cached.cache_info().currsize == 0  # released once the capture is loaded
