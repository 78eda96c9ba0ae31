"""The physics manifest of one object and its offline estimator (tables + geometry)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Literal

import numpy as np
from pydantic import BaseModel, Field

from realsim.physics.mujoco_params import solref_from_restitution
from realsim.physics.size_table import lookup, material

if TYPE_CHECKING:
    from realsim.assets.prepare import PreparedObject

Source = Literal["table", "geometry", "fallback", "claude", "user"]
GENERIC_MASS = (0.005, 0.3, 20.0)
GRIPPER_OPENING = 0.08  # m, Franka Hand


class ObjectManifest(BaseModel):
    """Physical description of one object; ``sources`` says where each value came from."""

    label: str
    category: str | None = None
    mass_kg: float = Field(gt=0)
    friction: tuple[float, float, float]  # MuJoCo (sliding, torsional, rolling)
    restitution: float = Field(ge=0, le=1)
    solref: tuple[float, float]  # MuJoCo (timeconst, dampratio)
    com: tuple[float, float, float]  # object frame
    inertia: tuple[float, float, float, float, float, float]  # about com: ixx iyy izz ixy ixz iyz
    joint_type: Literal["free", "hinge", "slide", "fixed"] = "free"
    joint_axis: tuple[float, float, float] | None = None
    joint_range: tuple[float, float] | None = None
    is_graspable: bool = False
    is_pushable: bool = True
    is_openable: bool = False
    is_support_surface: bool = False
    material_class: str = "default"
    size_class: Literal["tiny", "small", "medium", "large", "huge"] = "small"
    hollow: bool = False
    notes: list[str] = Field(default_factory=list)
    sources: dict[str, Source] = Field(default_factory=dict)

    def fullinertia(self) -> list[float]:
        """MuJoCo ``fullinertia`` order (ixx, iyy, izz, ixy, ixz, iyz)."""
        return list(self.inertia)


def size_class(largest: float) -> str:
    """A size word for an object's largest extent in metres: tiny, small, medium, large or huge."""
    for limit, name in ((0.03, "tiny"), (0.12, "small"), (0.4, "medium"), (1.2, "large")):
        if largest < limit:
            return name
    return "huge"


def _support_surface(prepared: "PreparedObject") -> bool:
    """A flat, wide top: upward faces near the top cover much of the footprint."""
    solid = prepared.solid
    if solid is None or min(prepared.size[:2]) < 0.12:
        return False
    up = solid.face_normals[:, 2] > 0.97
    top = solid.triangles_center[:, 2] > prepared.size[2] - 0.005
    flat = float(solid.area_faces[up & top].sum())
    return flat >= 0.5 * prepared.size[0] * prepared.size[1]


def estimate_mass(prepared: "PreparedObject") -> tuple[float, str, list[str]]:
    """(mass kg, source, notes) from the category's material, form and the solid geometry."""
    m = lookup(prepared.label)
    V, A = prepared.volume, prepared.surface_area
    notes: list[str] = []
    if m is None:
        mat = material("default")
        mass = mat.density * V
        lo, _, hi = GENERIC_MASS
        src = "fallback"
        notes.append(f"unknown label {prepared.label!r}: default density {mat.density:g} kg/m^3")
    else:
        cat = m.category
        mat = material(cat.material)
        rho, t = mat.density, cat.shell
        if prepared.open_cavity or cat.form == "solid":
            mass = rho * V
            how = "walls as scanned" if cat.form != "solid" and prepared.open_cavity else "solid"
        elif cat.form == "closed_container":
            shell = min(rho * t * A, rho * V)
            mass = shell + cat.contents * max(V - t * A, 0.0)
            how = f"{t * 1000:g} mm {cat.material} shell + contents {cat.contents:g} kg/m^3"
        elif cat.form == "open_container":
            mass = min(rho * t * A * 1.5, rho * V)  # inner + outer wall of a closed-looking blob
            how = f"{t * 1000:g} mm walls (cavity not visible in the mesh)"
        else:  # hollow
            mass = min(rho * t * A, rho * V)
            how = f"{t * 1000:g} mm hollow shell"
        lo, _, hi = cat.mass
        src = "geometry"
        notes.append(f"mass from {cat.material} ({rho:g} kg/m^3), {how}, volume {V * 1e6:.1f} cm^3")
    if mass < lo or mass > hi:
        clamped = float(np.clip(mass, lo, hi))
        notes.append(f"mass {mass:.3g} kg outside the plausible {lo:g}-{hi:g} kg; clamped to {clamped:.3g}")
        mass = clamped
        src = "table" if m is not None else "fallback"
    return float(mass), src, notes


