"""Compose the MJCF with ``mujoco.MjSpec``: options, arena, objects and a capture camera.

Mesh files are attached to the spec as in-memory assets (``spec.assets``) under the names they
get in ``assets/``, so the spec compiles before anything is written and the written
``scene.xml`` refers to them by relative path.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np
import trimesh
from scipy.spatial.transform import Rotation

from realsim.composition.appearance import (
    AppearanceParams,
    CaptureImage,
    capture_image,
    colour_object_from_points,
    follow_captured_surface,
    projected_texture,
    support_mask,
    support_top,
    textured_mesh,
    top_view_texture,
)
from realsim.composition.arena import ArenaParams, add_arena
from realsim.composition.backdrop import Backdrop, BackdropParams, build_backdrop
from realsim.composition.backdrop_ahead import cloud_backdrop, cloud_layers
from realsim.composition.object_meshes import collision_file, mesh_bytes, object_meshes
from realsim.forkmap import Ahead
from realsim.perception.capture_camera import capture_intrinsics
from realsim.scene import Scene, SceneObject
from realsim.scene_format import ASSET_DIR, COLLISION_GROUP, VISUAL_GROUP


@dataclass(frozen=True)
class ComposeParams:
    """Parameters of MJCF composition."""

    timestep: float = 0.002
    sleep: bool = True  # MuJoCo's island sleeping in the written scene (settling and rest checks run awake)
    # a tree sleeps once every dof moves slower than this (m/s at the body's size) for 10 steps; MuJoCo's 1 mm/s
    # kept a mug rocking on its 3-point contact awake for good (bench/bench_sim.py: robot x 1.28 at 5 mm/s)
    sleep_tolerance: float = 0.005
    object_condim: int = 4
    default_density: float = 300.0  # kg/m^3 for scan objects without a manifest
    min_mass: float = 0.02
    max_mass: float = 5.0
    arena: ArenaParams = ArenaParams()
    appearance: AppearanceParams = AppearanceParams()
    backdrop: BackdropParams = BackdropParams()
    # Lights: textures baked from the capture already hold its light, so they are mostly emissive and
    # the lights modest (ambient + emission ~ 0.85, a little shading on top; measured by bench_fidelity).
    baked_emission: float = 0.45
    headlight_ambient: float = 0.4
    headlight_diffuse: float = 0.15
    sun_diffuse: float = 0.15


def new_spec(params: ComposeParams) -> mujoco.MjSpec:
    """An empty spec with realsim's physics options and rendering defaults."""
    spec = mujoco.MjSpec()
    spec.modelname = "realsim_scene"
    spec.meshdir = ASSET_DIR
    spec.texturedir = ASSET_DIR
    spec.option.timestep = params.timestep
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.option.impratio = 10.0
    if params.sleep:  # bodies at rest are skipped until something touches them (measured: bench/bench_sim.py)
        spec.option.enableflags |= int(mujoco.mjtEnableBit.mjENBL_SLEEP)
        spec.option.sleep_tolerance = params.sleep_tolerance
    spec.visual.global_.offwidth = 1280
    spec.visual.global_.offheight = 960
    spec.visual.headlight.ambient = [params.headlight_ambient] * 3
    spec.visual.headlight.diffuse = [params.headlight_diffuse] * 3
    spec.visual.headlight.specular = [0.1] * 3
    spec.worldbody.add_light(name="sun", pos=[0, 0, 4], dir=[0, 0, -1], type=mujoco.mjtLightType.mjLIGHT_DIRECTIONAL,
                             diffuse=[params.sun_diffuse] * 3, specular=[0.1] * 3, castshadow=0)
    return spec


