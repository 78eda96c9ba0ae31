"""Procedural CSG objects: watertight, sized inside the size table, concave where they should be."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from realsim.assets import AssetParams, prepare_object
from realsim.cache import DiskCache
from realsim.physics.sim_checks import ball_in_container_test
from realsim.procedural import generate, get_backend, register_backend, size_range, write_ply

LABELS = ["mug", "bowl", "plate", "cup", "bottle", "soda can", "cereal box", "book", "jar", "tray", "trash bin", "toy dinosaur"]


@pytest.mark.parametrize("label", LABELS)
def test_generated_shape_in_table_range(label: str) -> None:
    for seed in range(3):
        gen = generate(label, np.random.default_rng(seed))
        mesh = gen.parts[0].mesh
        assert mesh.is_watertight and mesh.volume > 0
        lo, _, hi = size_range(label)
        assert lo <= max(mesh.extents) <= hi, (label, mesh.extents)
        assert np.allclose(mesh.bounds[0][2], 0.0) and np.allclose(mesh.bounds.mean(axis=0)[:2], 0.0, atol=1e-6)


def test_seeded_and_sized() -> None:
    a = generate("bowl", np.random.default_rng(3)).parts[0].mesh
    b = generate("bowl", np.random.default_rng(3)).parts[0].mesh
    assert np.array_equal(a.vertices, b.vertices)
    small = generate("bowl", np.random.default_rng(3), size_word="small").parts[0].mesh
    large = generate("bowl", np.random.default_rng(3), size_word="large").parts[0].mesh
    assert max(small.extents) < max(a.extents) < max(large.extents)


def test_articulated_parts() -> None:
    gen = generate("drawer cabinet", np.random.default_rng(0))
    assert gen.kind == "drawer_cabinet" and len(gen.parts) == 2
    assert gen.joint is not None and gen.joint.type == "slide" and gen.joint.range[1] > 0.1
    lid = generate("hinged box", np.random.default_rng(0))
    assert lid.joint is not None and lid.joint.type == "hinge"


@pytest.mark.parametrize("label", ["mug", "bowl"])
def test_container_concave_in_simulation(label: str, tmp_path: Path) -> None:
    gen = generate(label, np.random.default_rng(0))
    path = write_ply(gen.parts[0].mesh, gen.parts[0].color, tmp_path / f"{label}.ply")
    prep = prepare_object(path, label, AssetParams(), DiskCache())
    assert len(prep.hulls) > 1
    result = ball_in_container_test(prep, radius=0.02)
    assert result["cavity_found"] and result["inside"], result


def test_text_to_3d_registry_off_by_default(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("REALSIM_TEXT_TO_3D", raising=False)
    assert get_backend() is None

    class Fake:
        name = "fake"

        def generate(self, label: str, description: str, dest: Path, seed: int) -> Path:
            return dest / f"{label}.obj"

    register_backend("fake", Fake)
    assert get_backend("fake").name == "fake"
