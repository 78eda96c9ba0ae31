"""Described scenes laid out as said: stacks, contents in cavities, supports, relations; all at rest."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from realsim.composition.layout import hull_pieces, rest_height
from realsim.composition.settle import rest_check
from realsim.pipeline import run_pipeline
from realsim.procedural import generate

NO_ROBOT = {"robot": {"enabled": False}}


def _settled(text: str, seed: int = 0):
    """The scene, its objects' world bounds at keyframe 'initial', and the rest check."""
    scene = run_pipeline(None, seed=seed, overrides={"load": {"text": text}, **NO_ROBOT})
    spec = scene.spec.copy()
    spec.memory = -1
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
    mujoco.mj_forward(model, data)
    bounds = {}
    for o in scene.objects:
        b = model.body(o.name).id
        pts = np.vstack([h.vertices for h in o.collision]) @ data.xmat[b].reshape(3, 3).T + data.xpos[b]
        bounds[o.name] = (pts.min(axis=0), pts.max(axis=0))
    assert rest_check(model, 2.0)["max_displacement"] <= 0.005
    return scene, bounds


def _named(scene, label: str) -> list[str]:
    return [o.name for o in scene.objects if o.label == label]


def test_rest_height_is_exact_on_a_box() -> None:
    box = [np.array([[x, y, z] for x in (-0.1, 0.1) for y in (-0.1, 0.1) for z in (0.7, 0.75)])]
    cube = [np.array([[x, y, z] for x in (-0.02, 0.02) for y in (-0.02, 0.02) for z in (0.0, 0.04)])]
    assert rest_height(cube, box, np.array([0.05, 0.0]), 0.3) == pytest.approx(0.75)
    assert rest_height(cube, box, np.array([0.5, 0.0]), 0.0) is None
    assert len(hull_pieces(cube)) == 1


def test_stack_and_things_on_top() -> None:
    scene, b = _settled("a stack of three books on the desk and a mug on top of the books")
    books = sorted(_named(scene, "book"), key=lambda n: b[n][0][2])
    assert len(books) == 3
    for lower, upper in zip(books, books[1:]):
        assert b[upper][0][2] == pytest.approx(b[lower][1][2], abs=0.004)  # resting on the one below
    mug = _named(scene, "mug")[0]
    assert b[mug][0][2] == pytest.approx(b[books[-1]][1][2], abs=0.004)


def test_contents_inside_the_cavity_and_floor_beside_the_table() -> None:
    scene, b = _settled("a bowl with two apples in it on the table, and a basket of oranges on the floor", seed=2)
    bowl, basket = _named(scene, "bowl")[0], _named(scene, "basket")[0]
    for name, container in [(n, bowl) for n in _named(scene, "apple")] + [(n, basket) for n in _named(scene, "orange")]:
        lo, hi = b[name]
        clo, chi = b[container]
        centre = (lo + hi)[:2] / 2
        assert np.all(centre > clo[:2]) and np.all(centre < chi[:2]) and lo[2] < chi[2] - 0.005, name  # in, below the rim
    assert len(_named(scene, "orange")) == 3
    assert b[basket][0][2] == pytest.approx(0.0, abs=0.005) and b[bowl][0][2] == pytest.approx(0.75, abs=0.005)


def test_relations_kept() -> None:
    scene, b = _settled("a laptop on the desk, a lamp behind it, a mug to the right of the laptop and a book to the left of it", seed=3)
    c = {o.label: (b[o.name][0] + b[o.name][1]) / 2 for o in scene.objects if o.label != "laptop lid"}
    assert c["lamp"][1] > c["laptop"][1] and c["mug"][0] > c["laptop"][0] and c["book"][0] < c["laptop"][0]


def test_row_and_grasp_sites() -> None:
    scene, b = _settled("four cans in a row on the shelf and a frying pan on the counter", seed=4)
    cans = _named(scene, "can")
    ys = [(b[n][0][1] + b[n][1][1]) / 2 for n in cans]
    assert len(cans) == 4 and np.ptp(ys) < 0.01  # one line
    model = scene.spec.compile()
    pan = _named(scene, "frying pan")[0]
    assert model.site(f"{pan}_handle").bodyid[0] == model.body(pan).id and model.site(f"{pan}_rim") is not None
    shelf = next(p for p in scene.planes if p.kind == "shelf")
    assert all(b[n][0][2] == pytest.approx(shelf.height, abs=0.005) for n in cans)


def test_container_grows_for_its_contents() -> None:
    scene, b = _settled("some bananas in a bowl", seed=8)
    bowl = _named(scene, "bowl")[0]
    assert max(b[bowl][1][:2] - b[bowl][0][:2]) > max(generate("bowl", np.random.default_rng(0)).dims)


def test_where_on_the_support_and_what_does_not_fit() -> None:
    """"a hammer on the left, a mug on the right": sides of the support; a thing larger than its support is left out
    with a warning while the rest is built."""
    scene, bounds = _settled("a rack on the counter, a hammer on the left and a mug on the right")
    assert _named(scene, "rack") == [] and any("rack" in w and "left out" in w for w in scene.warnings)
    (hammer,), (mug,) = _named(scene, "hammer"), _named(scene, "mug")
    assert (bounds[hammer][0][0] + bounds[hammer][1][0]) / 2 < (bounds[mug][0][0] + bounds[mug][1][0]) / 2 - 0.2
