"""Compose's object mesh files begun ahead are taken only when nothing they read has changed."""

from __future__ import annotations

import sys

import numpy as np
import pytest
import trimesh

from realsim.composition import object_meshes
from realsim.composition.appearance import AppearanceParams
from realsim.composition.object_meshes import begin, collision_file
from realsim.composition.object_meshes import object_meshes as meshes_of
from realsim.forkmap import can_fork
from realsim.scene import Scene, SceneObject

NO_PHOTO = AppearanceParams(enabled=False)


@pytest.fixture(autouse=True)
def _two_workers(monkeypatch: pytest.MonkeyPatch) -> None:
    """The suite runs with one worker per process (tests/conftest.py): these tests allow the fork."""
    monkeypatch.setenv("REALSIM_WORKERS", "2")


def _scene(n: int = 4) -> Scene:
    scene = Scene.unread(None)
    rng = np.random.default_rng(5)
    for k in range(n):
        hull = trimesh.convex.convex_hull(rng.normal(size=(200, 3)) * 0.03)  # more than 64 vertices: capped
        scene.objects.append(SceneObject(id=k + 1, name=f"obj{k + 1}", label="object", position=np.array([0.1 * k, 0.0, 0.0]),
                                         quat=np.array([1.0, 0.0, 0.0, 0.0]), size=hull.extents, collision=[hull], visual=hull))
    return scene


def _expected(scene: Scene) -> list[list[bytes]]:
    return [[collision_file(h) for h in o.collision] for o in scene.objects]


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="begin forks on Linux only")
def test_begun_work_is_taken_when_unchanged() -> None:
    assert can_fork()
    scene = _scene()
    begin(scene, NO_PHOTO)
    ahead = object_meshes._begun[-1][3]
    with meshes_of(scene, None, NO_PHOTO) as taken:
        assert taken is ahead
        assert [stl for _, stl in taken.results()] == _expected(scene)


@pytest.mark.parametrize("change", ["mesh", "appearance", "scene"])
def test_begun_work_is_dropped_when_anything_it_read_changed(change: str) -> None:
    scene = _scene()
    begin(scene, NO_PHOTO)
    appearance = NO_PHOTO
    if change == "mesh":
        scene.objects[2].collision = [trimesh.creation.box((0.05, 0.06, 0.07))]
    elif change == "appearance":
        appearance = AppearanceParams(enabled=False, margin_px=NO_PHOTO.margin_px + 1)
    else:
        scene = _scene()
    with meshes_of(scene, None, appearance) as ahead:
        assert [stl for _, stl in ahead.results()] == _expected(scene)
    assert not object_meshes._begun
