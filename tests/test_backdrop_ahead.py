"""The backdrop begun by a thread before completion: taken only when compose reads the same inputs,
and then the very backdrop compose would build itself."""

from __future__ import annotations

import numpy as np
import pytest

from realsim.composition import backdrop_ahead
from realsim.composition.appearance import AppearanceParams
from realsim.composition.backdrop import Backdrop, BackdropParams, build_cloud_backdrop
from realsim.composition.backdrop_ahead import cloud_backdrop, cloud_layers
from realsim.scene import Scene, SupportPlane

PARAMS = BackdropParams(cloud_max_faces=4000)


def _scene(seed: int = 0) -> Scene:
    """A 2 m wall at y = 1 behind a 2 x 2 m floor at z = 0 (a support) with a box-sized cluster on it (object 1)."""
    rng = np.random.default_rng(seed)
    n = 30000
    wall = np.column_stack([rng.uniform(-1, 1, n), np.full(n, 1.0) + rng.normal(0, 0.001, n), rng.uniform(0.01, 1.5, n)])
    floor = np.column_stack([rng.uniform(-1, 1, n // 2), rng.uniform(-1, 0.9, n // 2), rng.normal(0, 0.001, n // 2)])
    box = np.column_stack([rng.uniform(-0.05, 0.05, 500), rng.uniform(-0.05, 0.05, 500), rng.uniform(0.0, 0.1, 500)])
    scene = Scene.unread(None)
    scene.points = np.vstack([wall, floor, box])
    scene.colors = np.vstack([np.where(wall[:, :1] < 0, [[0.9, 0.1, 0.1]], [[0.1, 0.1, 0.9]]), np.full((n // 2, 3), 0.5),
                              np.full((500, 3), 0.2)])
    scene.labels = np.concatenate([np.zeros(n + n // 2, np.int32), np.ones(500, np.int32)])
    square = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 0.9], [-1.0, 0.9]])
    scene.planes = [SupportPlane(1, "floor", np.array([0.0, 0.0, 1.0]), 0.0, square, np.array([0.0, -0.05]), np.array([2.0, 1.9]), 0.0, n // 2)]
    scene.capture.point_spacing = 0.005
    return scene


def _same(a: Backdrop | None, b: Backdrop | None) -> bool:
    assert a is not None and b is not None
    return np.array_equal(a.mesh.vertices, b.mesh.vertices) and np.array_equal(a.mesh.faces, b.mesh.faces) and a.texture_png == b.texture_png


def test_begun_backdrop_is_taken_and_is_the_one_built_from_the_background(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "2")  # a thread is begun only when more than one core may be used
    scene = _scene()
    backdrop_ahead.begin(scene, AppearanceParams(), PARAMS)
    begun = backdrop_ahead._begun[0]
    layers = cloud_layers(scene, AppearanceParams(), PARAMS)
    got = cloud_backdrop(layers.backdrop)
    assert got is begun.result and not backdrop_ahead._begun  # the thread's work, taken once
    background = (scene.labels <= 0) & (scene.points[:, 2] > 0.01)  # neither the object nor the floor's top
    whole = build_cloud_backdrop(scene.points, scene.colors, background, 0.005, layers.backdrop.viewpoint, PARAMS)
    assert _same(got, whole)
    assert np.abs(got.mesh.vertices[:, 1] - 1.0).max() < 0.01  # the wall only
    assert [t[0].id for t in layers.tops] == [1] and len(layers.tops[0][2]) == len(scene.points) - 30000 - 500


def test_what_changed_after_begin_is_built_again(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    scene = _scene()
    backdrop_ahead.begin(scene, AppearanceParams(), PARAMS)
    begun = backdrop_ahead._begun[0]
    scene.labels[:15000] = 2  # completion took half of the wall as an object
    layers = cloud_layers(scene, AppearanceParams(), PARAMS)
    got = cloud_backdrop(layers.backdrop)
    begun.join()
    assert got is not begun.result and not _same(got, begun.result)
    assert _same(got, layers.backdrop.build())
    assert len(layers.backdrop.points) == 15000


def test_other_parameters_one_core_or_an_organized_view_begin_nothing_usable(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    scene = _scene()
    backdrop_ahead.begin(scene, AppearanceParams(), PARAMS)
    layers = cloud_layers(scene, AppearanceParams(), BackdropParams(cloud_max_faces=2000))
    assert len(cloud_backdrop(layers.backdrop).mesh.faces) <= 2000  # built for these parameters
    monkeypatch.setenv("REALSIM_WORKERS", "1")
    backdrop_ahead.begin(scene, AppearanceParams(), PARAMS)
    assert not backdrop_ahead._begun
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    scene.grid_shape = (100, 450)
    backdrop_ahead.begin(scene, AppearanceParams(), PARAMS)
    assert not backdrop_ahead._begun
