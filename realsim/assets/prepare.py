"""The asset stage: a raw object mesh -> a normalized, decomposed, simulation-ready object."""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import trimesh

from realsim.assets.decompose import decompose
from realsim.assets.geometry import blend_inertia, clean_geometry, make_solid, plausible_scale, shell_inertia_unit, solid_inertia_unit
from realsim.assets.loading import colour_captured, load_object_mesh, missing_references, texture_file, visual_appearance
from realsim.assets.params import AssetParams
from realsim.cache import DiskCache, cache_key
from realsim.composition.atlas import baked_colours, surface_colour
from realsim.errors import InputError
from realsim.parallel import parallel_map
from realsim.physics.size_table import lookup

OPEN_CAVITY_RATIO = 0.6  # solid / convex-hull volume below this: the scan shows the cavity (walls only)


@dataclass
class PreparedObject:
    """One object ready for MJCF: visual mesh + convex hulls in the object frame (origin at the
    centre of the base, Z up, metres) and its mass properties per unit mass."""

    label: str
    source: Path
    visual: trimesh.Trimesh
    texture_png: bytes | None
    rgba: tuple[float, float, float, float]
    hulls: list[trimesh.Trimesh]
    volume: float
    size: np.ndarray
    com: np.ndarray
    inertia_unit_mass: np.ndarray
    scale_applied: float
    warnings: list[str] = field(default_factory=list)
    timings: dict[str, float] = field(default_factory=dict)
    solid: trimesh.Trimesh | None = None  # the watertight solid (object frame)
    surface_area: float = 0.0
    convex_hull_volume: float = 0.0
    solid_method: str = "manifold"
    inertia_model: str = "solid"  # "solid" | "shell" | "shell+contents"
    decomposition: dict = field(default_factory=dict)
    category: str | None = None
    color: np.ndarray | None = None  # (3,) RGB the object shows (its texture's mean), for names and the planner; None: unknown

    @property
    def open_container(self) -> bool:
        """True when the size table calls the object an open container (mug, bowl, pitcher):
        its volume is walls, so hull fidelity is judged by surface distance, not volume IoU."""
        entry = lookup(self.label)
        return entry is not None and entry.category.form == "open_container"

    @property
    def open_cavity(self) -> bool:
        """True when the geometry itself shows a cavity (walls only: mugs, bowls as scanned)."""
        return self.convex_hull_volume > 0 and self.volume / self.convex_hull_volume < OPEN_CAVITY_RATIO


def _inertia_for(solid: trimesh.Trimesh, label: str, open_cavity: bool) -> tuple[np.ndarray, np.ndarray, str]:
    """Unit-mass (com, inertia): shell-aware for hollow categories whose mesh is a closed blob."""
    com_s, I_s = solid_inertia_unit(solid)
    m = lookup(label)
    if m is None or not m.category.hollow or open_cavity:
        return com_s, I_s, "solid"
    cat = m.category
    from realsim.physics.size_table import material

    com_h, I_h = shell_inertia_unit(solid)
    shell_mass = material(cat.material).density * cat.shell * solid.area
    contents_mass = cat.contents * max(solid.volume - cat.shell * solid.area, 0.0) if cat.form == "closed_container" else 0.0
    if contents_mass <= 0:
        return com_h, I_h, "shell"
    com, I = blend_inertia([(shell_mass, com_h, I_h), (contents_mass, com_s, I_s)])
    return com, I, "shell+contents"