def add_baked_material(spec: mujoco.MjSpec, name: str, png: bytes, assets: dict[str, bytes], emission: float) -> str:
    """A material textured with ``png``: colours baked from the capture, matte, partly emissive so
    they read as photographed under the scene's modest lights. Returns its name."""
    file = f"{name}_texture.png"
    assets[file] = png
    spec.add_texture(name=f"{name}_texture", file=file, type=mujoco.mjtTexture.mjTEXTURE_2D)
    mat = spec.add_material(name=f"{name}_material", emission=emission, specular=0.0, shininess=0.0, reflectance=0.0)
    mat.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = f"{name}_texture"
    return mat.name


def add_visual_mesh(spec: mujoco.MjSpec, body: mujoco.MjsBody, name: str, mesh: trimesh.Trimesh, assets: dict[str, bytes],
                    material: str = "", rgba: list[float] | None = None) -> None:
    """A visual-only mesh geom (group 2, no contacts, no mass); open surfaces get shell inertia."""
    file = f"{name}.obj"
    assets[file] = mesh_bytes(mesh, "obj")
    m = spec.add_mesh(name=name, file=file)
    if not mesh.is_volume:
        m.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL
    body.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_MESH, meshname=name, group=VISUAL_GROUP, contype=0, conaffinity=0,
                  density=0.0, rgba=rgba or [1.0, 1.0, 1.0, 1.0], material=material)


def _mass_properties(obj: SceneObject, params: ComposeParams) -> tuple[float, np.ndarray, np.ndarray]:
    """Mass, centre of mass and inertia (about the com, object frame) of an object."""
    if obj.mass is not None and obj.com is not None and obj.inertia is not None:
        return obj.mass, obj.com, obj.inertia
    solid = trimesh.util.concatenate(obj.collision) if len(obj.collision) > 1 else obj.collision[0]
    volume = max(sum(abs(h.volume) for h in obj.collision), 1e-7)
    mass = float(np.clip(volume * params.default_density, params.min_mass, params.max_mass))
    com = solid.center_mass if solid.is_volume else solid.bounds.mean(axis=0)
    if solid.is_volume:
        inertia = solid.moment_inertia * (mass / max(solid.mass, 1e-12))
    else:
        ext = solid.extents
        inertia = np.diag(mass / 12.0 * np.array([ext[1] ** 2 + ext[2] ** 2, ext[0] ** 2 + ext[2] ** 2, ext[0] ** 2 + ext[1] ** 2]))
    obj.mass, obj.com, obj.inertia = mass, np.asarray(com), np.asarray(inertia)
    return obj.mass, obj.com, obj.inertia


JOINT_TYPES = {"slide": mujoco.mjtJoint.mjJNT_SLIDE, "hinge": mujoco.mjtJoint.mjJNT_HINGE}
PRIMITIVES = {"box": mujoco.mjtGeom.mjGEOM_BOX, "cylinder": mujoco.mjtGeom.mjGEOM_CYLINDER, "sphere": mujoco.mjtGeom.mjGEOM_SPHERE}


