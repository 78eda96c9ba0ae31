"""``robot``: the Panda placed where it reaches the work and attached (:mod:`realsim.composition.robot_mount`)."""

from realsim.composition.robot_mount import RobotStageParams, robot_scene
from realsim.stages.base import Stage

STAGE = Stage("robot", robot_scene, RobotStageParams, needs=("spec",))
