"""The Franka Panda: model attachment, base placement, IK, grasping and motion primitives."""

from realsim.robot.grasps import GraspCandidate, grasp_candidates
from realsim.robot.ik import ArmIK, IKParams, IKResult
from realsim.robot.model import GripperParams, RobotHandles, attach_robot, menagerie_panda_dir
from realsim.robot.optimizer import EpsilonGreedy, GraspParams
from realsim.robot.placement import PlacementParams, add_robot, choose_robot_pose
from realsim.robot.robot import ActionResult, Robot, RobotParams

__all__ = [
    "ActionResult", "ArmIK", "EpsilonGreedy", "GraspCandidate", "GraspParams", "GripperParams", "IKParams", "IKResult",
    "PlacementParams", "Robot", "RobotHandles", "RobotParams", "add_robot", "attach_robot", "choose_robot_pose",
    "grasp_candidates", "menagerie_panda_dir",
]
