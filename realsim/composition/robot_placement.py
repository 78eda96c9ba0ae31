"""Where the robot stands: a base pose beside the primary work surface.

The Panda stands on a box pedestal beside the table, its base footprint outside the table's
rectangle, link0 level with the table top (``pedestal_drop`` below it). A Panda standing on the
floor beside a 0.75 m table would have its shoulder (0.333 m above the base) barely above the
table top and would reach the far half of the table only with a stretched arm; mounting the base
at table height is what real setups do and gives top-down grasps over ~0.25-0.8 m of reach.

Candidate poses lie along each side of the support rectangle, facing inward; each is scored by
solving IK for top-down hovers above every object (and for the sideways pull of each drawer
handle) and summing reachability and manipulability sqrt(det J J^T). Every object is a target: one
the hand can hold is picked, any other is placed on, into or beside, or pushed; an object the hand
can hold counts :data:`HOLDABLE_WEIGHT` times as much, so no pose trades one of those for others.
The best candidate wins (ties broken by candidate order, so the choice is deterministic). Every candidate is scored on its own (no solve carries over), so they are
shared with a forked helper (:func:`realsim.forkmap.fork_map`).
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from realsim.forkmap import fork_map
from realsim.geometry import yaw_quat
from realsim.robot.grasps import frame_from
from realsim.robot.ik import ArmIK, IKParams, mat_to_quat
from realsim.robot.model import BASE_FOOTPRINT, GRIPPER_MAX_OPENING, PREFIX, RobotHandles, attach_robot, panda_spec
from realsim.scene import Scene, SceneObject, primary_support

TOP_DOWN = np.array([0.0, 1.0, 0.0, 0.0])  # tcp z axis pointing down (w, x, y, z)
SHOULDER_HEIGHT = 0.333  # m, joint 2 above link0
MAX_REACH = 0.86  # m from the shoulder to the tcp when stretched (Panda datasheet reach 855 mm + tcp)
SCORING_IK = IKParams(max_iters=120, dls_iters=80)  # ranking needs a verdict, not a polished solution
COMFORT_DISTANCE = 0.5  # m, horizontal base-to-target distance the Panda reaches best from above
COMFORT_BAND = 0.3  # m either side of it
HOLDABLE_WEIGHT = 10.0  # an object the hand can hold (or a handle, a given target) outweighs all others together


@dataclass(frozen=True)
class PlacementParams:
    """Parameters of the base pose search."""

    edge_gaps: tuple[float, ...] = (0.02, 0.1)  # m between the pedestal and the table edge
    side_offsets: tuple[float, ...] = (-0.3, -0.15, 0.0, 0.15, 0.3)  # fraction of the side length
    pedestal_drop: float = 0.0  # m, link0 this far below the table top
    hover: float = 0.05  # m above an object's top for the scored IK targets
    ik_candidates: int = 8  # poses scored with IK after the cheap reach ranking


def graspable_objects(scene: Scene) -> list[SceneObject]:
    """Objects narrower than the hand's opening in some horizontal direction."""
    out = []
    for obj in scene.objects:
        if obj.size is None or float(np.min(obj.size[:2])) < GRIPPER_MAX_OPENING - 0.005 or obj.label in ("bowl", "mug", "cup"):
            out.append(obj)
    return out or list(scene.objects)


def candidate_poses(scene: Scene, params: PlacementParams = PlacementParams()) -> list[tuple[float, float, float]]:
    """(x, y, yaw) along every side of the primary support, facing the table centre."""
    plane = primary_support(scene)
    c = np.asarray(plane.rect_center, float)
    half = np.asarray(plane.rect_size, float) / 2
    rot = np.array([[np.cos(plane.rect_yaw), -np.sin(plane.rect_yaw)], [np.sin(plane.rect_yaw), np.cos(plane.rect_yaw)]])
    out = []
    for axis in (0, 1):
        for sign in (-1.0, 1.0):
            for gap in params.edge_gaps:
                for frac in params.side_offsets:
                    local = np.zeros(2)
                    local[axis] = sign * (half[axis] + BASE_FOOTPRINT + gap)
                    local[1 - axis] = frac * 2 * half[1 - axis]
                    xy = c + rot @ local
                    inward = -(rot @ (np.eye(2)[axis] * sign))
                    out.append((float(xy[0]), float(xy[1]), float(np.arctan2(inward[1], inward[0]))))
    return out


