"""realsim.synth: YCB scenes on tables, counters and floors, every capture form, ground truth."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import trimesh

from realsim.synth import SceneSpec, make_scene, sample_cloud, write_all, write_point_cloud
from realsim.synth.scene import ycb_root

pytestmark = pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")

OBJECTS = ("003_cracker_box", "005_tomato_soup_can", "025_mug", "077_rubiks_cube")


@pytest.fixture(scope="module")
def scene():
    return make_scene(SceneSpec(layout="table", objects=OBJECTS, seed=3))


def _gap_over(top: trimesh.Trimesh, below: trimesh.Trimesh) -> float:
    """The smallest height of ``top``'s vertices over ``below``'s surface straight under them (ray cast)."""
    import open3d as o3d

    from realsim.synth.meshes import raycaster

    rays = np.zeros((len(top.vertices), 6), np.float32)
    rays[:, :2], rays[:, 2], rays[:, 5] = top.vertices[:, :2], below.bounds[1, 2] + 1.0, -1.0
    t = raycaster(below).cast_rays(o3d.core.Tensor(rays))["t_hit"].numpy()
    hit = np.isfinite(t)
    return float(np.min(top.vertices[hit, 2] - (below.bounds[1, 2] + 1.0 - t[hit])))


def test_objects_rest_on_the_table_stacked_and_touching(scene) -> None:
    table = scene.primary_support()
    assert 0.70 <= table.height <= 0.78
    assert [o.id for o in scene.objects] == [1, 2, 3, 4]
    stacked = [o for o in scene.objects if o.resting_on is not None]
    assert len(stacked) == 1
    touching = [o for o in scene.objects if o.touching]
    assert len(touching) == 2
    meshes = {o.id: o.mesh() for o in scene.objects}
    for o in scene.objects:
        low = meshes[o.id].bounds[0, 2]
        if o.resting_on is None:
            assert abs(low - table.height) < 0.002  # on the table, not in it
        else:  # on the surface of the object below (a bulged or tilted top is lower than its highest point)
            assert abs(_gap_over(meshes[o.id], meshes[o.resting_on])) < 0.0005
    a, b = touching
    assert _distance(meshes[a.id], meshes[b.id]) < 0.004
    related = {(o.id, o.resting_on) for o in scene.objects} | {(a.id, b.id)}
    for o in scene.objects:  # every other pair is apart
        for p in scene.objects:
            if o.id < p.id and (o.id, p.id) not in related and (p.id, o.id) not in related:
                assert _distance(meshes[o.id], meshes[p.id]) > 0.01


def _distance(a: trimesh.Trimesh, b: trimesh.Trimesh) -> float:
    import open3d as o3d

    rc = o3d.t.geometry.RaycastingScene()
    rc.add_triangles(o3d.core.Tensor(a.vertices.astype(np.float32)), o3d.core.Tensor(a.faces.astype(np.uint32)))
    return float(rc.compute_distance(o3d.core.Tensor(b.vertices.astype(np.float32))).numpy().min())


def test_deterministic(scene) -> None:
    again = make_scene(SceneSpec(layout="table", objects=OBJECTS, seed=3))
    for a, b in zip(scene.objects, again.objects):
        assert np.array_equal(a.pose, b.pose)


def test_cloud_units_and_labels(scene, tmp_path: Path) -> None:
    pts, cols, ids = sample_cloud(scene, 50_000, seed=0, noise=0.0)
    assert pts.shape == (50_000, 3) and cols.shape == (50_000, 3)
    # labels agree with the nearest-face ground truth
    assert (scene.label_points(pts[:5000]) == ids[:5000]).mean() > 0.99
    assert set(np.unique(ids)) == {0, 1, 2, 3, 4}
    entry, _ = write_point_cloud(scene, tmp_path / "c.ply", 20_000, units="mm", up="+y")
    cloud = trimesh.load(tmp_path / "c.ply")
    back = np.asarray(cloud.vertices) @ np.asarray(entry["capture_to_world"])[:3, :3].T
    assert abs(np.percentile(back[:, 2], 99.5) - 0.9) < 0.4  # Y-up millimetres back to Z-up metres
    assert np.ptp(np.asarray(cloud.vertices)[:, 1]) > 500  # millimetres along Y


@pytest.mark.parametrize("layout", ["counter", "floor"])
def test_layouts(layout: str) -> None:
    s = make_scene(SceneSpec(layout=layout, n_objects=3, seed=1))
    sup = s.primary_support()
    assert sup.height == (0.0 if layout == "floor" else sup.height) and len(s.objects) == 3
    for o in s.objects:
        if o.resting_on is None:
            assert abs(o.mesh().bounds[0, 2] - sup.height) < 0.002


def test_write_all_forms(scene, tmp_path: Path) -> None:
    dest = write_all(scene, tmp_path / "cap", cloud_points=30_000, frames=3)
    gt = json.loads((dest / "ground_truth.json").read_text())
    assert [f["form"] for f in gt["forms"]] == ["organized_view", "rgbd_sequence", "point_cloud", "mesh"]
    assert len(list((dest / "sequence" / "depth").glob("*.png"))) == 3
    assert (dest / "sequence" / "odometry.csv").read_text().count("\n") == 4
    from realsim.perception.pcd_io import read_pcd

    view = read_pcd(dest / "view.pcd")
    assert view.grid_shape == (480, 640)
    assert {10, 20, 30, 40} <= set(np.unique(view.labels).tolist())
    mesh = trimesh.load(dest / "mesh.glb", force="mesh")
    assert mesh.extents.max() > 1000  # millimetres
    assert len(np.load(dest / "cloud_labels.npy")) == 30_000
