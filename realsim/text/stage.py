"""The ``text`` stage: a scene description -> procedural objects on a declared support.

The description (``--text`` or ``text:`` in capture.yaml) is parsed (:mod:`realsim.text.parser`,
or Claude when a key is set and ``use_llm``), each object is built with CSG
(:mod:`realsim.procedural`) and written as a coloured PLY under ``$REALSIM_CACHE/procedural``
(named by content hash), and those files go through the very path scanned object meshes take:
the ``objects`` stage (normalize, CoACD, manifest, seeded rejection-sampling layout).
Articulated objects (a drawer cabinet, a hinged box) are prepared the same way part by part and
placed with room for the drawer's travel; the child part is recorded in
``capture.metadata["articulations"]`` for :func:`realsim.compose.compose_scene`, which hangs it
on its parent with a slide or hinge joint.
"""

from __future__ import annotations

import dataclasses
import hashlib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from realsim.assets import prepare_objects
from realsim.cache import DiskCache, cache_root
from realsim.compose import safe_name
from realsim.errors import InputError
from realsim.layout import LayoutParams, declared_support, footprint, place_on_support
from realsim.objects_stage import (
    ObjectsParams,
    _support_for,
    _world_footprint,
    _yaw_quat,
    prepare_scene_objects,
    scene_object,
)
from realsim.physics import estimate_manifest
from realsim.procedural import Generated, generate, get_backend, write_ply
from realsim.scene import Scene
from realsim.text.parser import SceneRequest, parse_description

ARTICULATIONS = "articulations"  # capture.metadata key read by compose
KEEP_CLEAR = "keep_clear"  # capture.metadata key: xy polygons the layout of other objects avoids
MAX_OBJECTS = 24


@dataclass(frozen=True)
class TextParams:
    """Parameters of the text stage."""

    # objects gathered within reach of one long edge of the table, where the Panda will stand
    objects: ObjectsParams = field(default_factory=lambda: ObjectsParams(layout=LayoutParams(reach_radius=0.5)))
    use_llm: bool = True  # parse with Claude when ANTHROPIC_API_KEY is set (validated; offline fallback)
    variation: float = 0.08  # seeded relative size variation around the table's typical dims
    text_to_3d: str | None = None  # a registered text-to-3D backend (realsim.procedural.text_to_3d); off by default
    asset_dir: str | None = None  # where generated meshes go (default $REALSIM_CACHE/procedural)


def parse(text: str, use_llm: bool = True) -> SceneRequest:
    """The description parsed by Claude (when configured and allowed) or offline."""
    if use_llm:
        from realsim.text.claude import parse_with_claude

        return parse_with_claude(text)
    return parse_description(text)


def _support_metadata(scene: Scene, req: SceneRequest) -> None:
    meta = scene.capture.metadata
    if meta.get("support"):
        return
    meta["support"] = {"size": list(req.support_size), "height": req.support_height, "kind": req.support}


def _write_part(part, index: int, folder: Path) -> Path:
    """The part as a coloured PLY named by its content hash (a warm rerun hits every cache)."""
    data = np.ascontiguousarray(part.mesh.vertices).tobytes() + np.ascontiguousarray(part.mesh.faces).tobytes() + repr(part.color).encode()
    digest = hashlib.sha256(data).hexdigest()[:12]
    return write_ply(part.mesh, part.color, folder / f"{index:02d}_{safe_name(part.label)}_{digest}.ply")


def generate_objects(req: SceneRequest, seed: int, params: TextParams) -> list[Generated]:
    """Every requested object instance, built in order with one seeded generator."""
    if req.total() > MAX_OBJECTS:
        raise InputError(f"the description asks for {req.total()} objects; at most {MAX_OBJECTS} fit a text scene")
    rng = np.random.default_rng(seed)
    out = []
    for o in req.objects:
        for _ in range(o.count):
            out.append(generate(o.label, rng, o.size or None, o.rgb, variation=params.variation))
    return out


