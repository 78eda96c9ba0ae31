"""``robot``: the Panda placed where it reaches the work and attached (:mod:`realsim.composition.robot_mount`),
reading the objects from the model compose compiled."""

from realsim.composition.compiled import handed_model
from realsim.composition.robot_mount import RobotStageParams, robot_scene
from realsim.scene import Scene
from realsim.stages.base import Stage


def robot(scene: Scene, params: RobotStageParams) -> Scene:
    """:func:`robot_scene` on the model the stage before compiled (if it did)."""
    return robot_scene(scene, params, handed_model(scene))


STAGE = Stage("robot", robot, RobotStageParams, needs=("spec",))
