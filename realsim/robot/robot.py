"""Motion primitives of the Panda over a loaded realsim scene.

Every primitive steps the physics (simulated time only) with the position-controlled actuators
following an interpolated joint trajectory, within a ``max_sim_time`` budget, and returns an
:class:`ActionResult` whose ``success`` is measured in the simulation (contacts, poses), never
assumed. Motions lift before they traverse: transits go up to a safe height above everything,
across, and down; approaches are straight lines along the grasp axis. Every transit is checked
against the scene's objects before it runs (a kinematic MuJoCo collision check on a scratch
state), pushes too.

The layers, each a small class on top of the one before: :class:`~realsim.robot.arm.Arm`
(handles, stepping, time budget), :class:`~realsim.robot.queries.WorldQueries` (points, ray
casts, contacts), :class:`~realsim.robot.motion.Motion` (lines, transits, collision checks), and
one skill family per module of :mod:`realsim.robot.skills`. Their numbers live in
:class:`~realsim.robot.params.RobotParams`.
"""

from __future__ import annotations

from realsim.robot.params import RobotParams
from realsim.robot.result import ActionResult
from realsim.robot.skills import ArticulationSkills, BasicSkills, GraspSkill, PlaceSkills, PushSkill

__all__ = ["ActionResult", "Robot", "RobotParams"]


class Robot(BasicSkills, GraspSkill, PlaceSkills, PushSkill, ArticulationSkills):
    """The Panda in a loaded scene: primitives that act by stepping ``data``."""