def _heavy(mesh_v: np.ndarray, mesh_f: np.ndarray, label: str, params: AssetParams, cache: DiskCache | None = None) -> dict:
    """The cached part: normalization, solid and decomposition (pure function of its inputs)."""
    t: dict[str, float] = {}
    t0 = time.perf_counter()
    g = clean_geometry(trimesh.Trimesh(mesh_v, mesh_f, process=False))
    if len(g.faces) == 0:
        raise InputError(f"{label}: the mesh has only degenerate faces; re-export it")
    warns: list[str] = []
    scale = 1.0
    if params.rescale_implausible:
        scale, msg = plausible_scale(g.extents, label, params.plausible_margin)
        if msg:
            warns.append(msg)
            g.apply_scale(scale)
    lo, hi = g.bounds
    offset = -np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]])
    g.apply_translation(offset)
    t["clean"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    solid, method, notes = make_solid(g, params.voxel_fallback_pitch)
    warns += [f"{label}: {n}" for n in notes if "could not" in n]
    t["solid"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    category = lookup(label)
    hulls, info = decompose(solid, params, open_container=category.category.form == "open_container" if category else None, cache=cache)
    t["decompose"] = time.perf_counter() - t0
    hull_vol = float(solid.convex_hull.volume)
    return dict(scale=scale, offset=offset, solid=solid, method=method, notes=notes, warnings=warns, hulls=hulls, info=info, hull_volume=hull_vol, timings=t)


PREPARE_VERSION = 7  # bump when the preparation logic changes: old cache entries stop matching
FINISH_VERSION = 1  # bump when only the cheap finish (appearance, inertia) changes: hulls stay cached


def _file_key(path: Path, label: str | None, params: AssetParams) -> str | None:
    """Key of the whole prepared object from the file bytes (+ MTL/texture), label, params and
    :data:`PREPARE_VERSION` and :data:`FINISH_VERSION`."""
    from realsim.assets.loading import texture_file

    path = Path(path)
    if not path.is_file():
        return None
    files = [path] + [f for f in path.parent.glob("*.mtl")][:1] + ([t] if (t := texture_file(path)) else [])
    return cache_key("assets.prepared_file", files=files, params={"label": label, "params": params, "version": PREPARE_VERSION, "finish": FINISH_VERSION})


def prepare_object(path: Path, label: str | None = None, params: AssetParams = AssetParams(), cache: DiskCache | None = None) -> PreparedObject:
    """Load, normalize and decompose one object mesh (cached by file content + params)."""
    path = Path(path)
    cache = cache if cache is not None else DiskCache()
    fkey = _file_key(path, label, params) if cache.enabled else None
    if fkey is not None:
        t0 = time.perf_counter()
        hit = cache.get(fkey)
        if hit is not None:
            hit.timings = {"cache": time.perf_counter() - t0}
            hit.decomposition = {**hit.decomposition, "cache_hit": True}
            return hit
    obj = _prepare_uncached_file(path, label, params, cache)
    if fkey is not None:
        cache.put(fkey, obj)
    return obj


def _prepare_uncached_file(path: Path, label: str | None, params: AssetParams, cache: DiskCache) -> PreparedObject:
    t0 = time.perf_counter()
    mesh, label = load_object_mesh(path, label)
    t_load = time.perf_counter() - t0
    cache = cache if cache is not None else DiskCache()
    v = np.ascontiguousarray(mesh.vertices, dtype=np.float64)
    f = np.ascontiguousarray(mesh.faces, dtype=np.int64)
    key = cache_key("assets.prepare", data=v.tobytes() + f.tobytes() + label.encode(), params={"params": params, "version": PREPARE_VERSION})
    t0 = time.perf_counter()
    heavy = cache.get(key)
    hit = heavy is not None
    if heavy is None:
        heavy = _heavy(v, f, label, params, cache)
        cache.put(key, heavy)
    t_heavy = time.perf_counter() - t0
    t0 = time.perf_counter()
    visual = mesh.copy()
    if heavy["scale"] != 1.0:
        visual.apply_scale(heavy["scale"])
    visual.apply_translation(heavy["offset"])
    visual.update_faces(visual.nondegenerate_faces(height=1e-12))
    png, rgba, _ = visual_appearance(visual, texture_file(path))
    if png is None and (baked := baked_colours(visual)) is not None:  # painted vertices: their colours as a texture
        visual, png = baked
        rgba = (1.0, 1.0, 1.0, 1.0)
    if png is not None:  # a textured object's colour is its texture's
        shown = surface_colour(visual, png)
    else:  # a material colour the file sets; None when the file does not say (e.g. its texture is missing)
        shown = np.asarray(rgba[:3], float) if colour_captured(visual) else None
    solid = heavy["solid"]
    open_cavity = heavy["hull_volume"] > 0 and solid.volume / heavy["hull_volume"] < OPEN_CAVITY_RATIO
    com, inertia, model = _inertia_for(solid, label, open_cavity)
    m = lookup(label)
    timings = {"load": t_load, **({"cache": t_heavy} if hit else heavy["timings"]), "finish": time.perf_counter() - t0}
    return PreparedObject(
        label=label,
        source=path,
        visual=visual,
        texture_png=png,
        rgba=rgba,
        color=shown,
        hulls=heavy["hulls"],
        volume=float(solid.volume),
        size=np.asarray(solid.extents, float),
        com=com,
        inertia_unit_mass=inertia,
        scale_applied=float(heavy["scale"]),
        warnings=list(heavy["warnings"]) + [f"{name} is missing: the object is shown in a plain colour"
                                            for name in missing_references(path)],
        timings=timings,
        solid=solid,
        surface_area=float(solid.area),
        convex_hull_volume=heavy["hull_volume"],
        solid_method=heavy["method"],
        inertia_model=model,
        decomposition={**heavy["info"], "cache_hit": hit},
        category=m.category.name if m else None,
    )


def _prepare_job(job: tuple[Path, str | None, AssetParams, Path | None, bool]) -> PreparedObject:
    path, label, params, root, enabled = job
    return prepare_object(path, label, params, DiskCache(root, enabled))


def prepare_objects(paths: list[Path], labels: list[str | None] | None = None, params: AssetParams = AssetParams(), cache: DiskCache | None = None, progress: bool = False) -> list[PreparedObject]:
    """:func:`prepare_object` over many meshes in worker processes (results in input order)."""
    labels = list(labels) if labels is not None else [None] * len(paths)
    if len(labels) != len(paths):
        raise InputError(f"got {len(paths)} object meshes but {len(labels)} labels; pass one label (or None) per mesh")
    cache = cache if cache is not None else DiskCache()
    results: list[PreparedObject | None] = [None] * len(paths)
    todo = []
    for i, (p, lab) in enumerate(zip(paths, labels)):
        key = _file_key(Path(p), lab, params) if cache.enabled else None
        t0 = time.perf_counter()
        hit = cache.get(key) if key else None
        if hit is not None:
            hit.timings = {"cache": time.perf_counter() - t0}
            hit.decomposition = {**hit.decomposition, "cache_hit": True}
            results[i] = hit
        else:
            todo.append(i)
    if todo:
        jobs = [(Path(paths[i]), labels[i], params, cache.root, cache.enabled) for i in todo]
        for i, obj in zip(todo, parallel_map(_prepare_job, jobs, description="objects: decomposing", progress=progress)):
            results[i] = obj
    return results  # type: ignore[return-value]
