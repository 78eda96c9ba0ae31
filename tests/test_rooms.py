"""The generator's rooms layout (realsim.synth.rooms): several tables at different heights, objects on
each; and detection on it: every table found level at its height, objects on all of them."""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pytest

from realsim.geometry import inside_convex_polygon
from realsim.synth import SceneSpec, make_scene
from realsim.synth.scene import ycb_root

pytestmark = pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")


def _digest(seed: int) -> str:
    scene = make_scene(SceneSpec(layout="rooms", seed=seed))
    h = hashlib.sha256()
    for a in (scene.mesh.vertices, scene.mesh.faces, scene.face_object, scene.face_part):
        h.update(np.ascontiguousarray(a).tobytes())
    return h.hexdigest()


@pytest.mark.parametrize("seed", [0, 1, 2, 7])
def test_rooms_hold_tables_apart_in_height_and_place_objects_on_each(seed: int) -> None:
    scene = make_scene(SceneSpec(layout="rooms", seed=seed))
    tables = [s for s in scene.supports if s.kind != "floor"]
    assert scene.supports[0].kind == "floor" and 2 <= len(tables) <= 3
    assert scene.primary_support() is tables[0]
    heights = sorted(t.height for t in tables)
    assert min(np.diff(heights)) >= 0.05 and all(0.05 <= abs(t.height - tables[0].height) <= 0.40 for t in tables[1:])
    for t in tables[1:]:
        apart = np.linalg.norm(np.subtract(t.center, tables[0].center))
        assert 0.3 <= apart <= 2.5
    on = {t.name: [o for o in scene.objects if o.support == t.name] for t in tables}
    assert all(on.values()), on  # objects on every table
    assert [o.id for o in scene.objects] == list(range(1, len(scene.objects) + 1))
    for obj in scene.objects:
        table = next(t for t in tables if t.name == obj.support)
        verts = obj.mesh().vertices
        rect = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]]) * np.divide(table.size, 2) + table.center
        assert inside_convex_polygon(verts[:, :2], rect, 1e-6).all()
        if obj.resting_on is None:  # standing on the table top: touching it, no gap
            assert abs(verts[:, 2].min() - table.height) < 1e-6
        else:
            assert scene.objects[obj.resting_on - 1].support == obj.support
    for obj_id, count in zip(*np.unique(scene.face_object, return_counts=True)):
        assert obj_id == 0 or count > 0


def test_rooms_are_seeded() -> None:
    assert _digest(3) == _digest(3)
    assert _digest(3) != _digest(4)


@pytest.fixture(scope="module")
def detected(tmp_path_factory: pytest.TempPathFactory):
    """A 200k-point cloud of a rooms scene (tables at three heights), converted by load, planes and segment."""
    from realsim.pipeline import run_pipeline
    from realsim.synth import write_point_cloud

    tmp = tmp_path_factory.mktemp("rooms")
    gt = make_scene(SceneSpec(layout="rooms", seed=SEED))
    entry, ids = write_point_cloud(gt, tmp / "rooms.ply", 200_000)
    (tmp / "detect.yaml").write_text("name: detect\nstages:\n  - load\n  - planes\n  - segment\n")
    scene = run_pipeline(tmp / "rooms.ply", pipeline=tmp / "detect.yaml")
    to_gt = np.asarray(entry["capture_to_world"]) @ np.linalg.inv(scene.capture.input_to_world)
    return gt, scene, to_gt, ids


SEED = 2  # three tables: 0.71, 0.58 and 0.87 m


def test_every_table_found_level_at_its_height(detected) -> None:
    gt, scene, to_gt, _ = detected
    for table in gt.supports[1:]:
        found = []
        for p in scene.planes:
            if not p.observed:
                continue
            centre = to_gt @ np.r_[p.rect_center, p.height, 1.0]
            inside = inside_convex_polygon(centre[None, :2], np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]]) * np.divide(table.size, 2) + table.center, 0.05)[0]
            if inside:
                normal = to_gt[:3, :3] @ p.normal
                found.append((abs(centre[2] - table.height), float(np.degrees(np.arccos(abs(normal[2]) / np.linalg.norm(normal))))))
        assert found, f"{table.name} at {table.height} m not found"
        err, tilt = min(found)
        assert err < 0.003 and tilt < 0.3, (table.name, err, tilt)


def test_objects_on_every_table_found(detected) -> None:
    from realsim.metrics import matched_iou

    gt, scene, _, ids = detected
    ious, _ = matched_iou(scene.labels, ids)
    assert len(scene.objects) == len(gt.objects)
    assert float(np.min(ious)) >= 0.5
    assert {o.support for o in gt.objects} == {t.name for t in gt.supports[1:]}


def test_rooms_example_writes_every_form(tmp_path: Path) -> None:
    from realsim.synth import write_all

    dest = write_all(make_scene(SceneSpec(layout="rooms", seed=1)), tmp_path / "rooms", frames=3, cloud_points=20_000)
    import json

    truth = json.loads((dest / "ground_truth.json").read_text())
    assert [s["name"] for s in truth["supports"]][:2] == ["floor", "table"] and len(truth["supports"]) >= 3
    assert {f["form"] for f in truth["forms"]} == {"organized_view", "rgbd_sequence", "point_cloud", "mesh"}


def test_primary_support_of_a_floorless_scene() -> None:
    """Without its floor (a table-top scan), a scene still names the table its objects stand on."""
    from realsim.synth.exports import without_floor

    for layout in ("table", "counter", "rooms"):
        scene = without_floor(make_scene(SceneSpec(layout=layout, seed=1, n_objects=3)))
        assert scene.primary_support().name == ("table" if layout == "rooms" else layout)


@pytest.mark.parametrize("seed", [3, 81])
def test_a_camera_view_keeps_a_lower_table_beside_the_main_one(seed: int, tmp_path: Path) -> None:
    """A table 10-30 cm lower than the main one and beside it (not under it) is a support of its own:
    it was dropped as noise under the largest support."""
    from realsim.pipeline import run_pipeline
    from realsim.synth import write_organized_view

    gt = make_scene(SceneSpec(layout="rooms", seed=seed))
    entry = write_organized_view(gt, tmp_path / "view.pcd")
    (tmp_path / "detect.yaml").write_text("name: detect\nstages:\n  - load\n  - planes\n")
    scene = run_pipeline(tmp_path / "view.pcd", pipeline=tmp_path / "detect.yaml")
    to_gt = np.asarray(entry["capture_to_world"]) @ np.linalg.inv(scene.capture.input_to_world)
    heights = [float((to_gt @ np.r_[p.rect_center, p.height, 1.0])[2]) for p in scene.planes if p.observed]
    main = gt.supports[1].height
    lower = [t for t in gt.supports[1:] if 0.05 <= main - t.height <= 0.25]
    assert lower, "the layout was meant to hold a lower table"
    for table in lower:
        assert min(abs(h - table.height) for h in heights) < 0.005, (table.name, table.height, heights)
