"""Phantom arena: the collision primitives that stand in for the captured environment.

A floor plane, a box under each support reaching down to the floor, and perimeter walls so
nothing leaves the scene. Collision geoms are group 3 (hidden in viewers by default); the floor
and the supports also get group-2 visual twins so a rendered frame shows them. A support whose
top was captured (``slabs``) is shown as a thin slab under its textured top instead of a box down
to the floor, so what the camera saw beneath it (the backdrop) stays visible.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from realsim.geometry import yaw_quat
from realsim.scene import Scene, SupportPlane

VISUAL_GROUP = 2
COLLISION_GROUP = 3


@dataclass(frozen=True)
class ArenaParams:
    """Parameters of the phantom arena."""

    wall_height: float = 1.0
    wall_thickness: float = 0.05
    wall_margin: float = 0.6  # walls this far outside the supports (m)
    support_color: tuple[float, float, float, float] = (0.55, 0.42, 0.3, 1.0)
    floor_color: tuple[float, float, float, float] = (0.35, 0.37, 0.4, 1.0)
    slab_thickness: float = 0.03  # visual thickness of a captured support (m)


def _add_pair(body: mujoco.MjsBody, name: str, rgba, visual: bool = True, **geom) -> None:
    body.add_geom(name=f"{name}_collision", group=COLLISION_GROUP, contype=1, conaffinity=1, rgba=[0.4, 0.6, 0.8, 0.3], **geom)
    if visual:
        body.add_geom(name=f"{name}_visual", group=VISUAL_GROUP, contype=0, conaffinity=0, rgba=list(rgba), **geom)


def support_box(plane: SupportPlane, floor_z: float) -> tuple[list[float], list[float], list[float]]:
    """Centre, half-sizes and quaternion of the box standing under a support, down to the floor."""
    depth = max(plane.height - floor_z, 0.02)
    centre = [float(plane.rect_center[0]), float(plane.rect_center[1]), plane.height - depth / 2]
    half = [float(plane.rect_size[0] / 2), float(plane.rect_size[1] / 2), depth / 2]
    return centre, half, yaw_quat(plane.rect_yaw).tolist()


def add_arena(spec: mujoco.MjSpec, scene: Scene, params: ArenaParams = ArenaParams(), slabs: dict[int, list[float]] | None = None) -> None:
    """Add the floor, one box per non-floor support, and perimeter walls to ``spec``.

    ``slabs`` maps the ids of supports with a captured, textured top to the colour of their slab.
    """
    slabs = slabs or {}
    world = spec.worldbody
    floor_z = scene.floor_height
    tex = spec.add_texture(name="floor_grid", type=mujoco.mjtTexture.mjTEXTURE_2D, builtin=mujoco.mjtBuiltin.mjBUILTIN_CHECKER,
                           rgb1=[0.32, 0.34, 0.37], rgb2=[0.38, 0.40, 0.43], width=256, height=256)
    mat = spec.add_material(name="floor_grid", texrepeat=[8, 8], reflectance=0.05)
    mat.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = tex.name
    world.add_geom(name="floor_collision", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[0, 0, 0.05], pos=[0, 0, floor_z],
                   group=COLLISION_GROUP, contype=1, conaffinity=1, rgba=[0.4, 0.6, 0.8, 0.3])
    world.add_geom(name="floor_visual", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[0, 0, 0.05], pos=[0, 0, floor_z],
                   group=VISUAL_GROUP, contype=0, conaffinity=0, material="floor_grid", rgba=list(params.floor_color))
    corners = []
    for plane in scene.planes:
        corners.append(plane.polygon)
        if plane.kind == "floor":
            continue
        centre, half, quat = support_box(plane, floor_z)
        _add_pair(world, f"support{plane.id}", params.support_color, visual=plane.id not in slabs, type=mujoco.mjtGeom.mjGEOM_BOX,
                  pos=centre, size=half, quat=quat)
        if plane.id in slabs:
            t = min(params.slab_thickness, 2 * half[2]) / 2
            world.add_geom(name=f"support{plane.id}_visual", type=mujoco.mjtGeom.mjGEOM_BOX, group=VISUAL_GROUP, contype=0, conaffinity=0,
                           pos=[centre[0], centre[1], plane.height - t], size=[half[0], half[1], t], quat=quat, rgba=list(slabs[plane.id]))
    for obj in scene.objects:
        corners.append(obj.position[None, :2])
    if not corners:
        return
    pts = np.vstack(corners)
    lo = pts.min(axis=0) - params.wall_margin
    hi = pts.max(axis=0) + params.wall_margin
    centre = (lo + hi) / 2
    half = (hi - lo) / 2
    t, h = params.wall_thickness / 2, params.wall_height / 2
    walls = {
        "wall_xneg": ([lo[0] - t, centre[1], floor_z + h], [t, half[1] + 2 * t, h]),
        "wall_xpos": ([hi[0] + t, centre[1], floor_z + h], [t, half[1] + 2 * t, h]),
        "wall_yneg": ([centre[0], lo[1] - t, floor_z + h], [half[0] + 2 * t, t, h]),
        "wall_ypos": ([centre[0], hi[1] + t, floor_z + h], [half[0] + 2 * t, t, h]),
    }
    for name, (pos, size) in walls.items():
        _add_pair(world, name, params.floor_color, visual=False, type=mujoco.mjtGeom.mjGEOM_BOX, pos=[float(v) for v in pos], size=[float(v) for v in size])