def add_object(spec: mujoco.MjSpec, obj: SceneObject, params: ComposeParams, assets: dict[str, bytes],
               parent: mujoco.MjsBody | None = None, joint: dict | None = None,
               collision_stl: list[bytes] | None = None) -> mujoco.MjsBody:
    """Add one free body: convex collision meshes (group 3), a visual mesh (group 2), inertia.

    With ``parent`` and ``joint`` (``{"type": "slide"|"hinge", "axis", "range", "pos", "damping"}``,
    optionally ``"handle"``, in the object frame) the body is instead a child of ``parent`` on that
    joint (a drawer in its cabinet), with a site ``<name>_handle`` where a hand pulls it; its world
    pose is still ``obj.position``/``obj.quat``. ``collision_stl``: the collision meshes' files when
    already made (see :func:`realsim.composition.object_meshes.object_meshes`).
    """
    if parent is None or joint is None:
        body = spec.worldbody.add_body(name=obj.name, pos=obj.position.tolist(), quat=obj.quat.tolist())
        body.add_freejoint(name=f"{obj.name}_joint")
    else:
        p_rot = Rotation.from_quat(np.roll(np.asarray(parent.quat, dtype=np.float64), -1))  # (w,x,y,z) -> scipy (x,y,z,w)
        c_rot = Rotation.from_quat(np.roll(obj.quat, -1))
        rel_pos = p_rot.inv().apply(obj.position - np.asarray(parent.pos, dtype=np.float64))
        rel_xyzw = (p_rot.inv() * c_rot).as_quat()
        body = parent.add_body(name=obj.name, pos=rel_pos.tolist(), quat=[rel_xyzw[3], *rel_xyzw[:3]])
        body.add_joint(name=f"{obj.name}_joint", type=JOINT_TYPES[joint["type"]], axis=list(joint["axis"]),
                       pos=list(joint.get("pos", [0.0, 0.0, 0.0])), range=list(joint["range"]),
                       limited=mujoco.mjtLimited.mjLIMITED_TRUE, damping=float(joint.get("damping", 1.0)))
        if joint.get("handle"):
            body.add_site(name=f"{obj.name}_handle", pos=list(joint["handle"]), size=[0.005, 0.005, 0.005], group=4)
    mass, com, inertia = _mass_properties(obj, params)
    body.mass = mass
    body.ipos = np.asarray(com).tolist()
    body.fullinertia = [inertia[0, 0], inertia[1, 1], inertia[2, 2], inertia[0, 1], inertia[0, 2], inertia[1, 2]]
    body.explicitinertial = True
    for i, hull in enumerate(obj.collision):
        primitive = hull.metadata.get("mujoco_primitive")  # realsim.assets.primitives: a box, cylinder or sphere
        if primitive is not None:
            shape = dict(type=PRIMITIVES[primitive["type"]], size=list(primitive["size"]), pos=list(primitive["pos"]), quat=list(primitive["quat"]))
        else:
            file = f"{obj.name}_collision_{i}.stl"
            assets[file] = collision_stl[i] if collision_stl is not None else collision_file(hull)
            spec.add_mesh(name=f"{obj.name}_collision_{i}", file=file)
            shape = dict(type=mujoco.mjtGeom.mjGEOM_MESH, meshname=f"{obj.name}_collision_{i}")
        body.add_geom(
            name=f"{obj.name}_collision_{i}",
            **shape,
            group=COLLISION_GROUP,
            contype=1,
            conaffinity=1,
            condim=params.object_condim,
            friction=list(obj.friction),
            solref=list(obj.solref),
            density=0.0,
            rgba=[0.8, 0.3, 0.3, 0.5],
        )
    if obj.visual is not None:
        _add_visual(spec, body, obj, assets, params)
    return body


def _add_visual(spec: mujoco.MjSpec, body: mujoco.MjsBody, obj: SceneObject, assets: dict[str, bytes], params: ComposeParams) -> None:
    if obj.texture_png is not None and obj.source_file is None:  # scanned: the capture's own colours
        material = add_baked_material(spec, obj.name, obj.texture_png, assets, params.baked_emission)
        add_visual_mesh(spec, body, f"{obj.name}_visual", obj.visual, assets, material)
        return
    file = f"{obj.name}_visual.obj"
    assets[file] = mesh_bytes(obj.visual, "obj")
    spec.add_mesh(name=f"{obj.name}_visual", file=file)
    rgba = [*np.clip(obj.color, 0, 1).tolist(), 1.0] if obj.color is not None else [0.7, 0.7, 0.7, 1.0]
    material = ""
    if obj.texture_png is not None:
        tex_file = f"{obj.name}_texture.png"
        assets[tex_file] = obj.texture_png
        spec.add_texture(name=f"{obj.name}_texture", file=tex_file, type=mujoco.mjtTexture.mjTEXTURE_2D)
        mat = spec.add_material(name=f"{obj.name}_material")
        mat.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = f"{obj.name}_texture"
        material = mat.name
        rgba = [1.0, 1.0, 1.0, 1.0]
    body.add_geom(
        name=f"{obj.name}_visual",
        type=mujoco.mjtGeom.mjGEOM_MESH,
        meshname=f"{obj.name}_visual",
        group=VISUAL_GROUP,
        contype=0,
        conaffinity=0,
        density=0.0,
        rgba=rgba,
        material=material,
    )


