"""The robot stage's compiled model handed to settle: the very model compiling the spec again gives."""

from __future__ import annotations

from realsim.cache import model_digest
from realsim.composition.compiled import handed_model
from realsim.composition.compose import compose_scene
from realsim.robot.model import attach_robot
from tests.test_robot import box_object, table_scene


def test_attach_robot_model_is_the_spec_compiled_again() -> None:
    scene = compose_scene(table_scene([box_object(1, "box_a", (0.1, 0.05), (0.05, 0.05, 0.06))]))
    handles = attach_robot(scene.spec, (-0.75, 0.0, 0.0), base_z=0.0, pedestal_height=0.5)
    assert handles.model.key("home").id >= 0
    assert model_digest(handles.model) == model_digest(scene.spec.compile())  # the home keyframe included


def test_a_held_model_serves_only_its_own_spec_and_once() -> None:
    scene = compose_scene(table_scene([box_object(1, "box_a", (0.1, 0.05), (0.05, 0.05, 0.06))]))
    held = scene.compiled[1]
    assert scene.compiled[0] is scene.spec
    assert handed_model(scene) is held and scene.compiled is None
    assert handed_model(scene) is None  # taken once
    other = compose_scene(table_scene([]))
    scene.compiled = (other.spec, held)
    assert handed_model(scene) is None and scene.compiled is None  # another spec's model is never used
