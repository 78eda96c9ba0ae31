"""The Franka Panda from MuJoCo Menagerie, attached to a scene spec with ``MjSpec.attach``.

The robot is attached under the prefix ``panda/`` at a base pose (x, y, yaw) on an optional box
pedestal, with a tool-centre site ``panda/tcp`` between the fingertip pads. Its meshes become
in-memory assets named ``panda_<file>`` so a written scene refers to them under ``assets/``.
The spec gets a ``home`` keyframe: the robot at its home posture, objects at their poses, and
the actuator controls that hold that posture (settle.py resets to it before settling).

The Menagerie is read only while converting. At run time everything about the robot comes from
the scene itself: :func:`describe_robot` reads the names, the home posture (keyframe ``home``)
and the gripper's range from the compiled scene (with the names scene.json records), and
:func:`robot_kinematics` copies the arm's kinematic chain out of it for IK.
"""

from __future__ import annotations

import functools
import os
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import trimesh

from realsim.cache import DiskCache, cache_key
from realsim.errors import InputError
from realsim.geometry import yaw_quat

PANDA_DIR = "franka_emika_panda"
PREFIX = "panda/"
ARM_JOINTS = tuple(f"joint{i}" for i in range(1, 8))
FINGER_JOINTS = ("finger_joint1", "finger_joint2")
ARM_ACTUATORS = tuple(f"actuator{i}" for i in range(1, 8))
GRIPPER_ACTUATOR = "actuator8"
HOME_ARM = (0.0, 0.0, 0.0, -1.57079, 0.0, 1.57079, -0.7853)
GRIPPER_OPEN_CTRL = 255.0  # the Menagerie gripper maps ctrl 0..255 to opening 0..0.04 m per finger
GRIPPER_MAX_OPENING = 0.08  # m between the fingers, fully open
TCP_OFFSET = 0.1034  # m from the hand frame to the centre of the fingertip pads (hand z axis)
BASE_FOOTPRINT = 0.14  # m, half side of a square that covers link0 (and the pedestal top)
PEDESTAL_NAME = "robot_pedestal"


@dataclass(frozen=True)
class GripperParams:
    """Stiffer gripper than the Menagerie default (whose ~2 N squeeze drops 0.5 kg objects)."""

    stiffness: float = 1500.0  # N per m of tendon (Menagerie: 100)
    damping: float = 60.0  # N s/m (Menagerie: 10)
    max_force: float = 70.0  # N (Franka Hand: 70 N continuous)
    closed_target: float = -0.02  # m of tendon the closed command aims past closed: a thin part is squeezed too (~19 N a pad at 1 cm, not ~4 N)
    # the fingertip pads' contacts: MuJoCo's contact stiffness is per unit of the contact's effective
    # mass, so at the default 0.02 s a light part squeezed at tens of N lets the pads sink millimetres
    # into it (pinching a 178 g pitcher's handle, the pads closed from 9.8 to 4.4 mm apart while it was
    # carried, and it slipped out); the Franka's firm rubber pads on rigid fingers give well under a millimetre.
    pad_solref: tuple[float, float] = (0.01, 1.0)  # s, damping ratio: 4x stiffer, still 5 steps of 2 ms
    pad_solimp: tuple[float, float, float, float, float] = (0.95, 0.99, 0.001, 0.5, 2.0)  # as the Menagerie's finger coupling
    pad_solmix: float = 1000.0  # the pads' solref/solimp govern their contacts (friction stays the larger of the two geoms')


@dataclass(frozen=True)
class RobotNames:
    """The names of the robot's elements in a composed or compiled scene."""

    prefix: str
    base_body: str
    tcp_site: str
    hand_body: str
    finger_bodies: tuple[str, str]
    arm_joints: tuple[str, ...]
    finger_joints: tuple[str, ...]
    arm_actuators: tuple[str, ...]
    gripper_actuator: str


