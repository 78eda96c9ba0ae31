"""Size tables, lookup, MuJoCo parameter mapping and the offline manifest estimator."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from realsim.assets import prepare_object
from realsim.assets.geometry import shell_inertia_unit, solid_inertia_unit
from realsim.cache import DiskCache
from realsim.physics import ObjectManifest, estimate_manifest, lookup, material, solref_from_restitution
from realsim.physics.size_table import load_materials, load_objects


def test_tables_complete():
    objs, mats = load_objects(), load_materials()
    assert len(objs) >= 80
    for name, c in objs.items():
        assert c.material in mats, name
        assert c.size[0] <= c.size[1] <= c.size[2], name
        assert c.mass[0] <= c.mass[1] <= c.mass[2], name
    for name, m in mats.items():
        assert m.density > 0 and len(m.friction) == 3 and 0 <= m.restitution <= 1 and m.source, name


@pytest.mark.parametrize("query,expected", [
    ("Mugs", "mug"), ("coffee_mug", "mug"), ("025_mug", "mug"), ("Cereal Boxes", "cracker_box"),
    ("pitcher_base", "pitcher"), ("large_marker", "marker"), ("tomatoe soup can", "can"), ("knives", "knife"),
    ("strawberries", "strawberry"), ("Rubik's Cube", "rubiks_cube"), ("red coffee mug", "mug"), ("Power-Drill", "power_drill"),
])
def test_lookup_tolerant(query, expected):
    m = lookup(query)
    assert m is not None and m.category.name == expected


def test_lookup_unknown():
    assert lookup("xyzzy") is None


def test_solref_from_restitution():
    assert solref_from_restitution(0.0)[1] == 1.0
    ratios = [solref_from_restitution(e)[1] for e in (0.1, 0.3, 0.6, 0.9)]
    assert all(a > b for a, b in zip(ratios, ratios[1:]))


def test_shell_inertia_larger_than_solid():
    box = trimesh.creation.box([0.1, 0.1, 0.1])
    _, Is = solid_inertia_unit(box)
    _, Ih = shell_inertia_unit(box)
    assert Is[0, 0] == pytest.approx(0.1**2 / 6, rel=1e-6)
    assert Ih[0, 0] == pytest.approx(5 * 0.1**2 / 18, rel=1e-6)  # thin-walled cube


def _prep(tmp_path, mesh, name):
    path = tmp_path / f"{name}.stl"
    mesh.export(path)
    return prepare_object(path, cache=DiskCache(enabled=False))


def test_manifest_solid_and_container(tmp_path):
    block = _prep(tmp_path, trimesh.creation.box([0.05, 0.05, 0.05]), "wooden_block")
    m = estimate_manifest(block)
    assert isinstance(m, ObjectManifest)
    assert m.category == "toy_block" and m.material_class == "wood"
    assert m.mass_kg == pytest.approx(650 * 0.05**3, rel=1e-3)
    assert m.sources["mass_kg"] == "geometry" and m.sources["friction"] == "table"
    assert m.is_graspable and m.is_pushable and m.joint_type == "free"
    assert m.friction == material("wood").friction
    # a closed cardboard box: shell + contents, shell-aware inertia
    box = _prep(tmp_path, trimesh.creation.box([0.16, 0.07, 0.21]), "cereal_box")
    mb = estimate_manifest(box)
    assert 0.3 < mb.mass_kg < 0.6
    assert box.inertia_model == "shell+contents"
    ObjectManifest.model_validate(mb.model_dump())


def test_manifest_articulated_and_unknown(tmp_path):
    cab = _prep(tmp_path, trimesh.creation.box([0.8, 0.5, 0.9]), "kitchen_cabinet")
    m = estimate_manifest(cab)
    assert m.joint_type == "hinge" and m.joint_axis == (0.0, 0.0, 1.0) and m.is_openable and not m.is_graspable
    unk = _prep(tmp_path, trimesh.creation.icosphere(radius=0.03), "zorblax")
    mu = estimate_manifest(unk)
    assert mu.category is None and mu.sources["mass_kg"] == "fallback"
    assert np.all(np.linalg.eigvalsh(np.array([[mu.inertia[0], mu.inertia[3], mu.inertia[4]], [mu.inertia[3], mu.inertia[1], mu.inertia[5]], [mu.inertia[4], mu.inertia[5], mu.inertia[2]]])) > 0)
