"""The ``text`` stage: a scene description -> procedural objects arranged as described.

The description (``--text`` or ``text:`` in capture.yaml) is read into a
:class:`~realsim.text.schema.SceneSpec` (offline parser, or Claude with the same schema when a
key is set and ``use_llm``), or a spec is already in ``scene.scene_spec`` (a photo). Each object instance is built by its procedural family (:mod:`realsim.procedural`,
exact convex pieces, no decomposition), given an offline manifest, and arranged
(:mod:`realsim.text.arrange`): supports side by side (the first table-like one at the origin, the
floor around), objects on their support, stacks, contents and objects on objects lowered onto
what they rest on. Articulated objects (drawer cabinet, hinged box, laptop) keep their child
part in ``scene.articulations``; grasp sites (handle, rim, lid, ...) go to ``scene.object_sites``
for :func:`realsim.composition.compose.compose_scene`.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from realsim.assets import prepare_objects
from realsim.cache import DiskCache, cache_root
from realsim.composition.layout import LayoutParams, declared_support
from realsim.composition.objects import ObjectsParams
from realsim.errors import InputError
from realsim.geometry import yaw_quat
from realsim.perception.capture_config import DeclaredSupport
from realsim.physics import estimate_manifest
from realsim.physics.size_table import lookup
from realsim.procedural import Generated, generate, get_backend
from realsim.procedural.prepare import prepare_part
from realsim.scene import Scene, SceneObject, SupportPlane, scene_object
from realsim.scene_format import safe_name
from realsim.text.arrange import Item, _NoRoom, place_children, place_roots
from realsim.text.parser import parse_scene
from realsim.text.schema import SUPPORT_DEFAULTS, ObjectSpec, SceneSpec, clamp
from realsim.text.vocabulary import COLORS, MATERIALS

MAX_OBJECTS = 24
SUPPORT_GAP = 0.6  # m between supports standing side by side (room for the robot's pedestal)


@dataclass(frozen=True)
class TextParams:
    """Parameters of the text stage."""

    # objects gathered within reach of one long edge of the table, where the Panda will stand
    objects: ObjectsParams = field(default_factory=lambda: ObjectsParams(layout=LayoutParams(reach_radius=0.5)))
    use_llm: bool = True  # parse with Claude when ANTHROPIC_API_KEY is set (validated; offline fallback)
    variation: float = 0.08  # seeded relative size variation around the table's typical dims
    text_to_3d: str | None = None  # a registered text-to-3D backend (realsim.procedural.text_to_3d); off by default
    asset_dir: str | None = None  # where backend meshes go (default $REALSIM_CACHE/procedural)


def parse(text: str, use_llm: bool = True) -> SceneSpec:
    """The description read by Claude (when configured and allowed) or offline."""
    if use_llm:
        from realsim.text.claude import parse_with_claude

        return parse_with_claude(text)
    return parse_scene(text)


def object_rgb(o: ObjectSpec) -> tuple[float, float, float] | None:
    """Seen RGB, else the colour word, else the material's colour."""
    if o.rgb is not None:
        return tuple(v / 255.0 for v in o.rgb)  # type: ignore[return-value]
    for word in reversed(o.color.split()):
        if word in COLORS:
            return COLORS[word]
    return MATERIALS.get(o.material) or None


def display_label(o: ObjectSpec) -> str:
    """The object's label in the scene: what it was called when that names the same kind ("coffee mug")."""
    if o.name and o.name != o.label:
        a, b = lookup(o.name), lookup(o.label)
        if a is not None and b is not None and a.category.name == b.category.name:
            return o.name
    return o.label


