"""Export a scene folder as a USD stage with UsdPhysics (usd-core).

The stage is Z-up in metres and kilograms, like MuJoCo. Geometry and poses come from the
*compiled* model at keyframe ``initial``: every object becomes a rigid body (``RigidBodyAPI``
+ ``MassAPI`` with MuJoCo's mass, centre of mass, principal inertia and principal axes), its
convex hulls are collision meshes (``CollisionAPI`` + ``MeshCollisionAPI`` approximation
``convexHull``, purpose ``guide`` so renderers hide them), its visual mesh gets a
``UsdPreviewSurface`` material with the texture or colour. The world's collision geoms (floor,
supports, walls, pedestal) are static colliders and the world's visual geoms their visible
twins. The robot is left out (see ``ROBOT_NOTE``).
"""

from __future__ import annotations

import os
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from realsim.destination import build_folder, check_destination, check_file_destination, normal_permissions, publish
from realsim.errors import InputError
from realsim.export.mjcf import _resolve, load_spec, object_bodies
from realsim.scene_format import KEYFRAME, ROBOT_PREFIX, VISUAL_GROUP

ROBOT_NOTE = (
    "The Franka Panda of the MJCF scene is not exported: its actuated joints and mimic-driven gripper "
    "have no faithful UsdPhysics equivalent here. Use an official Panda USD asset (e.g. Isaac Sim's "
    "franka.usd) and place its base at the pose recorded in realsim:robotBase."
)
PLANE_EXTENT = 20.0  # metres: the size given to MuJoCo's infinite planes


@dataclass
class UsdExport:
    """What :func:`export_usd` wrote."""

    path: Path
    rigid_bodies: list[str]
    static_colliders: list[str]
    textures: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)


def _pxr() -> Any:
    try:
        from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics, UsdShade, Vt  # noqa: F401
    except ImportError:  # pragma: no cover - a declared dependency
        raise InputError("USD export needs usd-core: pip install usd-core") from None
    import pxr

    return pxr


def usd_name(name: str) -> str:
    """A valid USD prim name for a MuJoCo element name (``panda/link0`` -> ``panda_link0``)."""
    out = "".join(c if c.isalnum() or c == "_" else "_" for c in name) or "unnamed"
    return out if not out[0].isdigit() else f"_{out}"


def _set_pose(xformable: Any, pos: np.ndarray, quat_wxyz: np.ndarray, scale: np.ndarray | None = None) -> None:
    from pxr import Gf, UsdGeom

    xformable.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*map(float, pos)))
    w, x, y, z = (float(v) for v in quat_wxyz)
    xformable.AddOrientOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Quatd(w, Gf.Vec3d(x, y, z)))
    if scale is not None:
        xformable.AddScaleOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*map(float, scale)))


