"""The numbers of the robot's primitives, one dataclass per concern, gathered in :class:`RobotParams`."""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["ArmParams", "ArticulationParams", "MotionParams", "PickParams", "PlaceParams", "PushParams", "RobotParams"]


@dataclass(frozen=True)
class ArmParams:
    """Stepping, the gripper and what counts as holding."""

    check_every: int = 50  # physics steps between divergence checks
    finger_rest_speed: float = 1e-3  # rad/s: the closing fingers have stopped
    holding_min_opening: float = 0.0  # m between the fingers while holding (not closed on nothing; a thin part squeezed hard leaves under 2 mm)
    open_min: float = 0.07  # m an open gripper reaches
    default_friction: float = 0.5  # when an object has no geoms
    default_grip_force: float = 70.0  # N when the gripper's force range is unset
    home_lift_margin: float = 0.05  # m below the home height from which go_home lifts first
    home_tol: float = 0.02  # rad joint error accepted at home
    hold_noslip: int = 10  # noslip iterations while an object is held: static friction holds it without the soft contacts' creep


@dataclass(frozen=True)
class MotionParams:
    """Straight lines and transits."""

    max_joint_jump: float = 0.6  # rad between IK waypoints before a line counts as a joint flip
    transit_low: float = 0.03  # m above the tallest object: the lowest traverse
    transit_drops: tuple[float, ...] = (0.04, 0.08)  # m below the safe height also tried
    swing_steps: int = 10  # joint-space waypoints of a swing across
    swing_dip: float = 0.02  # m a swing may dip below the lowest traverse
    joint_check_step: float = 0.05  # rad between checked postures of a move in joint space
    goal_posture_tol: float = 0.05  # rad: a transit ending this near a given goal posture need not move into it


@dataclass(frozen=True)
class PickParams:
    """Grasp attempts and their rewards."""

    budget_factor: float = 2.0  # a grasp gets this many max_sim_time budgets
    support_probe: float = 0.01  # m above the object's bottom where its support is looked for
    max_reachable: int = 6  # reachable candidates collected per attempt
    reach_tilts: tuple[float, ...] = (0.0, -0.3, 0.3, -0.6, 0.6, -0.9, 0.9, -1.2, 1.2)  # rad the hand leans about the closing axis when no candidate is reachable upright without touching another object (up to 1.2: into a corner between tall boxes)
    manipulability_weight: float = 0.5  # added to a candidate's score per unit manipulability
    lift_wait: float = 0.2  # s after lifting before judging
    retry_lift: float = 0.12  # m backed up after a failed attempt
    fell_drop: float = 0.1  # m below its start: the object fell off its support
    error_reward: float = -0.1  # reward of an attempt that could not be planned
    contact_reward: float = 0.3  # reward for both fingers touching at close
    lift_reward: float = 0.4  # reward for a full lift (scaled by the height reached)
    statics_weight: float = 0.3  # taken off a pinch's score per unit of torque needed over torque held
    squeeze_safety: float = 2.0  # the gripper squeezes this many times what the pinch's statics need
    carry_accel: tuple[float, float] = (1.0, 4.0)  # m/s2: the least and most peak acceleration of a carried object's pinch


@dataclass(frozen=True)
class PlaceParams:
    """Release poses, the fingers' footprint, retreat and rest."""

    finger_reach: float = 0.05  # m either side of the tcp the opening fingers sweep
    finger_half_width: float = 0.012  # m of a finger across the closing axis
    footprint_samples: int = 400  # points of the footprint tested against the keep-out
    approach_height: float = 0.08  # m above the release pose the transit ends
    surface_probe: float = 0.05  # m above the tallest object the surface below is looked for from
    retreat: float = 0.10  # m lifted after release
    handle_free: float = 0.015  # m the fingers open past a handle's width to free it (wider, the inner finger shoves the body)
    handle_back: float = 0.06  # m the hand backs out of a handle's loop along its approach before it lifts
    stand_tilt: float = 0.09  # rad: a held object tilted further from how it stood is lowered until it stands before release
    stand_step: float = 0.01  # m the hand lowers per step while the object comes upright on what is below it
    stand_reach: float = 0.08  # m the hand may lower past the release pose for it
    stand_gain: float = 0.001  # rad a step must right the object by while it rests on something, or the hand stops lowering
    release_wait: float = 0.4  # s after the retreat before judging
    rest_speed: float = 0.05  # m/s: the released object rests
    max_rock: float = 1.2  # s a released object may rock before it rests
    rock_step: float = 0.05  # s between rest checks
    tolerance: float = 0.03  # m from the asked point (place)
    on_top_margin: float = 0.01  # m below a target's top where what lies on it starts
    in_bottom_margin: float = 0.005  # m above a container's bottom where what lies in it starts
    rim_margin: float = 0.005  # m below a container's rim an object's bottom must come at release (else it rests on the rim)
    beside_gap: float = 0.03  # m between the object and the reference (place_beside)
    beside_extra: tuple[float, ...] = (0.0, 0.02, 0.05)  # m further out also tried
    beside_along: tuple[float, ...] = (0.0, 0.02, 0.05, -0.01, -0.02)  # m further out (or nearer) than the gap, for a named side
    beside_step: float = 0.03  # m between spots sideways off the line, for a named side
    side_slack: float = 0.02  # m off the line past the two half widths that a named side allows (relations.side_of)
    beside_margin: float = 0.015  # m kept inside that allowance
    side_overlap: float = 0.01  # m of the reference's extent along a named side the object may overlap (relations.side_of)
    overlap_margin: float = 0.01  # m kept inside that overlap (a released object settles a few mm)
    overlap_step: float = 0.01  # m between spots nearer than beside_along, down to that least gap
    beside_turns: tuple[float, ...] = (0.0, 1.5707963)  # rad the object may be turned for a named side (a long one across)
    turn_cost: float = 0.02  # m of spot cost per rad turned
    level_probe: float = 0.3  # m above the reference's bottom the surface is looked for from
    level_tol: float = 0.02  # m: a spot on the reference's surface (not off the table edge)
    between_along: tuple[float, ...] = (0.15, -0.15, 0.3, -0.3)  # fractions of the gap off the middle
    between_lateral: tuple[float, ...] = (0.0, 0.02, -0.02, 0.04, -0.04, 0.06, -0.06)  # m across
    between_margin: float = 0.005  # m kept to the other objects (place_between)
    down_radius: float = 0.30  # m around the object searched (place_down)
    down_step: float = 0.03  # m between search rings; six spots per step of radius
    down_reach: float = 0.75  # m from the robot's base (horizontal) past which a spot is tried only after the nearer ones
    table_tol: float = 0.002  # m: a spot on the static surface
    support_fraction: float = 0.5  # of the way from the object's centre to its footprint's edge that must lie over the support


