"""``robot``: the Panda placed where it reaches the work and attached (:mod:`realsim.robot_stage`)."""

from realsim.robot_stage import RobotStageParams, robot_scene
from realsim.stages.base import Stage

STAGE = Stage("robot", robot_scene, RobotStageParams, needs=("spec",))
