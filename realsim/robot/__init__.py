"""The Franka Panda: model attachment, base placement, IK, grasping and motion primitives.

Layers: :mod:`~realsim.robot.arm` (handles, stepping, time budget), :mod:`~realsim.robot.queries`
(world queries), :mod:`~realsim.robot.motion` (lines, transits, collision checks), the skill
families in :mod:`realsim.robot.skills`, composed into :class:`Robot`; numbers in
:mod:`~realsim.robot.params`.
"""

from realsim.robot.grasps import GraspCandidate, grasp_candidates
from realsim.robot.ik import ArmIK, IKParams, IKResult
from realsim.robot.model import GripperParams, RobotHandles, attach_robot, menagerie_panda_dir
from realsim.robot.optimizer import EpsilonGreedy, GraspParams
from realsim.robot.params import ArmParams, ArticulationParams, MotionParams, PickParams, PlaceParams, PushParams, RobotParams
from realsim.robot.result import ActionResult, BudgetExceeded, PlanFailure
from realsim.robot.robot import Robot

__all__ = [
    "ActionResult", "ArmIK", "ArmParams", "ArticulationParams", "BudgetExceeded", "EpsilonGreedy", "GraspCandidate",
    "GraspParams", "GripperParams", "IKParams", "IKResult", "MotionParams", "PickParams", "PlaceParams",
    "PlanFailure", "PushParams", "Robot", "RobotHandles", "RobotParams", "attach_robot",
    "grasp_candidates", "menagerie_panda_dir",
]