def _supports(spec: SceneSpec) -> dict[str, SupportPlane]:
    """Planes for the described supports: the table-like ones side by side along +x, the floor under them."""
    planes: dict[str, SupportPlane] = {}
    x = None
    pid = 1
    elevated = sorted((s for s in spec.supports if s.kind != "floor"), key=lambda s: s.kind not in ("table", "desk", "counter"))
    for s in elevated:
        height = s.height_m if s.height_m is not None else SUPPORT_DEFAULTS[s.kind][0]
        size = s.size_m or SUPPORT_DEFAULTS[s.kind][1]
        cx = 0.0 if x is None else x + SUPPORT_GAP + size[0] / 2
        plane = declared_support(DeclaredSupport(size=(size[0], size[1]), height=height, center=(cx, 0.0), kind=s.kind))
        plane.id = pid
        pid += 1
        planes[s.id] = plane
        x = cx + size[0] / 2
    floor_ids = [s.id for s in spec.supports if s.kind == "floor"] or ["floor"]
    if planes:
        pts = np.vstack([p.polygon for p in planes.values()])
        lo, hi = pts.min(axis=0) - 1.2, pts.max(axis=0) + 1.2
        corners = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
        floor = SupportPlane(0, "floor", np.array([0.0, 0.0, 1.0]), 0.0, corners, (lo + hi) / 2, hi - lo, 0.0, 0, observed=False)
    else:
        floor = declared_support(DeclaredSupport(size=SUPPORT_DEFAULTS["floor"][1], height=0.0, kind="floor"))
        floor.id = 0
    for fid in floor_ids:
        planes[fid] = floor
    return planes


def _unit_of(items: list[Item], key: str) -> str | None:
    """The row group of the item ``key`` (None when it stands alone)."""
    return next((it.group for it in items if it.key == key), None)


def _resting_on_placed(children: list[Item], placed: dict[str, Item]) -> list[Item]:
    """The children whose chain of parents ends on a placed item (those on something left out are left out too)."""
    by_key = {it.key: it for it in children}

    def grounded(it: Item) -> bool:
        seen: set[str] = set()
        while it.parent is not None and it.parent not in placed and it.parent in by_key and it.key not in seen:
            seen.add(it.key)
            it = by_key[it.parent]
        return it.parent in placed

    return [it for it in children if grounded(it)]


def _floor_region(planes: dict[str, SupportPlane]) -> tuple[np.ndarray, np.ndarray] | None:
    """Where floor objects go beside table-like supports: a band behind them (away from the robot)."""
    elevated = [p for p in planes.values() if p.kind != "floor"]
    if not elevated:
        return None
    pts = np.vstack([p.polygon for p in elevated])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    return np.array([lo[0] - 0.4, hi[1] + 0.25]), np.array([hi[0] + 0.4, hi[1] + 1.0])


@dataclass
class _Instance:
    spec: ObjectSpec
    index: int
    gen: Generated
    objects: list[SceneObject] = field(default_factory=list)
    item: Item | None = None


def text_scene(scene: Scene, params: TextParams = TextParams()) -> Scene:
    """Read the description, build the objects and arrange them (see the module doc)."""
    text = scene.capture.config.text
    spec = scene.scene_spec
    if spec is None:
        if not text or not text.strip():
            raise InputError("the text pipeline needs a description: pass --text \"a table with a mug\" or put text: in capture.yaml")
        spec = parse(text, params.use_llm)
    spec, notes = clamp(spec)
    if not spec.objects:
        raise InputError(f"no objects found in {text!r}: name some, e.g. \"a table with a mug and two soda cans\"")
    if spec.total() > MAX_OBJECTS:
        raise InputError(f"the description asks for {spec.total()} objects; at most {MAX_OBJECTS} fit a text scene")
    for note in spec.warnings + notes:
        scene.warn(note)
    scene.scene_spec = spec
    planes = _supports(spec)
    primary = next((p for p in planes.values() if p.kind != "floor"), None)
    if primary is not None and scene.support is None:
        scene.support = DeclaredSupport(size=(float(primary.rect_size[0]), float(primary.rect_size[1])), height=primary.height, kind=primary.kind)
    scene.planes = sorted({id(p): p for p in planes.values()}.values(), key=lambda p: p.id)
    instances = _build(scene, spec, params)
    _arrange(scene, spec, instances, planes, params)
    return scene