def add_capture_camera(spec: mujoco.MjSpec, scene: Scene) -> None:
    """A camera at the capture's viewpoint (optical frame +z forward, +y down)."""
    if not scene.capture.camera_view:
        return
    transform = scene.capture.input_to_world
    scale = np.cbrt(abs(np.linalg.det(transform[:3, :3])))
    rot_optical = transform[:3, :3] / scale
    rot_mujoco = rot_optical @ np.diag([1.0, -1.0, -1.0])  # MuJoCo cameras look along -z, y up
    quat_xyzw = Rotation.from_matrix(rot_mujoco).as_quat()
    cam = spec.worldbody.add_camera(name="capture", pos=transform[:3, 3].tolist(), quat=[quat_xyzw[3], *quat_xyzw[:3]], fovy=50.0)
    intr = capture_intrinsics(scene)
    if intr is not None:  # the capture's own intrinsics: renders line up with the photo pixel for pixel
        for key, value in intr.mujoco_camera().items():
            setattr(cam, key, value)


def _add_captured_surfaces(spec: mujoco.MjSpec, scene: Scene, image: CaptureImage, params: ComposeParams,
                           assets: dict[str, bytes], lows: dict[int, float]) -> dict[int, list[float]]:
    """Textured tops of the observed supports (following the captured surface; the lowest height of
    each in ``lows``) and the backdrop; returns the supports' mean colours."""
    exclude = np.isin(image.labels, [o.id for o in scene.objects])
    colours: dict[int, list[float]] = {}
    for plane in scene.planes:
        if not plane.observed:
            continue
        mask = support_mask(image, plane, params.appearance.support_tolerance)
        if not mask.any():
            continue
        exclude |= mask
        top = support_top(plane, params.appearance.support_cell, params.appearance.top_lift)
        if params.appearance.follow_surface:
            top = follow_captured_surface(top, plane, image, mask, params.appearance.top_lift)
        lows[plane.id] = float(top.vertices[:, 2].min()) - params.appearance.top_lift
        result = projected_texture(image, mask, image.pixels(top.vertices), params.appearance.margin_px)
        if result is None:
            continue
        png, uv = result
        top.visual = trimesh.visual.TextureVisuals(uv=uv)
        name = f"support{plane.id}_top"
        add_visual_mesh(spec, spec.worldbody, f"{name}_visual", top, assets, add_baked_material(spec, name, png, assets, params.baked_emission))
        colours[plane.id] = [*(np.median(image.rgb[mask], axis=0) / 255.0).tolist(), 1.0]
    backdrop = build_backdrop(image, exclude, params.backdrop)
    if backdrop is not None:
        _add_backdrop(spec, backdrop, params, assets)
    return colours


def _add_backdrop(spec: mujoco.MjSpec, backdrop: Backdrop, params: ComposeParams, assets: dict[str, bytes]) -> None:
    """The backdrop as one textured visual-only mesh in the world body."""
    material = add_baked_material(spec, "backdrop", backdrop.texture_png, assets, params.baked_emission)
    add_visual_mesh(spec, spec.worldbody, "backdrop_visual", backdrop.mesh, assets, material)


