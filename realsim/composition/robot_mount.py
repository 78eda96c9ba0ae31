"""The ``robot`` stage: put the Franka Panda beside the primary support, reaching the objects.

The searched pose is cached under exactly what the search reads (the primary support, the hover
and handle targets, the parameters, the code digest): a rerun attaches the robot where it stood
without searching.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import mujoco
import numpy as np

from realsim.cache import DiskCache, output_key
from realsim.composition import robot_ahead
from realsim.composition.robot_placement import MAX_REACH, PlacementParams, SearchInputs, add_robot, pedestal_height, search_inputs
from realsim.errors import InputError
from realsim.geometry import inside_convex_polygon
from realsim.robot.model import attach_robot
from realsim.scene import Scene

BASE_RADIUS = 0.12  # m, the Panda's base footprint around link0


@dataclass(frozen=True)
class RobotStageParams:
    """Whether to add the robot, and where (``pose`` = x, y, yaw overrides the search)."""

    enabled: bool = True
    pose: tuple[float, float, float] | None = None
    placement: PlacementParams = field(default_factory=PlacementParams)


def robot_scene(scene: Scene, params: RobotStageParams = RobotStageParams(), model: mujoco.MjModel | None = None) -> Scene:
    """Attach the Panda (pose searched for reach and manipulability unless given) to the spec.
    ``model`` is ``scene.spec`` compiled as it is now, when the caller has it (else compiled here);
    ``scene.compiled`` is left holding the spec compiled with the robot."""
    if not params.enabled or scene.spec is None or not scene.planes:
        return scene
    pose = tuple(float(v) for v in params.pose) if params.pose is not None else None
    robot_ahead.finish()  # the Panda's meshes cached by the thread begun after load, if any
    if pose is not None:
        check_robot_pose(scene, pose)
        handles = add_robot(scene, pose=pose, params=params.placement)
    else:
        cache = DiskCache()
        inputs = search_inputs(scene, scene.spec.compile() if model is None else model, params.placement)
        key = _placement_key(scene, params.placement, inputs)
        found = cache.get(key)
        if found is None:
            handles = add_robot(scene, params=params.placement, inputs=inputs)
            cache.put(key, handles.base_pose)
        else:  # the pose this very scene got before: attach without searching
            handles = attach_robot(scene.spec, tuple(found), base_z=scene.floor_height,
                                   pedestal_height=pedestal_height(scene, params.placement))
            scene.assets.update(handles.assets)
    scene.compiled = (scene.spec, handles.model)  # settle simulates this very model instead of compiling it again
    scene.robot = {
        "model": "franka_emika_panda (mujoco-menagerie panda.xml)",
        **handles.record(),
        "base_pose_xy_yaw": list(handles.base_pose),
        "base_z": handles.base_z,
        "pedestal_height": handles.pedestal_height,
        "pose_source": "override" if pose is not None else "reach and manipulability search",
    }
    return scene


def _placement_key(scene: Scene, params: PlacementParams, inputs: SearchInputs) -> str:
    """Everything the pose search reads (the primary support, the targets, the parameters; the
    composed spec only through them) and the floor the robot stands on."""
    return output_key("robot-placement", params={"placement": params, "search": inputs.record(), "floor": scene.floor_height})


def check_robot_pose(scene: Scene, pose: tuple[float, float, float], reach: float = MAX_REACH) -> None:
    """Refuse a given base pose that stands inside furniture or cannot reach any object.

    The base may not overlap a support (floor excepted) and must be within ``reach`` (plus the
    base radius) of the nearest object, or of the nearest support edge when there are no objects.
    """
    x, y, _ = pose
    if not all(np.isfinite(pose)):
        raise InputError(f"--robot-pose {x},{y}: must be finite numbers")
    base = np.array([[x, y]])
    for plane in scene.planes:
        if plane.kind != "floor" and inside_convex_polygon(base, plane.polygon, margin=BASE_RADIUS)[0]:
            raise InputError(f"--robot-pose {x:g},{y:g}: the base stands inside the {plane.kind} (support {plane.id}); "
                             "put it beside the furniture, or leave --robot-pose out to search for a pose")
    if scene.objects:
        targets = np.array([np.asarray(o.position, float)[:2] for o in scene.objects])
    else:
        targets = np.vstack([p.polygon for p in scene.planes if p.kind != "floor"] or [np.zeros((1, 2))])
    nearest = float(np.min(np.linalg.norm(targets - base, axis=1)))
    if nearest > reach + BASE_RADIUS:
        raise InputError(f"--robot-pose {x:g},{y:g}: the nearest {'object' if scene.objects else 'support'} is {nearest:.2f} m away "
                         f"and the Panda reaches {reach:.2f} m; put the base closer, or leave --robot-pose out to search for a pose")
