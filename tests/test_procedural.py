"""Procedural families: watertight, sized inside the size table, resting, containers holding a ball, sites."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from realsim.physics import estimate_manifest
from realsim.physics.sim_checks import ball_in_container_test, drop_test
from realsim.procedural import generate, get_backend, register_backend, size_range
from realsim.procedural.families import CONTAINERS, FAMILIES
from realsim.procedural.generate import kind_for
from realsim.procedural.prepare import prepare_part

# one label per family (the family comes from the label through the size table)
FAMILY_LABELS = {
    "mug": "coffee mug", "cup": "cup", "glass": "wine glass", "bowl": "salad bowl", "plate": "plate", "vase": "flower pot",
    "pan": "frying pan", "pot": "cooking pot", "kettle": "kettle", "teapot": "teapot", "tray": "serving tray", "basket": "basket",
    "crate": "crate", "bin": "trash bin", "bottle": "water bottle", "can": "soda can", "jar": "jar", "cylinder": "candle",
    "box": "phone", "upright_box": "cereal box", "book": "book", "cutting_board": "cutting board", "lamp": "desk lamp",
    "fruit": "apple", "banana": "banana", "carrot": "carrot", "pen": "marker", "ball": "tennis ball", "knife": "kitchen knife",
    "fork": "fork", "spoon": "spoon", "hammer": "hammer", "screwdriver": "screwdriver", "wrench": "wrench",
    "drawer_cabinet": "drawer cabinet", "hinged_box": "hinged box", "laptop": "laptop",
}
SITES = {"mug": {"handle", "rim"}, "pan": {"handle", "rim"}, "pot": {"handle", "handle_2", "rim"}, "kettle": {"handle", "lid", "spout"},
         "teapot": {"handle", "lid", "spout"}, "knife": {"handle"}, "hammer": {"handle"}, "cutting_board": {"handle"}, "jar": {"lid"},
         "bottle": {"lid"}, "basket": {"rim"}, "crate": {"handle", "rim"}, "laptop": {"hinge"}, "hinged_box": {"hinge"}, "lamp": {"stem"}}


def test_at_least_25_families_each_labelled() -> None:
    assert len(FAMILIES) >= 25 and set(FAMILY_LABELS) == set(FAMILIES)
    for family, label in FAMILY_LABELS.items():
        assert kind_for(label) == family, label


@pytest.mark.parametrize("family", sorted(FAMILY_LABELS))
def test_family_rests_and_fits_the_table(family: str) -> None:
    label = FAMILY_LABELS[family]
    gen = generate(label, np.random.default_rng(1))
    lo, _, hi = size_range(label)
    for part in gen.parts:
        assert part.mesh.is_watertight and part.mesh.volume > 0, part.label
        assert np.allclose(part.mesh.bounds[0][2], 0.0, atol=1e-6)
    if family not in ("drawer_cabinet", "hinged_box"):  # scaled to tabletop pieces
        assert lo <= max(gen.dims) <= hi * 1.02, (label, gen.dims)
    assert SITES.get(family, set()) <= set(gen.parts[0].sites), gen.parts[0].sites
    prep = prepare_part(gen.parts[0])
    rest = drop_test(prep, estimate_manifest(prep), settle_s=1.5)
    assert rest["finite"] and rest["drift"] < 0.002 and rest["sinking"] < 0.002, rest
    if family in CONTAINERS or family in ("drawer_cabinet", "hinged_box"):
        cont = prepare_part(gen.parts[1]) if family == "drawer_cabinet" else prep
        ball = ball_in_container_test(cont, radius=0.015)
        assert ball["cavity_found"] and ball["inside"], ball


def test_seeded_sized_and_articulated() -> None:
    a = generate("bowl", np.random.default_rng(3)).parts[0].mesh
    b = generate("bowl", np.random.default_rng(3)).parts[0].mesh
    assert np.array_equal(a.vertices, b.vertices)
    small = generate("bowl", np.random.default_rng(3), size_word="small").parts[0].mesh
    large = generate("bowl", np.random.default_rng(3), size_word="large").parts[0].mesh
    assert max(small.extents) < max(a.extents) < max(large.extents)
    drawer = generate("drawer cabinet", np.random.default_rng(0))
    assert drawer.joint is not None and drawer.joint.type == "slide" and drawer.joint.range[1] > 0.1 and drawer.joint.handle is not None
    laptop = generate("laptop", np.random.default_rng(0))
    assert laptop.joint is not None and laptop.joint.type == "hinge" and laptop.joint.handle is not None


def test_measured_dims_clamped_and_noted() -> None:
    gen = generate("mug", np.random.default_rng(0), dims=(0.5, 0.3, 0.3))
    assert max(gen.dims) <= size_range("mug")[2] * 1.01 and gen.notes


def test_text_to_3d_registry_off_by_default(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("REALSIM_TEXT_TO_3D", raising=False)
    assert get_backend() is None

    class Fake:
        name = "fake"

        def generate(self, label: str, description: str, dest: Path, seed: int) -> Path:
            return dest / f"{label}.obj"

    register_backend("fake", Fake)
    assert get_backend("fake").name == "fake"