@dataclass(frozen=True)
class PushParams:
    """The pushing hand and the stroke."""

    tilt: float = 0.4  # rad the hand leans back when pushing (fingertips lead)
    steep_tilts: tuple[float, ...] = (0.8, 1.1)  # rad also tried, after the upright hand: the wrist clears a tall object's face
    nudge: float = 0.015  # m a pushed object may travel in contact with another (it nudges it that far at most)
    contact_height: float = 0.03  # m above the bottom (at most half the height) the fingers push
    contact_lift: float = 0.005  # m added to it
    standoff: float = 0.03  # m behind the object the stroke starts (and the fingers reach it)
    footprint_samples: int = 400  # points of the footprint swept along the push
    ride_margin: float = 0.005  # m above the bottom where other objects count as in the way
    sweep_step: float = 0.01  # m between swept footprints
    touch_gap: float = 0.002  # m: the swept footprint touches another object
    retreat_back: float = 0.03  # m backed off the object after the stroke
    retreat_up: float = 0.1  # m lifted after the stroke
    rest_wait: float = 0.3  # s before the push is judged
    palm_height: float = 0.047  # m above the tcp where the hand's palm starts
    palm_clearance: float = 0.01  # m the palm keeps above a pushed object's top edge (the contact rises for it)
    palm_catch: float = 0.02  # m above the palm's lower edge a top edge is still caught by it (a taller face is pushed flat)
    max_contact_fraction: float = 0.6  # of the object's height the contact may rise to
    reach_lifts: tuple[float, ...] = (0.02, 0.04, 0.06)  # m the contact rises when no stroke at its height reaches (the wrist stays higher)
    tip_ratio: float = 1.0  # a contact this many times the half length along the push above the bottom could tip it (friction up to 1)


@dataclass(frozen=True)
class ArticulationParams:
    """Drawers and doors."""

    slide_open: float = 0.25  # m an unlimited slide is opened
    hinge_open: float = 1.2  # rad an unlimited hinge is opened
    closed_tol: float = 0.005  # joint units from the closed end: already closed
    handle_face: float = 0.005  # m deep slice of the front face taken as the handle
    steps: int = 10  # IK waypoints along the joint's motion
    retreat: float = 0.08  # m the hand backs off the handle
    open_fraction: float = 0.6  # of the asked opening that counts as opened
    close_tol: float = 0.01  # joint units from the closed end that count as closed
    close_fraction: float = 0.2  # or this fraction of the starting opening, when larger


@dataclass(frozen=True)
class RobotParams:
    """Speeds, clearances and budgets of the primitives; per-concern numbers in the nested groups."""

    max_joint_speed: float = 1.2  # rad/s along a trajectory
    min_segment_time: float = 0.25  # s
    cart_step: float = 0.02  # m between IK waypoints on straight-line moves
    clearance: float = 0.10  # m above the tallest object when traversing
    pregrasp: float = 0.10  # m back along the approach axis
    lift: float = 0.15  # m lifted after closing
    gripper_time: float = 0.6  # s to open or close
    settle_speed: float = 0.02  # rad/s: joints at rest
    max_settle: float = 0.6  # s waiting for rest after a trajectory
    max_sim_time: float = 40.0  # s budget per primitive
    grasp_attempts: int = 4
    lifted_min: float = 0.04  # m the object must rise to count as lifted
    track_tol: float = 0.01  # m tcp error accepted at the end of a straight move
    arm: ArmParams = field(default_factory=ArmParams)
    motion: MotionParams = field(default_factory=MotionParams)
    pick: PickParams = field(default_factory=PickParams)
    place: PlaceParams = field(default_factory=PlaceParams)
    push: PushParams = field(default_factory=PushParams)
    articulation: ArticulationParams = field(default_factory=ArticulationParams)