def text_scene(scene: Scene, params: TextParams = TextParams()) -> Scene:
    """Parse the description, build the objects and place them on the support (see the module doc)."""
    text = scene.capture.metadata.get("text")
    if not text or not str(text).strip():
        raise InputError("the text pipeline needs a description: pass --text \"a table with a mug\" or put text: in capture.yaml")
    req = parse(str(text), params.use_llm)
    if not req.objects:
        raise InputError(f"no objects found in {text!r}: name some, e.g. \"a table with a mug and two soda cans\"")
    for note in req.notes:
        scene.warn(note)
    scene.capture.metadata["text_request"] = {
        "parser": req.parser, "support": req.support,
        "objects": [{"label": o.label, "count": o.count, "color": o.color, "size": o.size} for o in req.objects],
    }
    _support_metadata(scene, req)
    folder = Path(params.asset_dir) if params.asset_dir else cache_root() / "procedural"
    backend = get_backend(params.text_to_3d)
    generated = generate_objects(req, scene.seed, params)
    labels = dict(scene.capture.metadata.get("labels") or {})
    files: list[Path] = []
    articulated: list[tuple[Generated, list[Path]]] = []
    for i, gen in enumerate(generated):
        if gen.joint is not None:
            articulated.append((gen, [_write_part(p, i, folder) for p in gen.parts]))
            continue
        path = None
        if backend is not None:
            try:
                path = backend.generate(gen.label, str(text), folder, scene.seed + i)
            except Exception as exc:  # a remote service may fail in many ways; procedural stands in
                scene.warn(f"text-to-3D backend {backend.name} failed for {gen.label!r} ({type(exc).__name__}); used the procedural model")
        path = path or _write_part(gen.parts[0], i, folder)
        labels[Path(path).stem] = gen.label
        files.append(Path(path))
        scene.warnings.extend(gen.notes)
    scene.capture.metadata["labels"] = labels
    if req.support == "floor" and not scene.planes:
        _floor_only(scene)
    if articulated:  # the largest first, with room kept clear for the drawer's or lid's travel
        _add_articulated(scene, articulated, params.objects)
    scene.object_files = list(scene.object_files) + files
    prepare_scene_objects(scene, params.objects)
    return scene


def _floor_only(scene: Scene) -> None:
    """On the floor: one support plane, the floor itself (no table box)."""
    support = declared_support(scene.capture.metadata)
    support.kind, support.id = "floor", 0
    scene.planes = [support]


def _add_articulated(scene: Scene, items: list[tuple[Generated, list[Path]]], params: ObjectsParams) -> None:
    """Prepare each articulated object's parts, place the parent with room for the child's travel."""
    support = _support_for(scene)
    cache = DiskCache(enabled=params.use_cache)
    rng = np.random.default_rng(scene.seed + 7919)
    obstacles = [_world_footprint(o) for o in scene.objects]
    arts = scene.capture.metadata.setdefault(ARTICULATIONS, {})
    next_id = max((o.id for o in scene.objects), default=0) + 1
    for gen, paths in items:
        prepared = prepare_objects(paths, [p.label for p in gen.parts], params.assets, cache)
        objs = []
        for prep, part in zip(prepared, gen.parts):
            obj = scene_object(prep, estimate_manifest(prep), next_id, f"obj{next_id}_{safe_name(part.label)}")
            obj.color = np.asarray(part.color, dtype=np.float64)
            objs.append(obj)
            next_id += 1
        parent, child = objs
        joint = gen.joint
        assert joint is not None
        travel = np.asarray(joint.axis) * (joint.range[1] if joint.type == "slide" else 0.0)
        pts = [h.vertices[:, :2] for h in parent.collision]
        pts += [h.vertices[:, :2] + np.asarray(joint.child_pos[:2]) + travel[:2] for h in child.collision]
        # axis-aligned (the drawer opens along the support's long side, +x), apart from everything placed
        layout = dataclasses.replace(params.layout, random_yaw=False, attempts_per_object=max(params.layout.attempts_per_object, 1000))
        (xy, yaw), = place_on_support([footprint(np.vstack(pts))], support, obstacles, rng, layout)
        parent.position = np.array([xy[0], xy[1], support.height + params.drop_clearance])
        parent.quat = _yaw_quat(yaw)
        parent.support_id = support.id
        c, s = np.cos(yaw), np.sin(yaw)
        rel = np.asarray(joint.child_pos)
        child.position = parent.position + np.array([c * rel[0] - s * rel[1], s * rel[0] + c * rel[1], rel[2]])
        child.quat = parent.quat.copy()
        child.resting_on = parent.id
        swept = footprint(np.vstack(pts)) @ np.array([[c, s], [-s, c]]) + xy  # the parent plus the child's travel
        obstacles.append(swept)
        scene.capture.metadata.setdefault(KEEP_CLEAR, []).append(swept.round(4).tolist())
        arts[child.name] = {"parent": parent.name, "type": joint.type, "axis": list(joint.axis), "range": list(joint.range),
                            "pos": list(joint.pos), "damping": joint.damping, "object": gen.label,
                            "handle": list(joint.handle) if joint.handle else None}
        scene.objects.extend([parent, child])