class _Writer:
    """Stateful helper: one stage, one compiled model, a cache of materials."""

    def __init__(self, stage: Any, model: mujoco.MjModel, spec: mujoco.MjSpec, src_dir: Path, tex_dir: Path, tex_rel: str) -> None:
        self.stage, self.model, self.spec, self.src_dir = stage, model, spec, src_dir
        self.tex_dir, self.tex_rel = tex_dir, tex_rel
        self.materials: dict[tuple[Any, ...], Any] = {}
        self.textures: list[str] = []

    # --- geometry ----------------------------------------------------------------------------
    def geom(self, path: str, g: int, collider: bool) -> Any:
        """A prim for geom ``g`` at ``path`` in its body's frame, or None for unsupported types."""
        from pxr import Gf, UsdGeom, UsdPhysics, Vt

        m = self.model
        gtype = m.geom_type[g]
        size = m.geom_size[g]
        T = mujoco.mjtGeom
        scale = None
        if gtype == T.mjGEOM_MESH:
            prim = UsdGeom.Mesh.Define(self.stage, path)
            mesh = m.geom_dataid[g]
            v0, nv = m.mesh_vertadr[mesh], m.mesh_vertnum[mesh]
            f0, nf = m.mesh_faceadr[mesh], m.mesh_facenum[mesh]
            verts = m.mesh_vert[v0 : v0 + nv]
            faces = m.mesh_face[f0 : f0 + nf]
            prim.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(verts.astype(np.float32)))
            prim.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(nf, 3, dtype=np.int32)))
            prim.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(faces.reshape(-1).astype(np.int32)))
            prim.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
            lo, hi = verts.min(axis=0), verts.max(axis=0)
            prim.CreateExtentAttr([Gf.Vec3f(*map(float, lo)), Gf.Vec3f(*map(float, hi))])
            if not collider and m.mesh_texcoordnum[mesh] > 0:
                t0 = m.mesh_texcoordadr[mesh]
                uv = m.mesh_texcoord[t0 : t0 + m.mesh_texcoordnum[mesh]].copy()
                uv[:, 1] = 1.0 - uv[:, 1]  # MuJoCo flips v when it loads a mesh; USD's st is OpenGL-style
                corner = m.mesh_facetexcoord[f0 : f0 + nf].reshape(-1)
                st = UsdGeom.PrimvarsAPI(prim).CreatePrimvar("st", _sdf().ValueTypeNames.TexCoord2fArray, UsdGeom.Tokens.faceVarying)
                st.Set(Vt.Vec2fArray.FromNumpy(uv[corner].astype(np.float32)))
        elif gtype == T.mjGEOM_BOX:
            prim = UsdGeom.Cube.Define(self.stage, path)
            prim.CreateSizeAttr(2.0)
            scale = size[:3]
        elif gtype == T.mjGEOM_PLANE:
            prim = UsdGeom.Plane.Define(self.stage, path)
            prim.CreateAxisAttr(UsdGeom.Tokens.z)
            sx = 2 * size[0] if size[0] > 0 else PLANE_EXTENT
            sy = 2 * size[1] if size[1] > 0 else PLANE_EXTENT
            prim.CreateWidthAttr(float(sx))
            prim.CreateLengthAttr(float(sy))
        elif gtype == T.mjGEOM_SPHERE:
            prim = UsdGeom.Sphere.Define(self.stage, path)
            prim.CreateRadiusAttr(float(size[0]))
        elif gtype in (T.mjGEOM_CYLINDER, T.mjGEOM_CAPSULE):
            prim = (UsdGeom.Cylinder if gtype == T.mjGEOM_CYLINDER else UsdGeom.Capsule).Define(self.stage, path)
            prim.CreateAxisAttr(UsdGeom.Tokens.z)
            prim.CreateRadiusAttr(float(size[0]))
            prim.CreateHeightAttr(float(2 * size[1]))
        else:
            return None
        _set_pose(prim, m.geom_pos[g], m.geom_quat[g], scale)
        if collider:
            UsdPhysics.CollisionAPI.Apply(prim.GetPrim())
            if gtype == T.mjGEOM_MESH:
                UsdPhysics.MeshCollisionAPI.Apply(prim.GetPrim()).CreateApproximationAttr(UsdPhysics.Tokens.convexHull)
            prim.CreatePurposeAttr(UsdGeom.Tokens.guide)
        else:
            self.bind_material(prim, g)
        return prim

    # --- materials ---------------------------------------------------------------------------
    def _texture_file(self, g: int) -> str | None:
        m = self.model
        mat = m.geom_matid[g]
        if mat < 0:
            return None
        tex = m.mat_texid[mat, mujoco.mjtTextureRole.mjTEXROLE_RGB]
        if tex < 0:
            return None
        source = self.spec.texture(m.tex(tex).name)
        if source is None or not source.file:
            return None  # builtin (procedural) textures: use the colour
        src = _resolve(self.src_dir, self.spec.texturedir, source.file)
        if not src.is_file():
            return None
        name = src.name
        if name not in self.textures:
            self.tex_dir.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(src, self.tex_dir / name)
            self.textures.append(name)
        return f"./{self.tex_rel}/{name}"

    def bind_material(self, prim: Any, g: int) -> None:
        from pxr import Gf, Sdf, UsdShade

        m = self.model
        rgba = m.geom_rgba[g].copy()
        if m.geom_matid[g] >= 0:
            if np.allclose(rgba, [0.5, 0.5, 0.5, 1.0]):  # MuJoCo: an unset geom colour defers to the material's
                rgba = m.mat_rgba[m.geom_matid[g]].copy()
        texture = self._texture_file(g)
        key = (tuple(np.round(rgba, 4)), texture)
        material = self.materials.get(key)
        if material is None:
            path = f"/World/Looks/material_{len(self.materials)}"
            material = UsdShade.Material.Define(self.stage, path)
            shader = UsdShade.Shader.Define(self.stage, f"{path}/PreviewSurface")
            shader.CreateIdAttr("UsdPreviewSurface")
            shader.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(0.6)
            shader.CreateInput("opacity", Sdf.ValueTypeNames.Float).Set(float(rgba[3]))
            diffuse = shader.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f)
            if texture is not None:
                reader = UsdShade.Shader.Define(self.stage, f"{path}/stReader")
                reader.CreateIdAttr("UsdPrimvarReader_float2")
                reader.CreateInput("varname", Sdf.ValueTypeNames.Token).Set("st")
                tex = UsdShade.Shader.Define(self.stage, f"{path}/diffuseTexture")
                tex.CreateIdAttr("UsdUVTexture")
                tex.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(texture)
                tex.CreateInput("st", Sdf.ValueTypeNames.Float2).ConnectToSource(reader.ConnectableAPI(), "result")
                tex.CreateOutput("rgb", Sdf.ValueTypeNames.Float3)
                diffuse.ConnectToSource(tex.ConnectableAPI(), "rgb")
            else:
                diffuse.Set(Gf.Vec3f(*map(float, rgba[:3])))
            material.CreateSurfaceOutput().ConnectToSource(shader.ConnectableAPI(), "surface")
            self.materials[key] = material
        UsdShade.MaterialBindingAPI.Apply(prim.GetPrim()).Bind(material)