@dataclass(frozen=True)
class RobotHandles(RobotNames):
    """The attached robot in the composed model: its names, where it stands, its mesh assets."""

    base_pose: tuple[float, float, float] = (0.0, 0.0, 0.0)  # x, y, yaw
    base_z: float = 0.0  # z of link0 (top of the pedestal)
    pedestal_height: float = 0.0
    home_key: str = "home"
    assets: dict[str, bytes] = field(default_factory=dict, repr=False)
    model: Any = field(default=None, repr=False, compare=False)  # mujoco.MjModel: the spec compiled as attach_robot left it

    def record(self) -> dict[str, Any]:
        """What scene.json records about the robot: the names the runtime looks up in scene.xml."""
        names = {f.name: getattr(self, f.name) for f in fields(RobotNames)}
        return {
            **{k: list(v) if isinstance(v, tuple) else v for k, v in names.items()},
            "home_key": self.home_key,
            "home_arm": list(HOME_ARM),
            "gripper_open_ctrl": GRIPPER_OPEN_CTRL,
            "gripper_max_opening": GRIPPER_MAX_OPENING,
        }


@dataclass(frozen=True)
class RobotDescription(RobotNames):
    """The robot of a compiled scene, read from the scene alone (never from the Menagerie)."""

    home_arm: tuple[float, ...] = ()  # from keyframe ``home_key``
    arm_limits: tuple[tuple[float, float], ...] = ()  # joint ranges (rad)
    gripper_open_ctrl: float = 0.0  # upper end of the gripper actuator's ctrlrange
    gripper_max_opening: float = 0.0  # m between the fingers, from the finger joints' ranges


def menagerie_panda_dir() -> Path:
    """The ``franka_emika_panda`` folder: ``$MENAGERIE_ROOT`` first, else the mujoco_menagerie package."""
    root = os.environ.get("MENAGERIE_ROOT")
    if root:
        folder = Path(root).expanduser() / PANDA_DIR
        if (folder / "panda.xml").is_file():
            return folder
        raise InputError(f"MENAGERIE_ROOT={root}: no {PANDA_DIR}/panda.xml there; point MENAGERIE_ROOT at a folder holding {PANDA_DIR}/")
    try:
        import mujoco_menagerie

        folder = Path(mujoco_menagerie.get(PANDA_DIR).path(progress=None))
    except Exception as exc:  # ImportError, download or registry errors
        raise InputError(
            f"the Franka Panda model could not be located ({type(exc).__name__}: {exc}); install mujoco-menagerie with "
            f"internet access once, or set MENAGERIE_ROOT to a folder holding {PANDA_DIR}/"
        ) from exc
    if not (folder / "panda.xml").is_file():
        raise InputError(f"{folder}: no panda.xml in the Menagerie download; set MENAGERIE_ROOT to a folder holding {PANDA_DIR}/")
    return folder


def panda_spec(gripper: GripperParams = GripperParams()) -> tuple[mujoco.MjSpec, dict[str, bytes]]:
    """The Menagerie Panda (with hand) as a spec with in-memory mesh assets, a ``tcp`` site and
    gravity compensation; returns (spec, assets by file name)."""
    folder = menagerie_panda_dir()
    spec = mujoco.MjSpec.from_file(str(folder / "panda.xml"))
    assets: dict[str, bytes] = {}
    mesh_dir = folder / (spec.meshdir or "")
    for mesh in spec.meshes:
        path = mesh_dir / mesh.file
        stat = path.stat()
        name, data = _mesh_asset(str(path), stat.st_size, stat.st_mtime_ns)
        assets[name] = data
        mesh.file = name
    spec.meshdir = ""
    spec.assets = assets
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    for light in list(spec.lights):
        spec.delete(light)
    hand = spec.body("hand")
    hand.add_site(name="tcp", pos=[0.0, 0.0, TCP_OFFSET], size=[0.006, 0.006, 0.006], group=4, rgba=[1, 0, 0, 0.6])
    for body in spec.bodies:
        if body.name != "world":
            body.gravcomp = 1.0
    for finger in ("left_finger", "right_finger"):
        for geom in spec.body(finger).geoms:
            if geom.classname.name.startswith("fingertip_pad_collision"):
                geom.solref, geom.solimp, geom.solmix = list(gripper.pad_solref), list(gripper.pad_solimp), gripper.pad_solmix
    act = spec.actuator(GRIPPER_ACTUATOR)
    act.gainprm[0] = (0.04 - gripper.closed_target) * gripper.stiffness / 255.0
    act.biasprm[0] = gripper.closed_target * gripper.stiffness
    act.biasprm[1] = -gripper.stiffness
    act.biasprm[2] = -gripper.damping
    act.forcerange = [-gripper.max_force, gripper.max_force]
    return spec, assets


