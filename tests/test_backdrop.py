"""The backdrop of unorganized captures: ball-pivoted, coloured per face, visual only, within budget."""

from __future__ import annotations

from io import BytesIO
from pathlib import Path

import mujoco
import numpy as np
import pytest
from PIL import Image

from realsim.composition.atlas import face_colour_atlas
from realsim.composition.backdrop import BackdropParams, build_cloud_backdrop
from realsim.pipeline import convert
from realsim.synth import SceneSpec, make_scene, write_point_cloud
from realsim.synth.scene import ycb_root


def _wall(n: int = 60000, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """A 2 x 1.5 m wall at y = 1 (red left half, blue right half) and a floor patch at z = 0."""
    rng = np.random.default_rng(seed)
    wall = np.column_stack([rng.uniform(-1, 1, n), np.full(n, 1.0) + rng.normal(0, 0.001, n), rng.uniform(0, 1.5, n)])
    colors = np.where(wall[:, :1] < 0, [[0.9, 0.1, 0.1]], [[0.1, 0.1, 0.9]])
    floor = np.column_stack([rng.uniform(-1, 1, n // 4), rng.uniform(-1, 1, n // 4), np.zeros(n // 4)])
    return np.vstack([wall, floor]), np.vstack([colors, np.full((n // 4, 3), 0.5)])


def _face_colours(mesh, png: bytes) -> np.ndarray:
    image = np.asarray(Image.open(BytesIO(png)).convert("RGB"), float) / 255
    uv = np.asarray(mesh.visual.uv)[mesh.faces[:, 0]]
    h, w = image.shape[:2]
    return image[((1 - uv[:, 1]) * h).astype(int), (uv[:, 0] * w).astype(int)]


def test_wall_is_meshed_where_it_was_seen_in_its_colours() -> None:
    points, colors = _wall()
    keep = points[:, 2] > 0.01  # the floor is a support: not backdrop
    params = BackdropParams(cloud_max_faces=6000)
    backdrop = build_cloud_backdrop(points, colors, keep, 0.005, np.array([0.0, 0.0, 1.2]), params)
    assert backdrop is not None
    mesh = backdrop.mesh
    assert 1000 < len(mesh.faces) <= params.cloud_max_faces
    assert np.abs(mesh.vertices[:, 1] - 1.0).max() < 0.01 and mesh.vertices[:, 2].min() > 0.0  # on the wall, no floor
    assert (mesh.face_normals[:, 1] < 0).mean() > 0.95  # facing the viewer in front of the wall
    shown = _face_colours(mesh, backdrop.texture_png)
    left = mesh.triangles_center[:, 0] < -0.05
    right = mesh.triangles_center[:, 0] > 0.05
    assert (shown[left, 0] > 0.7).mean() > 0.95 and (shown[right, 2] > 0.7).mean() > 0.95
    again = build_cloud_backdrop(points, colors, keep, 0.005, np.array([0.0, 0.0, 1.2]), params)
    assert again is not None and np.array_equal(again.mesh.vertices, mesh.vertices) and again.texture_png == backdrop.texture_png


def test_atlas_gives_every_face_its_colour() -> None:
    rng = np.random.default_rng(1)
    vertices = rng.uniform(0, 1, (30, 3))
    faces = rng.integers(0, 30, (37, 3))
    rgb = rng.uniform(0, 1, (37, 3))
    mesh, png = face_colour_atlas(vertices, faces, rgb)
    np.testing.assert_allclose(_face_colours(mesh, png), rgb, atol=1 / 255 + 1e-9)
    np.testing.assert_allclose(mesh.vertices.reshape(-1, 3, 3), vertices[faces])


def test_too_little_to_show_gives_no_backdrop() -> None:
    points, colors = _wall(200)
    assert build_cloud_backdrop(points, colors, np.zeros(len(points), bool), 0.005, np.zeros(3)) is None


@pytest.mark.skipif(not ycb_root().is_dir(), reason="needs ../shared/data/ycb_google16k")
def test_unorganized_scan_gets_a_visual_only_backdrop(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A visual-only backdrop, textured support tops and objects coloured from the points; the same
    files when forked helpers make the tops' textures and the rest check (a second conversion from
    scratch with two workers; the suite runs with one)."""
    scene = make_scene(SceneSpec(layout="table", objects=("077_rubiks_cube",), seed=0))
    cloud = tmp_path / "cloud.ply"
    write_point_cloud(scene, cloud, count=200_000, seed=0)
    convert(cloud, tmp_path / "out", overrides={"robot": {"enabled": False}})
    monkeypatch.setenv("REALSIM_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    convert(cloud, tmp_path / "forked", overrides={"robot": {"enabled": False}})
    for name in ["scene.xml", *(f"assets/{f.name}" for f in (tmp_path / "out" / "assets").iterdir())]:
        assert (tmp_path / "out" / name).read_bytes() == (tmp_path / "forked" / name).read_bytes(), name
    model = mujoco.MjModel.from_xml_path(str(tmp_path / "out" / "scene.xml"))
    backdrop = model.geom("backdrop_visual")
    assert backdrop.group[0] == 2 and backdrop.contype[0] == 0 and backdrop.conaffinity[0] == 0
    assert model.mat_texid[backdrop.matid[0]].max() >= 0
    tops = [g for g in range(model.ngeom) if model.geom(g).name.startswith("support") and model.geom(g).name.endswith("_top_visual")]
    assert tops and all(model.mat_texid[model.geom_matid[g]].max() >= 0 and model.geom_contype[g] == 0 for g in tops)
    visuals = [g for g in range(model.ngeom) if model.geom(g).name.startswith("obj") and model.geom(g).name.endswith("_visual")]
    assert visuals and all(model.mat_texid[model.geom_matid[g]].max() >= 0 for g in visuals)  # coloured from the points


def test_object_faces_take_the_colour_of_their_points() -> None:
    import trimesh

    from realsim.composition.appearance import AppearanceParams, colour_object_from_points
    from realsim.scene import SceneObject

    box = trimesh.creation.box(extents=(0.1, 0.1, 0.1))
    box.apply_translation([0.0, 0.0, 0.05])  # object frame: origin at the base centre
    rng = np.random.default_rng(2)
    points = rng.uniform(-0.05, 0.05, (4000, 3))
    points[:, 2] = 0.1  # only the top was seen: red on the left, green on the right
    colors = np.where(points[:, :1] < 0, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    obj = SceneObject(id=1, name="obj1_box", label="box", position=np.zeros(3), quat=np.array([1.0, 0, 0, 0]), size=np.full(3, 0.1), visual=box)
    assert colour_object_from_points(obj, points, colors, np.ones(len(points), int), AppearanceParams())
    shown = _face_colours(obj.visual, obj.texture_png)
    centres = obj.visual.triangles_center
    far_left, far_right = centres[:, 0] < -0.03, centres[:, 0] > 0.03
    assert (shown[far_left, 0] > 0.9).all() and (shown[far_right, 1] > 0.9).all()  # the unseen sides continue the seen top


def test_support_top_is_seen_from_above() -> None:
    from realsim.composition.appearance import support_top, top_view_texture
    from realsim.composition.layout import declared_support

    plane = declared_support(None)  # 1.2 x 0.8 m at 0.75 m, centred at the origin
    rng = np.random.default_rng(3)
    xy = rng.uniform([-0.6, -0.4], [0.6, 0.4], (20000, 2))
    rgb = np.where(xy[:, :1] < 0, [[0.9, 0.1, 0.1]], [[0.1, 0.1, 0.9]])
    keep = np.linalg.norm(xy - [0.3, 0.0], axis=1) > 0.1  # an object hid a disc of the blue half
    top = support_top(plane, 0.03, 0.0005)
    png, uv = top_view_texture(plane, top, xy[keep], rgb[keep])
    image = np.asarray(Image.open(BytesIO(png)).convert("RGB"), float) / 255
    assert uv.min() >= 0 and uv.max() <= 1
    h, w = image.shape[:2]
    assert image[:, : w // 2 - 2, 0].min() > 0.8 and image[:, w // 2 + 2:, 2].min() > 0.8  # the hidden disc filled from around it
    left = np.asarray(top.vertices)[:, 0] < -0.1
    assert (uv[left, 0] < 0.5).all() and (uv[~left & (np.asarray(top.vertices)[:, 0] > 0.1), 0] > 0.5).all()


def test_support_top_follows_the_captured_surface() -> None:
    """A table seen sagging (a slow dip of 8 mm, with 2 mm noise) gets a textured top at the heights
    the camera saw, within a few mm (the flat plane is 8 mm off at the dip); under an object, where
    nothing of the table was seen, the nearest seen height continues."""
    from realsim.composition.appearance import CaptureImage, follow_captured_surface, support_top
    from realsim.composition.layout import declared_support
    from realsim.perception.intrinsics import Intrinsics

    plane = declared_support(None)  # 1.2 x 0.8 m at 0.75 m, centred at the origin
    rng = np.random.default_rng(5)
    h, w = 200, 300
    x, y = np.meshgrid(np.linspace(-0.6, 0.6, w), np.linspace(-0.4, 0.4, h))

    def sag(px: np.ndarray, py: np.ndarray) -> np.ndarray:
        return -0.008 * np.exp(-((px - 0.2) ** 2 + py**2) / (2 * 0.15**2))

    z = plane.height + sag(x, y) + rng.normal(0.0, 0.002, x.shape)
    world = np.stack([x, y, z], axis=-1)
    mask = np.hypot(x + 0.3, y) > 0.08  # an object hid a disc of the table
    image = CaptureImage(np.zeros((h, w, 3), np.uint8), np.zeros((h, w), int), world, Intrinsics(300.0, 300.0, 150.0, 100.0, w, h), np.eye(4))
    flat = support_top(plane, 0.03, 0.0005)
    top = follow_captured_surface(flat, plane, image, mask, 0.0005)
    v = np.asarray(top.vertices)
    truth = plane.height + sag(v[:, 0], v[:, 1]) + 0.0005
    assert np.abs(np.asarray(flat.vertices)[:, 2] - truth).max() > 0.0075
    assert np.abs(v[:, 2] - truth).max() < 0.003
    assert np.array_equal(np.asarray(top.faces), np.asarray(flat.faces))
    none = follow_captured_surface(flat, plane, image, np.zeros((h, w), bool), 0.0005)
    assert np.array_equal(np.asarray(none.vertices), np.asarray(flat.vertices))  # nothing seen: the plane