def handle_targets(model: mujoco.MjModel, pregrasp: float = 0.10) -> list[tuple[np.ndarray, np.ndarray]]:
    """(tcp position, quaternion) targets for pulling each articulated part by its handle site
    (``<body>_handle``): in front of the handle, at it, where the pull ends and in front of that."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    out = []
    for i in range(model.nsite):
        if not model.site(i).name.endswith("_handle"):
            continue
        b = model.site_bodyid[i]
        j = model.body_jntadr[b]
        if j < 0 or int(model.jnt_type[j]) != mujoco.mjtJoint.mjJNT_SLIDE:
            continue  # hinged lids are pulled up, not along a horizontal line
        axis = model.jnt_axis[j] @ data.xmat[b].reshape(3, 3).T
        horiz = np.array([axis[0], axis[1], 0.0])
        if np.linalg.norm(horiz) < 1e-6:
            continue
        horiz /= np.linalg.norm(horiz)
        quat = mat_to_quat(frame_from(-horiz, np.array([0.0, 0.0, 1.0])))
        hpos = data.site_xpos[i].copy()
        travel = float(model.jnt_range[j][1])
        for p in (hpos + horiz * pregrasp, hpos, hpos + horiz * travel, hpos + horiz * (travel + pregrasp)):
            out.append((p, quat))
    return out


@functools.lru_cache(maxsize=1)
def bare_panda() -> mujoco.MjModel:
    """The Panda at the origin without geoms or meshes: the bodies (explicit inertials), joints,
    sites and actuators IK reads, the same arrays as the full model's, compiled without the mesh
    processing that costs half a second (a pose search needs kinematics, not looks)."""
    child, _ = panda_spec()
    for geom in list(child.geoms):
        child.delete(geom)
    for mesh in list(child.meshes):
        child.delete(mesh)
    spec = mujoco.MjSpec()
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    spec.attach(child, prefix=PREFIX, frame=spec.worldbody.add_frame(pos=[0.0, 0.0, 0.0], quat=[1.0, 0.0, 0.0, 0.0]))
    for key in list(spec.keys):
        spec.delete(key)
    return spec.compile()


@functools.lru_cache(maxsize=2)
def _scoring_ik(params: IKParams) -> ArmIK:
    """The pose search's IK on :func:`bare_panda`, built once and stood at each candidate pose."""
    return ArmIK(np.zeros(3), np.array([1.0, 0.0, 0.0, 0.0]), params, scene=bare_panda())


def prepare_search() -> None:
    """Build the pose search's IK (:func:`bare_panda` and its solver, kept per process) now."""
    _scoring_ik(SCORING_IK)


def score_pose(pose: tuple[float, float, float], base_z: float, targets: list[np.ndarray], ik_params: IKParams = SCORING_IK,
               oriented: Sequence[tuple[np.ndarray, np.ndarray]] = (), weights: Sequence[float] | None = None) -> tuple[float, int, float]:
    """(score, reachable count, mean manipulability) of a base pose over top-down hover
    ``targets`` and ``oriented`` (position, quaternion) targets such as drawer handles; the score
    sums the ``weights`` of the reached ``targets`` (1 each when None; an oriented target weighs
    :data:`HOLDABLE_WEIGHT`) and five times the mean manipulability.

    Targets beyond the arm's reach sphere around the shoulder count as unreachable without IK.
    """
    ik = _scoring_ik(ik_params)
    ik.place(np.array([pose[0], pose[1], base_z]), np.array(yaw_quat(pose[2])))
    shoulder = np.array([pose[0], pose[1], base_z + SHOULDER_HEIGHT])
    tw = [1.0] * len(targets) if weights is None else [float(w) for w in weights]
    reach, gained, manip = 0, 0.0, []
    for (t, quat), w in zip([(t, TOP_DOWN) for t in targets] + list(oriented), tw + [HOLDABLE_WEIGHT] * len(oriented)):
        if np.linalg.norm(np.asarray(t) - shoulder) > MAX_REACH:
            continue
        res = ik.solve(t, quat)
        if res.converged:
            reach += 1
            gained += w
            manip.append(res.manipulability)
    mean_m = float(np.mean(manip)) if manip else 0.0
    return gained + mean_m * 5.0, reach, mean_m


@dataclass(frozen=True)
class SearchInputs:
    """Everything the base pose search reads: the primary support's rectangle and height, the
    top-down hover targets and the oriented (position, quaternion) handle targets."""

    rect: tuple[tuple[float, float], tuple[float, float], float, float]  # centre, size, yaw, height
    targets: tuple[tuple[float, ...], ...]
    oriented: tuple[tuple[tuple[float, ...], tuple[float, ...]], ...]
    weights: tuple[float, ...] = ()  # one per target (:data:`HOLDABLE_WEIGHT` or 1); empty: all 1

    def record(self) -> dict[str, object]:
        """The inputs as plain lists (a cache key's parameters)."""
        return {"rect": self.rect, "targets": self.targets, "oriented": self.oriented, "weights": self.weights}

    def target_weights(self) -> list[float]:
        """The weight of each top-down target."""
        return list(self.weights) if self.weights else [1.0] * len(self.targets)


