"""Object meshes as people export them: GLB Y-up in millimetres with vertex colours, PLY in
centimetres, an open (non-watertight) STL in metres; all come out upright, at their true size."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import trimesh

from realsim.pipeline import convert


def test_object_meshes_in_any_unit_and_up_axis(tmp_path: Path) -> None:
    objects = tmp_path / "capture" / "objects"
    objects.mkdir(parents=True)
    can = trimesh.creation.cylinder(radius=40, height=95, sections=48)  # mm, Z up ...
    can.apply_transform(trimesh.transformations.rotation_matrix(-np.pi / 2, [1, 0, 0]))  # ... written Y up
    can.visual.vertex_colors = np.tile([200, 30, 30, 255], (len(can.vertices), 1))
    can.export(objects / "red_can.glb")
    box = trimesh.creation.box(extents=(20, 7, 28))  # cm
    box.export(objects / "cereal_box.ply")
    banana = trimesh.creation.capsule(radius=0.018, height=0.15)
    banana.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, [0, 1, 0]))
    banana.update_faces(np.arange(len(banana.faces)) % 37 != 0)  # a scan with holes
    assert not banana.is_watertight
    banana.export(objects / "banana.stl")
    scene = convert(tmp_path / "capture", tmp_path / "out", overrides={"robot": {"enabled": False}})
    sizes = {o.label: np.sort(o.size) * 1000 for o in scene.objects}
    np.testing.assert_allclose(sizes["red_can"], [80, 80, 95], atol=2)
    assert abs(next(o for o in scene.objects if o.label == "red_can").size[2] * 1000 - 95) < 2  # upright
    np.testing.assert_allclose(sizes["cereal_box"], [70, 200, 280], atol=2)
    np.testing.assert_allclose(sizes["banana"], [36, 36, 186], atol=3)
    model = mujoco.MjModel.from_xml_path(str(tmp_path / "out" / "scene.xml"))
    red = next(o.name for o in scene.objects if o.label == "red_can")
    assert model.geom(f"{red}_visual").rgba[0] > 0.7 > model.geom(f"{red}_visual").rgba[2] + 0.5  # its vertex colours
    assert any("millimetres" in w for w in scene.warnings) and any("centimetres" in w for w in scene.warnings)


def test_painted_vertices_become_a_texture(tmp_path: Path) -> None:
    from realsim.composition.atlas import baked_colours

    box = trimesh.creation.box(extents=(0.06, 0.06, 0.1)).subdivide().subdivide()
    top = box.vertices[:, 2] > 0
    box.visual.vertex_colors = np.where(top[:, None], [230, 20, 20, 255], [20, 20, 230, 255]).astype(np.uint8)
    baked = baked_colours(box)
    assert baked is not None
    mesh, png = baked
    from io import BytesIO

    from PIL import Image

    image = np.asarray(Image.open(BytesIO(png)).convert("RGB"))
    uv = np.asarray(mesh.visual.uv)[::3]
    shown = image[((1 - uv[:, 1]) * image.shape[0]).astype(int), (uv[:, 0] * image.shape[1]).astype(int)]
    high = mesh.triangles_center[:, 2] > 0.02
    low = mesh.triangles_center[:, 2] < -0.02
    assert (shown[high, 0] > 200).all() and (shown[low, 2] > 200).all()
    plain = trimesh.creation.box(extents=(0.06, 0.06, 0.1))
    plain.visual.vertex_colors = [200, 30, 30, 255]
    assert baked_colours(plain) is None  # one colour: a material colour says it


def test_a_textured_object_is_named_by_its_texture_colour() -> None:
    from io import BytesIO

    from PIL import Image

    from realsim.composition.atlas import surface_colour
    from realsim.planner.vocab import color_name

    mesh = trimesh.creation.box(extents=(0.1, 0.1, 0.1))
    texture = np.zeros((8, 8, 3), np.uint8)
    texture[:, :] = (200, 170, 20)  # banana yellow ...
    texture[:, :1] = (20, 20, 200)  # ... with a thin blue stripe no face samples
    buf = BytesIO()
    Image.fromarray(texture).save(buf, format="PNG")
    mesh.visual = trimesh.visual.TextureVisuals(uv=np.full((len(mesh.vertices), 2), 0.6))
    rgb = surface_colour(mesh, buf.getvalue())
    assert rgb is not None and color_name(rgb) == "yellow"
    assert color_name((0.77, 0.65, 0.07)) == "yellow" and color_name((0.4, 0.4, 0.4)) == "gray" and color_name(None) is None
