"""A captured object that settling moves away from where it was seen is reported."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from realsim.composition.settle import settle_scene
from realsim.scene import Scene, SceneObject


def _scene(heights: dict[str, float], captured: bool) -> Scene:
    """Boxes 5 cm a side over a floor, their bodies' origins at their base centres."""
    spec = mujoco.MjSpec()
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[2, 2, 0.1])
    scene = Scene.unread(None)
    for i, (name, z) in enumerate(heights.items()):
        body = spec.worldbody.add_body(name=name, pos=[0.3 * i, 0.0, z])
        body.add_freejoint()
        body.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.025, 0.025, 0.025], pos=[0, 0, 0.025], mass=0.1)
        scene.objects.append(SceneObject(id=i + 1, name=name, label="box", position=np.array([0.3 * i, 0.0, z]),
                                         quat=np.array([1.0, 0, 0, 0]), size=np.full(3, 0.05)))
    scene.spec = spec
    scene.labels = np.zeros(10, dtype=np.int32) if captured else None
    return scene


@pytest.mark.parametrize("captured", [True, False])
def test_an_object_seen_in_mid_air_falls_and_is_reported_only_for_captures(captured: bool) -> None:
    scene = settle_scene(_scene({"obj1_resting": 0.0, "obj2_floating": 0.3}, captured))
    moved = scene.settle_report["moved_during_settling"]
    assert moved["obj1_resting"] < 0.002 and moved["obj2_floating"] == pytest.approx(0.3, abs=0.01)
    reports = [w for w in scene.warnings if "while settling" in w]
    if captured:
        assert len(reports) == 1 and "obj2_floating 300 mm" in reports[0] and "obj1_resting" not in reports[0]
    else:
        assert reports == []  # a generated object's place was the generator's, not a capture's