@functools.lru_cache(maxsize=256)
def _mesh_asset(path: str, size: int, mtime_ns: int) -> tuple[str, bytes]:
    """(asset name, bytes) of one Menagerie mesh file: an OBJ as binary STL (on-disk cache keyed by
    its content), anything else as it is. Kept in process per file size and modification time, so
    each conversion does not read and hash the Panda's meshes again."""
    file = Path(path)
    if file.suffix.lower() != ".obj":
        return f"panda_{file.name}", file.read_bytes()
    return f"panda_{file.stem}.stl", DiskCache().get_or_compute(cache_key("panda-mesh-stl", files=[file]), lambda: _binary_stl(file))


def _binary_stl(path: Path) -> bytes:
    """A mesh file as binary STL: MuJoCo parses it about ten times faster than the Menagerie's
    large OBJ visuals (0.13 s against 1.3-1.8 s for the whole Panda), at the same geometry."""
    mesh = trimesh.load(path, force="mesh", process=False)
    return trimesh.exchange.stl.export_stl(mesh)


def attach_robot(
    spec: mujoco.MjSpec,
    base_pos_xy_yaw: tuple[float, float, float],
    base_z: float = 0.0,
    pedestal_height: float = 0.0,
    prefix: str = PREFIX,
    gripper: GripperParams = GripperParams(),
) -> RobotHandles:
    """Attach the Panda to ``spec`` with its base at (x, y) and yaw, standing at ``base_z``.

    ``base_z`` is the floor under the robot; with ``pedestal_height`` > 0 a fixed box pedestal
    (collision group 3 plus a visual twin) lifts link0 to ``base_z + pedestal_height``. The
    robot's meshes are added to ``spec.assets``, and a ``home`` keyframe replaces any existing
    one (robot at home posture, gripper open, every other joint at its ``qpos0``). The handles'
    ``model`` is ``spec`` compiled as it is left here (the keyframe written into the compiled model
    too: the same MJB bytes as compiling ``spec`` again).
    """
    x, y, yaw = (float(v) for v in base_pos_xy_yaw)
    top = float(base_z) + max(float(pedestal_height), 0.0)
    child, assets = panda_spec(gripper)
    # its meshes resolve as the scene's own (and as they will from the written scene.xml), so MuJoCo's
    # asset cache serves the written scene's compile check with the meshes processed here
    child.modelfiledir, child.meshdir = spec.modelfiledir, spec.meshdir
    if pedestal_height > 0:
        half = [BASE_FOOTPRINT, BASE_FOOTPRINT, pedestal_height / 2]
        pos = [x, y, base_z + pedestal_height / 2]
        common = dict(type=mujoco.mjtGeom.mjGEOM_BOX, size=half, pos=pos, quat=yaw_quat(yaw).tolist())
        spec.worldbody.add_geom(name=f"{PEDESTAL_NAME}_collision", group=3, contype=1, conaffinity=1, rgba=[0.4, 0.6, 0.8, 0.3], **common)
        spec.worldbody.add_geom(name=f"{PEDESTAL_NAME}_visual", group=2, contype=0, conaffinity=0, rgba=[0.2, 0.2, 0.22, 1.0], **common)
    frame = spec.worldbody.add_frame(pos=[x, y, top], quat=yaw_quat(yaw).tolist())
    spec.attach(child, prefix=prefix, frame=frame)
    spec.assets = {**spec.assets, **assets}
    for mesh in spec.meshes:  # attach prefixes file names too; keep the flat assets/ layout
        if mesh.file.startswith(prefix) and mesh.file[len(prefix):] in assets:
            mesh.file = mesh.file[len(prefix):]
    for key in list(spec.keys):
        if key.name in ("home", f"{prefix}home"):
            spec.delete(key)
    home = spec.add_key(name="home")  # at qpos0 until its values, which need the compiled layout, are known
    model = spec.compile()
    qpos = model.qpos0.copy()
    for name, value in zip(ARM_JOINTS, HOME_ARM):
        qpos[model.jnt_qposadr[model.joint(prefix + name).id]] = value
    for name in FINGER_JOINTS:
        qpos[model.jnt_qposadr[model.joint(prefix + name).id]] = GRIPPER_MAX_OPENING / 2
    ctrl = np.zeros(model.nu)
    for name, value in zip(ARM_ACTUATORS, HOME_ARM):
        ctrl[model.actuator(prefix + name).id] = value
    ctrl[model.actuator(prefix + GRIPPER_ACTUATOR).id] = GRIPPER_OPEN_CTRL
    home.qpos, home.qvel, home.ctrl = qpos.tolist(), np.zeros(model.nv).tolist(), ctrl.tolist()
    k = model.key("home").id
    model.key_qpos[k], model.key_qvel[k], model.key_ctrl[k] = qpos, 0.0, ctrl
    return RobotHandles(
        prefix=prefix,
        base_body=prefix + "link0",
        tcp_site=prefix + "tcp",
        hand_body=prefix + "hand",
        finger_bodies=(prefix + "left_finger", prefix + "right_finger"),
        arm_joints=tuple(prefix + j for j in ARM_JOINTS),
        finger_joints=tuple(prefix + j for j in FINGER_JOINTS),
        arm_actuators=tuple(prefix + a for a in ARM_ACTUATORS),
        gripper_actuator=prefix + GRIPPER_ACTUATOR,
        base_pose=(x, y, yaw),
        base_z=top,
        pedestal_height=max(float(pedestal_height), 0.0),
        assets=assets,
        model=model,
    )