def _sdf() -> Any:
    from pxr import Sdf

    return Sdf


def export_usd(source: Path, dest: Path | str, robot_prefix: str = ROBOT_PREFIX, *, force: bool = False) -> UsdExport:
    """Write the scene of output folder ``source`` to the USD file ``dest`` (.usda/.usd/.usdc).

    Poses are those of keyframe ``initial``. Texture images are copied to ``<dest stem>_textures/``
    next to the stage and referenced by relative path. The file is written to a temporary name
    and renamed into place.
    """
    pxr = _pxr()
    Gf, Usd, UsdGeom, UsdPhysics = pxr.Gf, pxr.Usd, pxr.UsdGeom, pxr.UsdPhysics
    if Path(dest).suffix.lower() not in (".usda", ".usd", ".usdc"):
        raise InputError(f"{dest}: a USD file name must end in .usda, .usd or .usdc")
    dest = check_file_destination(dest, inputs=[source], force=force)
    tex_rel = f"{dest.stem}_textures"
    if (dest.parent / tex_rel).exists():
        check_destination(dest.parent / tex_rel, inputs=[source], force=force)
    spec, src_dir = load_spec(source)
    model = spec.compile()
    data = mujoco.MjData(model)
    key = next((k for k in range(model.nkey) if model.key(k).name == KEYFRAME), None)
    warnings: list[str] = []
    if key is None:
        warnings.append(f"no keyframe '{KEYFRAME}': poses are the model's initial configuration")
        mujoco.mj_resetData(model, data)
    else:
        mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_kinematics(model, data)

    dest.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(prefix=f".{dest.stem}.", suffix=dest.suffix, dir=dest.parent)
    os.close(fd)
    tmp = Path(tmp_name)
    tex_tmp = build_folder(dest.parent / tex_rel)
    try:
        stage = Usd.Stage.CreateNew(str(tmp))
        UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
        UsdGeom.SetStageMetersPerUnit(stage, 1.0)
        UsdPhysics.SetStageKilogramsPerUnit(stage, 1.0)
        world = UsdGeom.Xform.Define(stage, "/World")
        stage.SetDefaultPrim(world.GetPrim())
        physics = UsdPhysics.Scene.Define(stage, "/World/PhysicsScene")
        gravity = np.asarray(model.opt.gravity, dtype=float)
        magnitude = float(np.linalg.norm(gravity))
        direction = gravity / magnitude if magnitude > 0 else np.array([0.0, 0.0, -1.0])
        physics.CreateGravityDirectionAttr(Gf.Vec3f(*map(float, direction)))
        physics.CreateGravityMagnitudeAttr(magnitude)
        physics.GetPrim().SetCustomDataByKey("realsim:timestep", float(model.opt.timestep))

        writer = _Writer(stage, model, spec, src_dir, tex_tmp, tex_rel)
        # --- static environment: geoms of the world body ---------------------------------------
        UsdGeom.Scope.Define(stage, "/World/Environment")
        statics: list[str] = []
        robot_bodies = {b for b in range(model.nbody) if model.body(b).name.startswith(robot_prefix)}
        for g in range(model.ngeom):
            if model.geom_bodyid[g] != 0:
                continue
            name = usd_name(model.geom(g).name or f"geom{g}")
            collider = bool(model.geom_contype[g] or model.geom_conaffinity[g])
            if not collider and model.geom_group[g] != VISUAL_GROUP:
                continue
            prim = writer.geom(f"/World/Environment/{name}", g, collider)
            if prim is not None and collider:
                statics.append(str(prim.GetPath()))
        # --- objects: one rigid body each -------------------------------------------------------
        UsdGeom.Scope.Define(stage, "/World/Objects")
        bodies: list[str] = []
        for name in object_bodies(model, robot_prefix):
            b = model.body(name).id
            path = f"/World/Objects/{usd_name(name)}"
            xform = UsdGeom.Xform.Define(stage, path)
            _set_pose(xform, data.xpos[b], data.xquat[b])
            prim = xform.GetPrim()
            prim.SetCustomDataByKey("realsim:mjcfBody", name)
            UsdPhysics.RigidBodyAPI.Apply(prim)
            mass = UsdPhysics.MassAPI.Apply(prim)
            mass.CreateMassAttr(float(model.body_mass[b]))
            mass.CreateCenterOfMassAttr(Gf.Vec3f(*map(float, model.body_ipos[b])))
            mass.CreateDiagonalInertiaAttr(Gf.Vec3f(*map(float, model.body_inertia[b])))
            w, x, y, z = (float(v) for v in model.body_iquat[b])
            mass.CreatePrincipalAxesAttr(Gf.Quatf(w, Gf.Vec3f(x, y, z)))
            UsdGeom.Scope.Define(stage, f"{path}/collision")
            UsdGeom.Scope.Define(stage, f"{path}/visual")
            for g in range(model.body_geomadr[b], model.body_geomadr[b] + model.body_geomnum[b]):
                gname = usd_name(model.geom(g).name or f"geom{g}")
                if model.geom_contype[g] or model.geom_conaffinity[g]:
                    writer.geom(f"{path}/collision/{gname}", g, collider=True)
                elif model.geom_group[g] == VISUAL_GROUP:
                    writer.geom(f"{path}/visual/{gname}", g, collider=False)
            bodies.append(path)
        # --- the robot: left out, with a note ----------------------------------------------------
        layer = stage.GetRootLayer()
        custom: dict[str, Any] = {"realsim:source": str(src_dir.resolve() / "scene.xml"), "realsim:keyframe": KEYFRAME}
        doc = "realsim scene: Z-up, metres, kilograms; poses from MJCF keyframe 'initial'."
        if robot_bodies:
            try:
                base = model.body(f"{robot_prefix}link0").id
            except KeyError:
                base = min(robot_bodies)
            custom["realsim:robot"] = ROBOT_NOTE
            custom["realsim:robotBase"] = {"position": Gf.Vec3d(*map(float, data.xpos[base])),
                                          "orientation_wxyz": Gf.Vec4d(*map(float, data.xquat[base]))}
            doc += " " + ROBOT_NOTE
            warnings.append("the robot is not exported to USD (see the stage's customLayerData['realsim:robot'])")
        layer.customLayerData = custom
        layer.documentation = doc
        layer.Save()
        del stage
        normal_permissions(tmp)
        os.replace(tmp, dest)
        if writer.textures:
            publish(tex_tmp, dest.parent / tex_rel, force=force, kind="export-usd-textures")
    finally:
        tmp.unlink(missing_ok=True)
        shutil.rmtree(tex_tmp, ignore_errors=True)
    return UsdExport(path=dest, rigid_bodies=bodies, static_colliders=statics, textures=writer.textures, warnings=warnings)
