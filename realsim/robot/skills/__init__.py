"""The robot's skills, one module per family; each is a short :class:`~realsim.robot.motion.Motion` subclass."""

from realsim.robot.skills.articulate import ArticulationSkills
from realsim.robot.skills.basic import BasicSkills
from realsim.robot.skills.grasp import GraspSkill
from realsim.robot.skills.place import PlaceSkills
from realsim.robot.skills.push import PushSkill
from realsim.robot.skills.release import Keepout, Release

__all__ = ["ArticulationSkills", "BasicSkills", "GraspSkill", "Keepout", "PlaceSkills", "PushSkill", "Release"]
