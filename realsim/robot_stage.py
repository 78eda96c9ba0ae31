"""The ``robot`` stage: put the Franka Panda beside the primary support, reaching the objects."""

from __future__ import annotations

from dataclasses import dataclass, field

from realsim.robot.placement import PlacementParams, add_robot
from realsim.scene import Scene


@dataclass(frozen=True)
class RobotStageParams:
    """Whether to add the robot, and where (``pose`` = x, y, yaw overrides the search)."""

    enabled: bool = True
    pose: tuple[float, float, float] | None = None
    placement: PlacementParams = field(default_factory=PlacementParams)


def robot_scene(scene: Scene, params: RobotStageParams = RobotStageParams()) -> Scene:
    """Attach the Panda (pose searched for reach and manipulability unless given) to the spec."""
    if not params.enabled or scene.spec is None or not scene.planes:
        return scene
    pose = tuple(float(v) for v in params.pose) if params.pose is not None else None
    handles = add_robot(scene, pose=pose, params=params.placement)
    scene.robot = {
        "model": "franka_emika_panda (mujoco-menagerie panda.xml)",
        "prefix": handles.prefix,
        "base_pose_xy_yaw": list(handles.base_pose),
        "base_z": handles.base_z,
        "pedestal_height": handles.pedestal_height,
        "pose_source": "override" if pose is not None else "reach and manipulability search",
    }
    return scene
