"""Object assets: loading, normalization, decomposition fidelity, cache, MuJoCo behaviour."""

from __future__ import annotations

import time
from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh

from realsim.assets import AssetParams, PreparedObject, label_from_path, load_object_mesh, prepare_object, prepare_objects
from realsim.assets.fidelity import surface_distances, volume_iou
from realsim.cache import DiskCache
from realsim.errors import InputError
from realsim.physics import estimate_manifest
from realsim.physics.sim_checks import ball_in_container_test, drop_test

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "ycb_google16k"
SUBSET = ["025_mug", "024_bowl", "035_power_drill", "037_scissors", "003_cracker_box", "012_strawberry"]
OFFICIAL_MASS = {"cracker_box": 0.411, "power_drill": 0.895}

pytestmark = pytest.mark.skipif(not DATA.is_dir(), reason="YCB data not available")


@pytest.fixture(scope="module")
def cache_dir(tmp_path_factory, monkeypatch_module=None):
    d = tmp_path_factory.mktemp("realsim_cache")
    import os

    old = os.environ.get("REALSIM_CACHE")
    os.environ["REALSIM_CACHE"] = str(d)
    yield d
    if old is None:
        os.environ.pop("REALSIM_CACHE", None)
    else:
        os.environ["REALSIM_CACHE"] = old


@pytest.fixture(scope="module")
def prepared(cache_dir) -> dict[str, PreparedObject]:
    paths = [DATA / n / "textured.obj" for n in SUBSET]
    objs = prepare_objects(paths, [None] * len(paths), AssetParams(), DiskCache(cache_dir), progress=False)
    return {o.label: o for o in objs}


def test_labels():
    assert label_from_path(Path("025_mug/textured.obj")) == "mug"
    assert label_from_path(Path("x/cracker_box.glb")) == "cracker_box"
    assert label_from_path(Path("003_cracker_box/google_16k/textured.obj")) == "cracker_box"
    assert label_from_path(Path("objs/019_pitcher_base/model.stl")) == "pitcher_base"
    assert label_from_path(Path("Coffee Mug.ply")) == "coffee_mug"


def test_bad_inputs_raise_input_error(tmp_path):
    empty = tmp_path / "empty.obj"
    empty.write_bytes(b"")
    with pytest.raises(InputError, match="empty"):
        load_object_mesh(empty)
    junk = tmp_path / "junk.obj"
    junk.write_text("this is not\nan obj file\n")
    with pytest.raises(InputError, match="no triangles|could not be read"):
        load_object_mesh(junk)
    bad_stl = tmp_path / "bad.stl"
    bad_stl.write_bytes(b"\x00\x01garbage" * 10)
    with pytest.raises(InputError):
        load_object_mesh(bad_stl)
    with pytest.raises(InputError, match="unsupported"):
        load_object_mesh(tmp_path / "x.fbx") if (tmp_path / "x.fbx").write_text("x") else None
    with pytest.raises(InputError, match="does not exist"):
        load_object_mesh(tmp_path / "missing.obj")
    pts_only = tmp_path / "points.ply"
    trimesh.PointCloud(np.random.default_rng(0).random((50, 3))).export(pts_only)
    with pytest.raises(InputError):
        prepare_object(pts_only, cache=DiskCache(enabled=False))


def test_formats_and_gltf_up_axis(tmp_path):
    box = trimesh.creation.box([0.05, 0.10, 0.20])  # tall along z
    yup = box.copy()
    yup.apply_transform(trimesh.transformations.rotation_matrix(-np.pi / 2, [1, 0, 0]))  # z-up -> y-up
    yup.export(tmp_path / "block.glb")
    box.export(tmp_path / "block.stl")
    box.export(tmp_path / "block.ply")
    box.export(tmp_path / "block.obj")
    for ext in ("glb", "stl", "ply", "obj"):
        m, label = load_object_mesh(tmp_path / f"block.{ext}")
        assert label == "block"
        assert np.allclose(np.sort(m.extents), [0.05, 0.10, 0.20], atol=1e-6)
        assert m.extents[2] == pytest.approx(0.20, abs=1e-6), ext


def test_shells_merged_degenerate_faces_dropped(tmp_path):
    a = trimesh.creation.box([0.04, 0.04, 0.04])
    b = trimesh.creation.box([0.04, 0.04, 0.04])
    b.apply_translation([0.02, 0, 0])  # overlaps a: union is 0.06 x 0.04 x 0.04
    c = trimesh.creation.box([0.02, 0.02, 0.02])
    c.apply_translation([0.0, 0.08, 0])  # separate shell of the same object
    mesh = trimesh.util.concatenate([a, b, c])
    faces = np.vstack([mesh.faces, mesh.faces[:5], [[0, 0, 1], [2, 2, 2]]])  # duplicates + degenerate
    trimesh.Trimesh(mesh.vertices, faces, process=False).export(tmp_path / "toy_block.obj")
    p = prepare_object(tmp_path / "toy_block.obj", cache=DiskCache(enabled=False))
    assert p.volume == pytest.approx(0.06 * 0.04 * 0.04 + 0.02**3, rel=1e-3)
    assert p.solid.is_watertight
    lo, hi = p.visual.bounds
    assert lo[2] == pytest.approx(0, abs=1e-9) and (lo[:2] + hi[:2]) == pytest.approx([0, 0], abs=1e-9)
    assert len(p.hulls) >= 2  # the two pieces are not one convex body


