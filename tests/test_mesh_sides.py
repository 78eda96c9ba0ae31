"""Which side of a captured mesh's faces is outside (realsim.perception.mesh_sides): a mesh written
with every face turned over converts as the same scene."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import trimesh

from realsim.perception.mesh_sides import is_turned, with_outward_faces
from realsim.pipeline import run_pipeline
from realsim.synth import SceneSpec, make_scene, write_mesh
from realsim.synth.scene import ycb_root

UP = np.array([0.0, 0.0, 1.0])


def _turned(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """Every face wound the other way (a fresh mesh: Trimesh.invert keeps cached normals)."""
    out = mesh.copy()
    out.faces = np.ascontiguousarray(out.faces[:, ::-1])
    return out


def _open_scan() -> trimesh.Trimesh:
    """A scanner's single-sided skin: a floor and a table top with its edges, no undersides."""
    floor = trimesh.creation.box((3.0, 3.0, 0.05))
    floor.apply_translation((0.0, 0.0, -0.025))
    table = trimesh.creation.box((1.0, 0.6, 0.04))
    table.apply_translation((0.0, 0.0, 0.72))
    parts = [trimesh.Trimesh(m.vertices, m.faces[m.face_normals[:, 2] > -0.9]) for m in (floor, table)]
    return trimesh.util.concatenate(parts)


def test_closed_bodies_read_by_their_volume() -> None:
    boxes = trimesh.util.concatenate([trimesh.creation.box((0.1, 0.1, 0.1)), trimesh.creation.icosphere(radius=0.03)])
    assert not is_turned(boxes, UP, 1.0)
    assert is_turned(_turned(boxes), UP, 1.0)


def test_open_skin_read_by_its_lowest_level_surface() -> None:
    scan = _open_scan()
    assert not is_turned(scan, UP, 1.0)
    inward = _turned(scan)
    assert is_turned(inward, UP, 1.0)
    outward, was = with_outward_faces(inward, UP, 1.0)
    assert was and np.allclose(outward.face_normals, scan.face_normals)


def test_inconsistent_winding_is_left_alone() -> None:
    box = trimesh.creation.box((1.0, 1.0, 1.0))
    faces = box.faces.copy()
    faces[0] = faces[0, ::-1]
    odd = trimesh.Trimesh(box.vertices, faces, process=False)
    assert odd is with_outward_faces(odd, UP, 1.0)[0]


@pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")
def test_mesh_with_every_face_turned_converts_as_the_same_scene(tmp_path: Path) -> None:
    gt = make_scene(SceneSpec(layout="table", objects=("003_cracker_box", "005_tomato_soup_can", "025_mug"), seed=0))
    write_mesh(gt, tmp_path / "room.glb")
    _turned(trimesh.load(tmp_path / "room.glb", force="mesh")).export(tmp_path / "turned.glb")
    pipeline = tmp_path / "detect.yaml"
    pipeline.write_text("name: detect\nstages:\n  - load\n  - planes\n  - segment\n")
    plain, turned = (run_pipeline(tmp_path / name, pipeline=pipeline) for name in ("room.glb", "turned.glb"))
    assert turned.capture.faces_turned and not plain.capture.faces_turned
    assert len(turned.objects) == len(plain.objects) == len(gt.objects)
    tables = [[round(p.height, 4) for p in s.planes if p.kind != "floor"] for s in (plain, turned)]
    assert tables[0] == tables[1] and len(tables[0]) == 1
    assert json.dumps(turned.capture.faces_turned) == "true"
