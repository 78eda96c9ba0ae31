"""Sampling-based transit in the arm's joint space: OMPL's RRT-Connect with a MuJoCo collision check.

:func:`plan_joint_path` connects two arm postures through postures ``valid`` accepts (the caller
checks them with MuJoCo: kinematics and contacts on a scratch state), every edge checked at
``resolution`` rad. Planning is bounded by a count of collision checks, not by wall time, and
OMPL's random source is seeded before each plan, so the same scene, postures and seed give the same
path. The path is then shortened (OMPL's vertex reduction and partial shortcutting, bounded in steps)
and its vertices are the corners of a trajectory the arm follows with a quintic time scaling
per segment: at rest at every corner, smooth (zero velocity and acceleration) in between.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from realsim.robot.result import PlanFailure

__all__ = ["TransitParams", "plan_joint_path"]


@dataclass(frozen=True)
class TransitParams:
    """Budget and resolution of the sampling-based transit."""

    max_checks: int = 6000  # collision checks a plan may spend
    resolution: float = 0.02  # rad between checked postures along an edge
    range: float = 0.6  # rad: longest tree extension of RRT-Connect
    simplify_steps: int = 60  # shortcut attempts on the found path
    margin: float = 0.01  # rad kept inside the joint limits
    clearance: float = 0.015  # m the arm keeps from every object between the path's ends (less only where an end is nearer)


def plan_joint_path(q_start: np.ndarray, q_goal: np.ndarray, lower: np.ndarray, upper: np.ndarray, valid: Callable[[np.ndarray], bool],
                    seed: int = 0, params: TransitParams = TransitParams()) -> list[np.ndarray]:
    """Joint-space waypoints from ``q_start`` (excluded) to ``q_goal`` (included) through postures
    ``valid`` accepts; raises :class:`PlanFailure` when none is found within the budget."""
    from ompl import base as ob
    from ompl import geometric as og
    from ompl import util as ou

    ou.setLogLevel(ou.LOG_NONE)
    ou.RNG.setSeed(int(seed) % (2**31 - 1) + 1)  # OMPL's seed is global: set before each plan for a reproducible one
    q_start, q_goal = np.asarray(q_start, float), np.asarray(q_goal, float)
    n = len(q_start)
    lo, hi = np.minimum(lower + params.margin, q_start), np.maximum(upper - params.margin, q_start)
    lo, hi = np.minimum(lo, q_goal), np.maximum(hi, q_goal)
    space = ob.RealVectorStateSpace(n)
    bounds = ob.RealVectorBounds(n)
    for i in range(n):
        bounds.setLow(i, float(lo[i]))
        bounds.setHigh(i, float(hi[i]))
    space.setBounds(bounds)
    checks = [0]

    def ok(state: object) -> bool:
        checks[0] += 1
        return bool(valid(np.array([state[i] for i in range(n)])))  # type: ignore[index]

    si = ob.SpaceInformation(space)
    si.setStateValidityChecker(ok)
    si.setStateValidityCheckingResolution(params.resolution / space.getMaximumExtent())
    si.setup()
    if not valid(q_start):
        raise PlanFailure("the arm's start posture already touches something")
    if not valid(q_goal):
        raise PlanFailure("the goal posture touches something")
    start, goal = space.allocState(), space.allocState()
    for i in range(n):
        start[i], goal[i] = float(q_start[i]), float(q_goal[i])
    pdef = ob.ProblemDefinition(si)
    pdef.setStartAndGoalStates(start, goal)
    planner = og.RRTConnect(si)
    planner.setRange(params.range)
    planner.setProblemDefinition(pdef)
    planner.setup()
    planner.solve(ob.PlannerTerminationCondition(lambda: checks[0] > params.max_checks))
    if not pdef.hasExactSolution():
        planner.clear()
        raise PlanFailure(f"no collision-free path found ({checks[0]} postures checked)")
    path = pdef.getSolutionPath()
    simplifier = og.PathSimplifier(si)
    simplifier.reduceVertices(path, params.simplify_steps)
    simplifier.partialShortcutPath(path, params.simplify_steps)
    out = [np.array([s[i] for i in range(n)]) for s in path.getStates()]
    planner.clear()
    pdef.clearSolutionPaths()
    out[-1] = q_goal
    return out[1:]