def estimate_manifest(prepared: "PreparedObject") -> ObjectManifest:
    """Offline manifest: size tables (material, form, joints) + geometry (volume, inertia)."""
    m = lookup(prepared.label)
    cat = m.category if m else None
    mat = material(cat.material if cat else "default")
    sources: dict[str, str] = {}
    notes: list[str] = []
    if m is not None and m.how == "fuzzy":
        notes.append(f"label {prepared.label!r} matched {cat.name!r} approximately ({m.score:.2f})")
    mass, sources["mass_kg"], mass_notes = estimate_mass(prepared)
    notes += mass_notes
    src_mat = "table" if cat else "fallback"
    sources.update(friction=src_mat, restitution=src_mat, material_class=src_mat)
    I = np.asarray(prepared.inertia_unit_mass, float) * mass
    I = 0.5 * (I + I.T)
    # keep it a valid inertia for MuJoCo (positive, triangle inequality) on thin/degenerate shapes
    w, R = np.linalg.eigh(I)
    w = np.maximum(w, max(w.max() * 1e-3, 1e-9))
    I = R @ np.diag(w) @ R.T
    sources["inertia"] = "geometry"
    sources["com"] = "geometry"
    joint_type, axis, rng = "free", None, None
    if cat and cat.joint:
        joint_type = cat.joint["type"]
        axis = tuple(float(x) for x in cat.joint["axis"])
        rng = tuple(float(x) for x in cat.joint["range"])
        sources["joint_type"] = "table"
    elif mass > 40.0:
        joint_type = "fixed"
        sources["joint_type"] = "geometry"
        notes.append("too heavy to move: fixed")
    else:
        sources["joint_type"] = "table" if cat else "fallback"
    size = np.asarray(prepared.size, float)
    graspable = bool(np.sort(size)[0] <= GRIPPER_OPENING and mass <= 3.0 and joint_type == "free")
    support = _support_surface(prepared) or bool(cat and cat.name in ("table", "shelf", "cabinet", "tray", "cutting_board", "plate", "book"))
    sources.update(is_graspable="geometry", is_pushable="geometry", is_openable="table" if cat else "fallback", is_support_surface="geometry")
    sources["hollow"] = "table" if cat else "fallback"
    return ObjectManifest(
        label=prepared.label,
        category=cat.name if cat else None,
        mass_kg=mass,
        friction=tuple(mat.friction),
        restitution=mat.restitution,
        solref=solref_from_restitution(mat.restitution),
        com=tuple(float(x) for x in prepared.com),
        inertia=(float(I[0, 0]), float(I[1, 1]), float(I[2, 2]), float(I[0, 1]), float(I[0, 2]), float(I[1, 2])),
        joint_type=joint_type,
        joint_axis=axis,
        joint_range=rng,
        is_graspable=graspable,
        is_pushable=bool(joint_type == "free" and mass <= 10.0),
        is_openable=joint_type in ("hinge", "slide"),
        is_support_surface=support,
        material_class=cat.material if cat else "default",
        size_class=size_class(float(size.max())),
        hollow=bool(cat and cat.hollow),
        notes=notes + [f"inertia model: {prepared.inertia_model}"],
        sources=sources,
    )