def robot_only_model(base_pos: np.ndarray, base_quat: np.ndarray, gripper: GripperParams = GripperParams()) -> mujoco.MjModel:
    """The Panda alone at a base pose (world frame): the kinematic model IK works on."""
    child, assets = panda_spec(gripper)
    spec = mujoco.MjSpec()
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    frame = spec.worldbody.add_frame(pos=np.asarray(base_pos, float).tolist(), quat=np.asarray(base_quat, float).tolist())
    spec.attach(child, prefix=PREFIX, frame=frame)
    spec.assets = assets
    for key in list(spec.keys):
        spec.delete(key)
    return spec.compile()


def describe_robot(model: mujoco.MjModel, record: dict[str, Any] | None = None) -> RobotDescription:
    """The robot in ``model`` by the names in ``record`` (scene.json's ``robot``; the Panda's names
    under ``panda/`` when absent). Raises :class:`InputError` naming an element the scene lacks."""
    rec = dict(record or {})
    prefix = str(rec.get("prefix") or PREFIX)

    def names(key: str, default: tuple[str, ...]) -> tuple[str, ...]:
        return tuple(str(n) for n in rec.get(key) or (prefix + n for n in default))

    def one(key: str, default: str) -> str:
        return str(rec.get(key) or prefix + default)

    def need(kind: mujoco.mjtObj, name: str, what: str) -> int:
        i = mujoco.mj_name2id(model, kind, name)
        if i < 0:
            raise InputError(f"the scene has no {what} '{name}' (scene.json names it); convert the scene again")
        return i

    arm = names("arm_joints", ARM_JOINTS)
    fingers = names("finger_joints", FINGER_JOINTS)
    finger_bodies = names("finger_bodies", ("left_finger", "right_finger"))
    gripper = one("gripper_actuator", GRIPPER_ACTUATOR)
    base, tcp, hand = one("base_body", "link0"), one("tcp_site", "tcp"), one("hand_body", "hand")
    for body in (base, hand, *finger_bodies):
        need(mujoco.mjtObj.mjOBJ_BODY, body, "robot body")
    need(mujoco.mjtObj.mjOBJ_SITE, tcp, "tool-centre site")
    joints = [need(mujoco.mjtObj.mjOBJ_JOINT, j, "robot joint") for j in arm + fingers]
    actuators = names("arm_actuators", ARM_ACTUATORS)
    for a in actuators:
        need(mujoco.mjtObj.mjOBJ_ACTUATOR, a, "robot actuator")
    grip = need(mujoco.mjtObj.mjOBJ_ACTUATOR, gripper, "gripper actuator")
    qadr = [int(model.jnt_qposadr[j]) for j in joints[: len(arm)]]
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, str(rec.get("home_key") or "home"))
    if key >= 0:
        home = tuple(float(v) for v in model.key_qpos[key][qadr])
    elif rec.get("home_arm"):
        home = tuple(float(v) for v in rec["home_arm"])
    else:
        raise InputError("the scene has no 'home' keyframe for the robot; convert the scene again")
    finger_upper = [float(model.jnt_range[j][1]) for j in joints[len(arm):]]
    ctrl_upper = float(model.actuator_ctrlrange[grip][1]) if model.actuator_ctrllimited[grip] else float(rec.get("gripper_open_ctrl", GRIPPER_OPEN_CTRL))
    return RobotDescription(
        prefix=prefix, base_body=base, tcp_site=tcp, hand_body=hand, finger_bodies=(finger_bodies[0], finger_bodies[1]),
        arm_joints=arm, finger_joints=fingers, arm_actuators=actuators, gripper_actuator=gripper, home_arm=home,
        arm_limits=tuple((float(model.jnt_range[j][0]), float(model.jnt_range[j][1])) for j in joints[: len(arm)]),
        gripper_open_ctrl=ctrl_upper, gripper_max_opening=float(sum(finger_upper)) or GRIPPER_MAX_OPENING,
    )