def _build(scene: Scene, spec: SceneSpec, params: TextParams) -> list[_Instance]:
    """Every instance generated (one seeded generator, in order) and made into SceneObjects."""
    rng = np.random.default_rng(scene.seed)
    backend = get_backend(params.text_to_3d)
    cache = DiskCache(enabled=params.objects.use_cache)
    folder = Path(params.asset_dir) if params.asset_dir else cache_root() / "procedural"
    out: list[_Instance] = []
    next_id = max((o.id for o in scene.objects), default=0) + 1
    sites, arts = scene.object_sites, scene.articulations
    room = _room_needed(spec, scene.seed, params)
    for o in spec.objects:
        label = display_label(o)
        for k in range(o.count):
            gen = generate(label, rng, o.size or None, object_rgb(o), variation=params.variation, dims=o.size_m, at_least=room.get(o.id, 0.0))
            scene.warnings.extend(n for n in gen.notes if n not in scene.warnings)
            inst = _Instance(o, k, gen)
            for part in gen.parts:
                prep = None
                if backend is not None and gen.joint is None:
                    try:
                        path = backend.generate(label, scene.capture.config.text or "", folder, scene.seed + next_id)
                        prep = prepare_objects([Path(path)], [label], params.objects.assets, cache)[0]
                    except Exception as exc:  # a remote service may fail in many ways; procedural stands in
                        scene.warn(f"text-to-3D backend {backend.name} failed for {label!r} ({type(exc).__name__}); used the procedural model")
                prep = prep or prepare_part(part, params.objects.assets)
                name = f"obj{next_id}_{safe_name(part.label)}"
                obj = scene_object(prep, estimate_manifest(prep), next_id, name)
                obj.color = np.asarray(part.color, dtype=np.float64)
                next_id += 1
                if part.sites:
                    sites[name] = {k2: [round(float(v), 5) for v in p] for k2, p in part.sites.items()}
                inst.objects.append(obj)
            if gen.joint is not None:
                parent, child = inst.objects
                j = gen.joint
                arts[child.name] = {"parent": parent.name, "type": j.type, "axis": list(j.axis), "range": list(j.range), "pos": list(j.pos),
                                    "damping": j.damping, "object": gen.label, "handle": list(j.handle) if j.handle else None}
            out.append(inst)
    return out


CAVITY_SHARE = 0.8  # of a container's width that its cavity offers


def _room_needed(spec: SceneSpec, seed: int, params: TextParams) -> dict[str, float]:
    """Container id -> the largest extent (m) it needs to hold what is said to be in it: its
    contents' footprints side by side in a square grid (a bowl of bananas is a wide bowl)."""
    rng = np.random.default_rng(seed + 1)
    need: dict[str, float] = {}
    for o in spec.objects:
        if not o.inside:
            continue
        gen = generate(display_label(o), rng, o.size or None, None, variation=0.0, dims=o.size_m)
        span = float(max(gen.dims[:2]))
        per_row = int(np.ceil(np.sqrt(o.count)))
        need[o.inside] = max(need.get(o.inside, 0.0), (span * per_row + 0.01 * per_row) / CAVITY_SHARE)
    return need