def _add_cloud_surfaces(spec: mujoco.MjSpec, scene: Scene, params: ComposeParams, assets: dict[str, bytes]) -> dict[int, list[float]]:
    """An unorganized capture's look: each observed support's top as seen from above (and its
    median colour for the box under it) and the backdrop of what is neither object nor support;
    returns the supports' colours. The objects' colours (with the capture's colours) and the
    backdrop are made here (the backdrop perhaps by a thread begun before completion:
    :mod:`realsim.composition.backdrop_ahead`) while a forked helper makes the tops' textures (:class:`Ahead`)."""
    layers = cloud_layers(scene, params.appearance, params.backdrop)
    points, colors, tops = layers.points, layers.colors, layers.tops
    with Ahead(lambda k: top_view_texture(tops[k][0], tops[k][1], points[tops[k][2], :2], colors[tops[k][2]]), len(tops)) as textures:
        if scene.colors is not None:  # no photo to project: the objects' colours from their points (those taken once)
            assert scene.labels is not None
            mine = np.isin(scene.labels, [o.id for o in scene.objects])
            taken = points[mine], colors[mine], scene.labels[mine]
            for obj in scene.objects:
                colour_object_from_points(obj, *taken, params.appearance)
        backdrop = cloud_backdrop(layers.backdrop)
        made = textures.results()
    colours: dict[int, list[float]] = {}
    for (plane, top, on), (png, uv) in zip(tops, made):
        colours[plane.id] = [*np.median(np.clip(colors[on], 0.0, 1.0), axis=0).tolist(), 1.0]
        top.visual = trimesh.visual.TextureVisuals(uv=uv)
        name = f"support{plane.id}_top"
        add_visual_mesh(spec, spec.worldbody, f"{name}_visual", top, assets, add_baked_material(spec, name, png, assets, params.baked_emission))
    if backdrop is not None:
        _add_backdrop(spec, backdrop, params, assets)
    return colours


def compose_scene(scene: Scene, params: ComposeParams = ComposeParams()) -> Scene:
    """Build the MjSpec of the scene (arena, objects, camera) and check it compiles."""
    spec = new_spec(params)
    assets: dict[str, bytes] = {}
    image = capture_image(scene) if params.appearance.enabled else None
    slabs: dict[int, list[float]] = {}
    lows: dict[int, float] = {}
    with object_meshes(scene, image, params.appearance) as ahead:  # by a helper (perhaps begun already), while this process does the surfaces
        if image is not None:
            slabs = _add_captured_surfaces(spec, scene, image, params, assets, lows)
        elif params.appearance.enabled and scene.points is not None and scene.labels is not None:  # unorganized: no photo
            slabs = _add_cloud_surfaces(spec, scene, params, assets)
        prepared = ahead.results()
    for obj, (texture, _) in zip(scene.objects, prepared):  # textures only with a photo
        if texture is not None:
            obj.visual, obj.texture_png = textured_mesh(*texture[:3]), texture[3]
    add_arena(spec, scene, params.arena, slabs)
    for pid, low in lows.items():  # a captured top dipping below its plane: the slab under it sinks with it (else it hides the dip)
        slab, dip = spec.geom(f"support{pid}_visual"), scene.plane(pid).height - low
        if slab is not None and dip > 0 and slab.size[2] > dip:
            slab.pos[2], slab.size[2] = slab.pos[2] - dip / 2, slab.size[2] - dip / 2
    articulations = scene.articulations  # child name -> joint (realsim.text)
    object_sites = scene.object_sites  # body name -> {site: [x, y, z]} (realsim.text)
    bodies: dict[str, mujoco.MjsBody] = {}
    for obj, (_, collision_stl) in zip(scene.objects, prepared):
        joint = articulations.get(obj.name)
        parent = bodies.get(joint["parent"]) if joint else None
        bodies[obj.name] = add_object(spec, obj, params, assets, parent, joint, collision_stl)
        for site, pos in (object_sites.get(obj.name) or {}).items():  # grasp features of procedural objects: <body>_handle, _rim, _lid, ...
            bodies[obj.name].add_site(name=f"{obj.name}_{site}", pos=list(pos), size=[0.005, 0.005, 0.005], group=4)
    add_capture_camera(spec, scene)
    spec.assets = assets
    scene.compiled = (spec, spec.compile())  # the robot stage reads the objects' poses from it
    scene.spec = spec
    scene.assets = assets
    return scene