def search_inputs(scene: Scene, model_without_robot: mujoco.MjModel | None = None, params: PlacementParams = PlacementParams(),
                  extra_targets: list[np.ndarray] | None = None) -> SearchInputs:
    """What :func:`choose_robot_pose` searches over. Object poses are read from
    ``model_without_robot`` (its bodies' initial poses) when given, else from the scene."""
    plane = primary_support(scene)
    targets, weights = [], []
    holdable = {id(o) for o in graspable_objects(scene)}
    for obj in scene.objects:
        pos = np.asarray(obj.position, float)
        if model_without_robot is not None:
            try:
                pos = np.asarray(model_without_robot.body(obj.name).pos, float)
            except KeyError:
                pass
        height = float(obj.size[2]) if obj.size is not None else 0.1
        targets.append(np.array([pos[0], pos[1], pos[2] + height + params.hover]))
        weights.append(HOLDABLE_WEIGHT if id(obj) in holdable else 1.0)
    targets += [np.asarray(t, float) for t in extra_targets or []]
    weights += [HOLDABLE_WEIGHT] * len(extra_targets or [])
    oriented = handle_targets(model_without_robot) if model_without_robot is not None else []
    if not targets and not oriented:
        targets, weights = [np.array([*plane.rect_center, plane.height + 0.1])], [1.0]
    rect = (tuple(float(v) for v in plane.rect_center), tuple(float(v) for v in plane.rect_size), float(plane.rect_yaw), float(plane.height))
    return SearchInputs(rect, tuple(tuple(float(v) for v in t) for t in targets),  # type: ignore[arg-type]
                        tuple((tuple(float(v) for v in p), tuple(float(v) for v in q)) for p, q in oriented), tuple(weights))


def choose_robot_pose(scene: Scene, model_without_robot: mujoco.MjModel | None = None, override: tuple[float, float, float] | None = None,
                      params: PlacementParams = PlacementParams(), extra_targets: list[np.ndarray] | None = None,
                      inputs: SearchInputs | None = None) -> tuple[float, float, float]:
    """The base pose (x, y, yaw) beside the primary support maximizing reach and manipulability.

    ``override`` (the CLI's ``--robot-pose x,y,yaw``) is returned as given. The targets are
    ``inputs`` when given, else :func:`search_inputs` of the other arguments.
    """
    if override is not None:
        return tuple(float(v) for v in override)  # type: ignore[return-value]
    if inputs is None:
        inputs = search_inputs(scene, model_without_robot, params, extra_targets)
    base_z = inputs.rect[3] - params.pedestal_drop
    targets = [np.array(t) for t in inputs.targets]
    oriented = [(np.array(p), np.array(q)) for p, q in inputs.oriented]
    weights = inputs.target_weights()
    poses = _prefilter(candidate_poses(scene, params), targets + [p for p, _ in oriented], weights + [HOLDABLE_WEIGHT] * len(oriented),
                       params.ik_candidates)
    prepare_search()  # built once, before the helper forks, for both processes
    scores = fork_map(lambda i: score_pose(poses[i], base_z, targets, oriented=oriented, weights=weights)[0], len(poses))  # each pose on its own
    best, best_score = None, -np.inf
    for pose, s in zip(poses, scores):
        if s > best_score + 1e-9:
            best, best_score = pose, s
    assert best is not None
    return best


def _prefilter(poses: list[tuple[float, float, float]], targets: list[np.ndarray], weights: list[float],
               keep: int) -> list[tuple[float, float, float]]:
    """The ``keep`` poses whose horizontal distances to the targets (``weights`` each) sit best in
    the arm's comfortable band (a cheap stand-in for IK, used to rank before the IK scoring)."""
    pts = np.asarray(targets, float)[:, :2]
    w = np.asarray(weights, float)

    def comfort(pose: tuple[float, float, float]) -> float:
        d = np.linalg.norm(pts - np.asarray(pose[:2]), axis=1)
        return float(np.sum(w * np.clip(1.0 - np.abs(d - COMFORT_DISTANCE) / COMFORT_BAND, 0.0, 1.0)))

    ranked = sorted(range(len(poses)), key=lambda i: (-comfort(poses[i]), i))
    return [poses[i] for i in ranked[:keep]]


def pedestal_height(scene: Scene, params: PlacementParams = PlacementParams()) -> float:
    """Pedestal height putting link0 ``pedestal_drop`` below the primary support's top."""
    plane = primary_support(scene)
    return max(plane.height - params.pedestal_drop - scene.floor_height, 0.0)


def add_robot(scene: Scene, pose: tuple[float, float, float] | None = None, params: PlacementParams = PlacementParams(),
              extra_targets: list[np.ndarray] | None = None, inputs: SearchInputs | None = None) -> RobotHandles:
    """The robot stage: choose the base pose (unless given; over ``inputs`` when given), attach the
    Panda on its pedestal to ``scene.spec`` and add its meshes to ``scene.assets``. Run after
    compose, before settle."""
    model = scene.spec.compile() if scene.spec is not None and pose is None and inputs is None else None
    pose = choose_robot_pose(scene, model, override=pose, params=params, extra_targets=extra_targets, inputs=inputs)
    handles = attach_robot(scene.spec, pose, base_z=scene.floor_height, pedestal_height=pedestal_height(scene, params))
    scene.assets.update(handles.assets)
    return handles