def _arrange(scene: Scene, spec: SceneSpec, instances: list[_Instance], planes: dict[str, SupportPlane], params: TextParams) -> None:
    """Instances -> arrangement items -> placed SceneObjects."""
    rng = np.random.default_rng(scene.seed)
    by_spec: dict[str, list[_Instance]] = {}
    for inst in instances:
        by_spec.setdefault(inst.spec.id, []).append(inst)
    for inst in instances:
        main = inst.objects[0]
        extra = []
        if inst.gen.joint is not None:
            travel = np.asarray(inst.gen.joint.axis) * (inst.gen.joint.range[1] if inst.gen.joint.type == "slide" else 0.0)
            off = np.asarray(inst.gen.joint.child_pos)
            extra = [h.vertices + off + travel for h in inst.objects[1].collision]  # the drawer's travel kept clear
        item = Item(key=main.name, hulls=[h.vertices for h in main.collision], extra=extra, fixed_yaw=inst.gen.joint is not None,
                    position=inst.spec.position)
        o = inst.spec
        siblings = by_spec[o.id]
        if o.stacked and inst.index > 0:
            item.parent, item.stacked = siblings[inst.index - 1].objects[0].name, True
        elif o.inside or (o.on and o.on in by_spec):
            target = by_spec[o.inside or o.on]  # type: ignore[index]
            tspec = target[0].spec
            # on a stack: on its top; otherwise shared out among the target's instances
            item.parent = (target[-1] if tspec.stacked and not o.inside else target[inst.index % len(target)]).objects[0].name
            item.inside = o.inside is not None
        else:
            item.support = planes[o.on or next(iter(planes))].id if (o.on or planes) else None
            if o.row and o.count > 1:
                item.group = f"row:{o.id}"
        for rel in o.relations:
            if rel.target in by_spec:  # as many as the target: one each ("a mug next to each plate")
                targets = by_spec[rel.target]
                pick = targets[inst.index] if len(targets) == len(siblings) else targets[0]
                item.relations.append((rel.relation, pick.objects[0].name))
        inst.item = item
    items = [i.item for i in instances if i.item is not None]
    roots = [it for it in items if it.parent is None]
    obstacles: list[np.ndarray] = []
    placed: dict[str, Item] = {}
    by_id = {p.id: p for p in planes.values()}
    for pid in sorted({it.support for it in roots}, key=lambda v: (v == 0, v)):  # type: ignore[arg-type]
        support = by_id[pid]  # type: ignore[index]
        group = [it for it in roots if it.support == pid]
        region = _floor_region(planes) if support.kind == "floor" else None
        layout = params.objects.layout if support.kind != "floor" else dataclasses.replace(params.objects.layout, reach_radius=None)
        floor_obstacles = obstacles + ([p.polygon for p in planes.values() if p.kind != "floor"] if support.kind == "floor" else [])
        while group:  # what does not fit on its support (beside the rest) is left out, with a warning
            try:
                scene.warnings.extend(place_roots(group, support, floor_obstacles, rng, layout, region))
                break
            except _NoRoom as exc:
                unit = {it.key for it in group if it.key == str(exc) or (it.group is not None and it.group == _unit_of(group, str(exc)))}
                group = [it for it in group if it.key not in unit]
                scene.warnings.append(f"{', '.join(sorted(unit))}: no room on the {support.rect_size[0]:.2f} x {support.rect_size[1]:.2f} m "
                                      f"{support.kind} beside the rest; left out (describe fewer or smaller objects)")
        placed.update({it.key: it for it in group})
    if not placed:
        raise InputError("none of the described objects fits on its support: describe fewer or smaller objects")
    scene.warnings.extend(place_children(_resting_on_placed([it for it in items if it.parent is not None], placed), placed, rng))
    for inst in instances:
        it = inst.item
        if it is None or it.key not in placed:
            continue
        main = inst.objects[0]
        main.position = np.array([it.xy[0], it.xy[1], it.z + (params.objects.drop_clearance if it.parent is None else 0.0)])  # type: ignore[index]
        main.quat = yaw_quat(it.yaw)
        main.support_id = it.support if it.parent is None else None
        main.resting_on = next((i.objects[0].id for i in instances if i.objects[0].name == it.parent), None)
        scene.objects.append(main)
        if inst.gen.joint is not None:
            child = inst.objects[1]
            c, s = np.cos(it.yaw), np.sin(it.yaw)
            rel = np.asarray(inst.gen.joint.child_pos)
            child.position = main.position + np.array([c * rel[0] - s * rel[1], s * rel[0] + c * rel[1], rel[2]])
            child.quat = main.quat.copy()
            child.resting_on = main.id
            scene.objects.append(child)
