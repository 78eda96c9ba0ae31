"""A loaded realsim scene: the MuJoCo model at keyframe "initial", the Panda, and what planners
and goals read from it.

``Sim.load(folder)`` compiles ``folder/scene.xml`` and reads ``folder/scene.json`` (labels,
manifests, the robot's names). The folder is all it needs: the robot's kinematics, home posture
and limits are read from the scene, never from the Menagerie, so a moved or exported scene runs
offline. Object positions and sizes given to planners and goals are *live*: the centre and
the world-axis-aligned extents of each body's collision geometry at the current state, so a
goal measured after a run sees where the objects really are. Nothing is ever written back to
the scene folder.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from realsim.errors import InputError
from realsim.planner.program import Program
from realsim.planner.types import ObjectInfo
from realsim.robot.grasps import footprint_widths
from realsim.robot.model import PREFIX, describe_robot
from realsim.robot.robot import Robot, RobotParams
from realsim.scene_format import KEYFRAME

HOME_TOLERANCE = 0.05  # rad, max joint error still "at home"


@dataclass(frozen=True)
class SceneObjectRecord:
    """What scene.json says about one object (static; live state comes from the simulation)."""

    name: str
    label: str
    manifest: dict[str, Any]


def _affordances(manifest: dict[str, Any], label: str) -> tuple[str, ...]:
    from realsim.physics.size_table import lookup

    out: list[str] = []
    if manifest.get("is_graspable", True):
        out.append("graspable")
    match = lookup(manifest.get("category") or label)
    if match is not None and match.category.form == "open_container":
        out.append("container")
    if manifest.get("is_support_surface"):
        out.append("support")
    if manifest.get("is_pushable", True):
        out.append("pushable")
    joint = manifest.get("joint_type")
    if joint == "slide":
        out.append("drawer")
    elif joint == "hinge":
        out.append("door")
    return tuple(out)


def _aliases(label: str, manifest: dict[str, Any]) -> tuple[str, ...]:
    from realsim.physics.size_table import lookup

    words: list[str] = []
    category = manifest.get("category") or label
    match = lookup(category)
    if match is not None:
        words.append(match.category.name)
        words.extend(match.category.aliases)
    if category != label:
        words.append(category)
    norm = label.replace("_", " ")
    return tuple(dict.fromkeys(w.replace("_", " ") for w in words if w and w.replace("_", " ") != norm))


class Sim:
    """One scene folder loaded into MuJoCo, with the robot and a :class:`WorldView` for goals."""

    def __init__(self, folder: Path, model: mujoco.MjModel, meta: dict[str, Any], seed: int = 0,
                 robot_params: RobotParams = RobotParams()):
        self.folder = Path(folder)
        self.model = model
        self.data = mujoco.MjData(model)
        self.meta = meta
        self.seed = seed
        self.robot_params = robot_params
        self._scene_noslip = int(model.opt.noslip_iterations)  # the scene's own; a run ending while holding leaves it raised
        self.prefix = (meta.get("robot") or {}).get("prefix") or PREFIX
        if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, self.prefix + "link0") < 0:
            raise InputError(f"{self.folder}: the scene has no robot (no '{self.prefix}link0' body); "
                             "convert it again without --no-robot")
        if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, KEYFRAME) < 0:
            raise InputError(f"{self.folder}/scene.xml has no keyframe '{KEYFRAME}'; convert the scene again")
        try:  # everything about the robot comes from the scene, never from the Menagerie
            self.robot_description = describe_robot(model, meta.get("robot"))
        except InputError as exc:
            raise InputError(f"{self.folder}: {exc}") from None
        self.records: dict[str, SceneObjectRecord] = {}
        for o in meta.get("objects", []):
            body = o.get("body") or o.get("name")
            if body and mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, body) >= 0:
                self.records[body] = SceneObjectRecord(body, str(o.get("label") or body), dict(o.get("manifest") or {}))
        self.robot: Robot
        self.reset()

    # --- loading ------------------------------------------------------------------------------
    @classmethod
    def load(cls, folder: str | Path, seed: int = 0, robot_params: RobotParams = RobotParams()) -> Sim:
        """Load ``folder`` (written by ``realsim convert``); raises :class:`InputError` when it is
        missing, not a scene, or has no robot."""
        folder = Path(folder)
        if not folder.exists():
            raise InputError(f"{folder}: no such scene folder; make one with `realsim convert CAPTURE -o {folder}`")
        xml = folder / "scene.xml" if folder.is_dir() else folder
        if not xml.is_file():
            raise InputError(f"{folder}: not a realsim scene (no scene.xml); make one with `realsim convert`")
        meta_path = xml.parent / "scene.json"
        meta: dict[str, Any] = {}
        if meta_path.is_file():
            try:
                meta = json.loads(meta_path.read_text(encoding="utf-8"))
            except json.JSONDecodeError as exc:
                raise InputError(f"{meta_path}: not valid JSON ({exc}); convert the scene again") from None
        try:
            model = mujoco.MjModel.from_xml_path(str(xml))
        except ValueError as exc:
            raise InputError(f"{xml}: MuJoCo cannot load it ({' '.join(str(exc).split())[:200]})") from None
        return cls(xml.parent, model, meta, seed=seed, robot_params=robot_params)

    def reset(self) -> None:
        """Back to keyframe "initial" with a fresh :class:`Robot` (hooks are dropped) and the scene's
        own solver options (a run that ended holding an object leaves the noslip solver on)."""
        self.model.opt.noslip_iterations = self._scene_noslip
        mujoco.mj_resetDataKeyframe(self.model, self.data, self.model.key(KEYFRAME).id)
        mujoco.mj_forward(self.model, self.data)
        self.robot = Robot(self.model, self.data, prefix=self.prefix, params=self.robot_params, seed=self.seed)

    # --- objects ------------------------------------------------------------------------------
    def object_names(self) -> list[str]:
        """The scene's objects: free bodies, then articulated ones listed in scene.json."""
        names = self.robot.object_names()
        return names + [n for n in self.records if n not in names]

    def _check(self, name: str) -> None:
        if name not in self.object_names() and mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, name) < 0:
            raise KeyError(f"no object named {name!r}; objects: {', '.join(self.object_names())}")

    def bounds(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """World-axis-aligned (min, max) corners of body ``name``'s collision geometry, live."""
        self._check(name)
        pts = self.robot.object_points(name)
        return pts.min(axis=0), pts.max(axis=0)

    def object_infos(self) -> list[ObjectInfo]:
        """The objects as planners see them: labels and affordances from scene.json, live geometry."""
        out = []
        for name in self.object_names():
            rec = self.records.get(name) or SceneObjectRecord(name, name, {})
            pts = self.robot.object_points(name)
            lo, hi = pts.min(axis=0), pts.max(axis=0)
            out.append(ObjectInfo(
                name=name,
                label=rec.label.replace("_", " "),
                aliases=_aliases(rec.label, rec.manifest),
                position=tuple(round(float(v), 4) for v in (lo + hi) / 2),  # type: ignore[arg-type]
                size=tuple(round(float(v), 4) for v in hi - lo),  # type: ignore[arg-type]
                color=None,
                affordances=_affordances(rec.manifest, rec.label),
                footprint=tuple(round(w, 4) for w in footprint_widths(pts)),  # type: ignore[arg-type]
            ))
        return out

    def check_holdable(self, program: Program) -> None:
        """Raise :class:`InputError`, before anything moves, when ``program`` carries an object the
        hand cannot hold as it stands (wider than the opening at its narrowest, with no rim or
        handle to pinch, or only where its weight twists it out of the pinch): the robot's own
        :meth:`graspability`, asked before the run instead of when the arm arrives."""
        for name in program.carried():
            ok, why = self.robot.graspability(name)
            if not ok:
                rec = self.records.get(name)
                push = "; it can still be pushed" if rec is None or rec.manifest.get("is_pushable", True) else ""
                raise InputError(f"{why}, so it cannot be lifted or carried{push}")

    # --- WorldView (read by goals) ------------------------------------------------------------
    def object_pose(self, name: str) -> tuple[Sequence[float], Sequence[float]]:
        """(centre of the live bounding box, body quaternion w,x,y,z)."""
        lo, hi = self.bounds(name)
        quat = self.data.xquat[self.model.body(name).id]
        return [float(v) for v in (lo + hi) / 2], [float(v) for v in quat]

    def object_size(self, name: str) -> Sequence[float]:
        lo, hi = self.bounds(name)
        return [float(v) for v in hi - lo]

    def robot_yaw(self) -> float:
        """Yaw of the robot's base (rad): direction words are relative to it."""
        return float(((self.meta.get("robot") or {}).get("base_pose_xy_yaw") or [0.0, 0.0, 0.0])[2])

    def robot_base(self) -> tuple[float, float] | None:
        """World xy of the robot's base, when the scene records it ("nearest you" is nearest to it)."""
        pose = (self.meta.get("robot") or {}).get("base_pose_xy_yaw")
        return (float(pose[0]), float(pose[1])) if pose else None

    def ee_pos(self) -> Sequence[float]:
        pos, _ = self.robot.tcp_pose()
        return [float(v) for v in pos]

    def home_error(self) -> float:
        return float(np.abs(self.data.qpos[self.robot.qadr] - np.array(self.robot_description.home_arm)).max())

    def at_home(self) -> bool:
        return self.home_error() < HOME_TOLERANCE

    def joint_position(self, name: str) -> float:
        """Opening of the articulated body ``name``: its first joint's position (m or rad)."""
        self._check(name)
        b = self.model.body(name).id
        j = self.model.body_jntadr[b]
        if j < 0 or int(self.model.jnt_type[j]) not in (mujoco.mjtJoint.mjJNT_SLIDE, mujoco.mjtJoint.mjJNT_HINGE):
            raise KeyError(f"{name} has no hinge or slide joint")
        return float(self.data.qpos[self.model.jnt_qposadr[j]])

    # --- state snapshots (for tests and logs) -------------------------------------------------
    def state(self) -> dict[str, list[float]]:
        """Body positions of the objects (origin, not bbox), rounded; for logs and comparisons."""
        return {n: [round(float(v), 5) for v in self.data.xpos[self.model.body(n).id]] for n in self.object_names()}