def robot_kinematics(scene: mujoco.MjModel, base_body: str = PREFIX + "link0") -> mujoco.MjModel:
    """The robot's kinematic tree copied out of a compiled scene, its base at the world origin.

    Bodies (with their inertia), joints (axes, ranges) and sites of ``base_body``'s subtree keep
    their names, so IK built for the Menagerie model runs on it unchanged; geoms, actuators and
    everything else are left out. Nothing is read from outside the scene.
    """
    root = mujoco.mj_name2id(scene, mujoco.mjtObj.mjOBJ_BODY, base_body)
    if root < 0:
        raise InputError(f"the scene has no robot base body '{base_body}'")
    spec = mujoco.MjSpec()
    spec.modelname = "robot_kinematics"
    spec.compiler.degree = False  # the compiled scene's ranges are radians
    made: dict[int, mujoco.MjsBody] = {}
    for b in range(root, scene.nbody):  # depth-first order: a subtree is contiguous after its root
        if b != root and int(scene.body_parentid[b]) not in made:
            break
        parent = spec.worldbody if b == root else made[int(scene.body_parentid[b])]
        body = parent.add_body(name=scene.body(b).name)
        if b != root:
            body.pos, body.quat = scene.body_pos[b].tolist(), scene.body_quat[b].tolist()
        body.mass = float(scene.body_mass[b])
        body.ipos, body.iquat = scene.body_ipos[b].tolist(), scene.body_iquat[b].tolist()
        body.inertia = scene.body_inertia[b].tolist()
        body.explicitinertial = True
        for j in range(int(scene.body_jntadr[b]), int(scene.body_jntadr[b] + scene.body_jntnum[b])):
            limited = mujoco.mjtLimited.mjLIMITED_TRUE if scene.jnt_limited[j] else mujoco.mjtLimited.mjLIMITED_FALSE
            body.add_joint(name=scene.joint(j).name, type=mujoco.mjtJoint(int(scene.jnt_type[j])), axis=scene.jnt_axis[j].tolist(),
                           pos=scene.jnt_pos[j].tolist(), range=scene.jnt_range[j].tolist(), limited=limited)
        made[b] = body
    for s in range(scene.nsite):
        if int(scene.site_bodyid[s]) in made:
            made[int(scene.site_bodyid[s])].add_site(name=scene.site(s).name, pos=scene.site_pos[s].tolist(),
                                                     quat=scene.site_quat[s].tolist())
    return spec.compile()