@pytest.mark.parametrize("factor", [1000.0, 0.01])
def test_implausible_scale_is_rescaled_with_warning(tmp_path, factor):
    mesh, _ = load_object_mesh(DATA / "012_strawberry" / "textured.obj")
    ref = trimesh.Trimesh(mesh.vertices, mesh.faces).extents
    scaled = trimesh.Trimesh(mesh.vertices * factor, mesh.faces)
    path = tmp_path / f"strawberry_{int(factor * 100)}.stl"
    scaled.export(path)
    p = prepare_object(path, label="strawberry", cache=DiskCache(enabled=False))
    assert p.scale_applied == pytest.approx(1 / factor)
    assert np.allclose(np.sort(p.size), np.sort(ref), rtol=1e-3)
    assert any("implausible" in w and "rescaled" in w for w in p.warnings)


def test_real_scale_kept(prepared):
    for p in prepared.values():
        assert p.scale_applied == 1.0 and not any("rescaled" in w for w in p.warnings)


def test_hulls_valid_for_mujoco(prepared):
    for p in prepared.values():
        assert p.hulls
        spec = mujoco.MjSpec()
        body = spec.worldbody.add_body()
        for i, h in enumerate(p.hulls):
            assert len(h.vertices) >= 4 and h.volume > 0 and h.is_convex
            m = spec.add_mesh()
            m.name = f"h{i}"
            m.uservert = h.vertices.ravel().tolist()
            m.userface = h.faces.ravel().tolist()
            g = body.add_geom()
            g.type = mujoco.mjtGeom.mjGEOM_MESH
            g.meshname = f"h{i}"
        spec.compile()


def test_fidelity(prepared):
    for p in prepared.values():
        a, b = surface_distances(p.hulls, p.solid, n=8000, dense=120000)
        assert np.percentile(a, 95) <= 0.004, p.label
        assert np.percentile(b, 95) <= 0.004, p.label
        if not p.open_container:
            assert volume_iou(p.hulls, p.solid) >= 0.85, p.label


def test_convex_object_needs_no_coacd(prepared):
    assert prepared["strawberry"].decomposition["method"] == "single_hull"
    assert len(prepared["strawberry"].hulls) == 1


@pytest.mark.parametrize("label", ["mug", "bowl"])
def test_container_keeps_cavity(prepared, label):
    p = prepared[label]
    assert p.open_cavity
    r = ball_in_container_test(p)
    assert r["cavity_found"] and r["inside"], r


def test_drop_rests_upright(prepared):
    for p in prepared.values():
        d = drop_test(p, estimate_manifest(p), height=0.02)
        assert d["finite"], p.label
        assert d["sinking"] <= 0.002, (p.label, d)
        assert d["drift"] <= 0.005, (p.label, d)
        assert d["tilt_deg"] < 10, (p.label, d)


def test_mass_estimates(prepared):
    for label, ref in OFFICIAL_MASS.items():
        m = estimate_manifest(prepared[label]).mass_kg
        assert abs(m - ref) / ref <= 0.3, (label, m, ref)


def test_visuals_kept():
    p = prepare_object(DATA / "011_banana" / "textured.obj", cache=DiskCache(enabled=False))
    assert p.texture_png is not None and p.texture_png[:8] == b"\x89PNG\r\n\x1a\n"
    assert p.visual.visual.uv is not None and len(p.visual.visual.uv) == len(p.visual.vertices)
    assert len(p.rgba) == 4


def test_colour_is_what_the_file_records(prepared, tmp_path):
    """The banana's texture gives yellow; the bowl's MTL names a texture that is missing, so its
    colour is unknown (None), not the loader's grey; an MTL Kd is a recorded colour."""
    banana = prepare_object(DATA / "011_banana" / "textured.obj", cache=DiskCache(enabled=False))
    assert banana.color is not None and banana.color[0] > 0.5 and banana.color[1] > 0.5 and banana.color[2] < 0.3
    assert prepared["bowl"].color is None
    (tmp_path / "red.mtl").write_text("newmtl m\nKd 0.8 0.1 0.1\n")
    box = trimesh.creation.box((0.05, 0.05, 0.05))
    lines = ["mtllib red.mtl", "usemtl m", *(f"v {x} {y} {z}" for x, y, z in box.vertices), *(f"f {a + 1} {b + 1} {c + 1}" for a, b, c in box.faces)]
    (tmp_path / "red_block.obj").write_text("\n".join(lines) + "\n")
    red = prepare_object(tmp_path / "red_block.obj", cache=DiskCache(enabled=False))
    assert red.color is not None and np.allclose(red.color, (0.8, 0.1, 0.1), atol=0.01)


def test_warm_cache_fast_and_deterministic(prepared, cache_dir):
    paths = [DATA / n / "textured.obj" for n in SUBSET]
    t = time.perf_counter()
    again = prepare_objects(paths, [None] * len(paths), AssetParams(), DiskCache(cache_dir), progress=False)
    assert time.perf_counter() - t < 2.0
    for o in again:
        assert o.decomposition["cache_hit"]
        ref = prepared[o.label]
        assert len(o.hulls) == len(ref.hulls)
        assert all(np.array_equal(h.vertices, r.vertices) for h, r in zip(o.hulls, ref.hulls))
