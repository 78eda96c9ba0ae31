"""Scene understanding inside the ``objects`` stage: labels for scan clusters and photo objects,
and physics manifests (Claude when a key is set, the offline estimator otherwise).

Without a key everything is offline: scan clusters labelled ``"object"`` get the size-table
category nearest to their shape, and manifests are :func:`realsim.physics.estimate_manifest`'s.
With a key: the photo (``--photo`` or ``photo.*`` in the capture folder) names the clusters or,
with no scan, the objects; each object's manifest comes from two Claude passes, run for several
objects at once (``max_workers``) under one deadline (``timeout_s``). Any failure falls back to
the offline result and is noted; the conversion never fails because of Claude.
"""

from __future__ import annotations

import os
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor, wait
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from realsim import llm
from realsim.assets import PreparedObject
from realsim.cache import DiskCache
from realsim.composition.atlas import png_bytes
from realsim.physics import ObjectManifest, estimate_manifest
from realsim.physics.size_table import lookup
from realsim.scene import Scene, SceneObject
from realsim.understanding.calls import CallLog
from realsim.understanding.camera import capture_camera
from realsim.understanding.manifest_claude import claude_manifest, fallback_manifest
from realsim.understanding.naming import balanced, distinct, offline_name, white_point
from realsim.understanding.photo import PhotoObject, find_photo, label_photo, match_clusters
from realsim.understanding.primitives import prepared_from_mesh, primitive_extents, primitive_mesh
from realsim.understanding.sanitize import clean_text, safe_label
from realsim.understanding.shape_label import is_cylinder, is_prism
from realsim.understanding.thumbnail import thumbnail

UNLABELLED = "object"


@dataclass(frozen=True)
class UnderstandingParams:
    """How objects are named and given physics."""

    photo: str | None = None  # a photo of the scene; None: photo.* in the capture folder
    photo_is_capture_view: bool = True  # the photo is the scan camera's view: match clusters by image position too
    claude: bool = True  # use Claude when ANTHROPIC_API_KEY is set
    label_from_shape: bool = True  # name unlabelled scan clusters by the nearest size-table shape
    scan_manifests: bool = True  # with Claude: manifests for scan clusters too (offline they keep compose's defaults)
    thumbnails: bool = True
    max_workers: int = 4
    timeout_s: float = 300.0  # deadline for all manifest calls together
    model: str | None = None  # None: REALSIM_MODEL or the llm module's default


@dataclass
class Understanding:
    """Per-conversion state: settings, the photo's objects, the call log."""

    scene: Scene
    params: UnderstandingParams = field(default_factory=UnderstandingParams)
    cache: DiskCache = field(default_factory=DiskCache)
    settings: llm.LLMSettings = field(init=False)
    log: CallLog = field(default_factory=CallLog)
    _photo: list[PhotoObject] | None = field(default=None, init=False)
    _photo_done: bool = field(default=False, init=False)
    elapsed_s: float = field(default=0.0, init=False)  # wall time of the manifest calls

    def __post_init__(self) -> None:
        self.settings = llm.LLMSettings(model=self.params.model) if self.params.model else llm.LLMSettings()

    # ---------------------------------------------------------------- configuration
    @property
    def use_claude(self) -> bool:
        return self.params.claude and llm.available(self.settings)

    def photo_path(self) -> Path | None:
        if self.params.photo:
            return Path(self.params.photo)
        return find_photo(Path(self.scene.capture.source))

    def photo_objects(self) -> list[PhotoObject]:
        """The photo's objects (one call, cached); [] without a key, a photo or on failure."""
        if self._photo_done:
            return self._photo or []
        self._photo_done = True
        path = self.photo_path()
        if path is None and self.use_claude:  # an organized cloud is a photo taken from the scan's own viewpoint
            return self._label_capture_photo()
        if path is None:
            return []
        if not self.use_claude:
            self.scene.warn(f"photo {path.name}: ignored (no ANTHROPIC_API_KEY); objects are named from their shape")
            return []
        return self._label(path, path.name)

    def _label_capture_photo(self) -> list[PhotoObject]:
        """Claude's objects in the capture's own RGB (organized clouds with colours), else []."""
        scene = self.scene
        if scene.colors is None or scene.grid_shape is None or not scene.capture.camera_view:
            return []
        h, w = scene.grid_shape
        rgb = (np.clip(np.nan_to_num(scene.colors), 0, 1) * 255 + 0.5).astype(np.uint8).reshape(h, w, 3)
        fd, name = tempfile.mkstemp(prefix="realsim-capture-", suffix=".png")
        os.close(fd)
        try:
            Path(name).write_bytes(png_bytes(rgb))
            return self._label(Path(name), "of the capture's own colours")
        finally:
            Path(name).unlink(missing_ok=True)

    def _label(self, path: Path, what: str) -> list[PhotoObject]:
        try:
            result = label_photo(path, settings=self.settings, log=self.log, cache=self.cache)
        except llm.LLMError as exc:
            self._fail(f"photo {what}", str(exc))
            return []
        for note in result.notes:
            self.scene.warn(f"photo {what}: {note}")
        self._photo = result.objects
        return self._photo

    def _fail(self, what: str, why: str) -> None:
        msg = f"{what}: Claude failed ({clean_text(why, 200)}); offline fallback used"
        with self.log._lock:
            self.log.failures.append(msg)
        self.scene.warn(msg)

    # ---------------------------------------------------------------- labels
    def label_scan_objects(self) -> None:
        """Name scan clusters still labelled ``"object"``: photo match, else shape (offline)."""
        scene = self.scene
        todo = [o for o in scene.objects if o.label == UNLABELLED and o.visual is not None and o.source_file is None]
        if not todo:
            return
        photo = self.photo_objects() if scene.points is not None else []
        matched: dict[int, PhotoObject] = {}
        if photo:
            camera = capture_camera(scene) if self.params.photo_is_capture_view else None
            xy = []
            for o in todo:
                if camera is None:
                    xy.append(None)
                    continue
                centre = o.position + np.array([0.0, 0.0, float(o.size[2]) / 2])
                xy.append(camera.project(centre)[0])
            pairs = match_clusters([_extents(o)[0] for o in todo], xy, [o.color for o in todo], photo)
            matched = {todo[i].id: photo[j] for i, j in pairs.items()}
            for j, p in enumerate(photo):
                if j not in pairs.values():
                    scene.warn(f"photo object {p.name!r} matched no scan cluster (occluded, merged or too small)")
        offline = []
        for o in todo:
            p = matched.get(o.id)
            if p is not None:
                self._rename(o, p.label, f"label {p.label!r} from the photo ({p.name!r} at x={p.x:.2f}, y={p.y:.2f})")
            elif self.params.label_from_shape:
                offline.append(o)
        if offline:
            self._name_offline(offline)

    def _name_offline(self, objects: list[SceneObject]) -> None:
        """Colour+shape names (:mod:`realsim.understanding.naming`), distinct within the scene."""
        scene = self.scene
        white = white_point(scene.colors) if scene.colors is not None else None  # each object's own colours balanced to it
        camera = capture_camera(scene)
        names, volumes, colours, image_x = [], [], [], []
        for o in objects:
            mask = scene.labels == o.id
            pts = scene.points[mask]
            rgb = balanced(scene.colors[mask], white) if scene.colors is not None else np.zeros((0, 3))
            size, cylinder, prism = _extents(o)
            completed = " ".join(n for n in o.notes if n.startswith("completed"))
            if "open container" in completed or "as a cylinder" in completed:  # fitted round from its visible profile,
                cylinder, prism = True, False  # whatever carving and cutting from its neighbours did to its fill
            name, cols = offline_name(size, pts[np.all(np.isfinite(pts), axis=1)], rgb[np.all(np.isfinite(rgb), axis=1)], o.position[:2],
                                      cylinder, prism, open_top="open container" in completed)
            names.append(name)
            colours.append(cols)
            volumes.append(float(abs(o.visual.volume)) if o.visual is not None and o.visual.is_volume else float(np.prod(o.size)))
            image_x.append(float(camera.project(o.position + [0.0, 0.0, float(o.size[2]) / 2])[0, 0]) if camera is not None else None)
        taken = {o.label for o in scene.objects if o not in objects}
        for o, name in zip(objects, distinct(names, volumes, colours, image_x)):
            label = name.label if name.label not in taken else f"{name.label}_{o.id}"
            self._rename(o, label, name.note)

    @staticmethod
    def _rename(obj: SceneObject, label: str, note: str) -> None:
        label = safe_label(label)
        obj.label = label
        obj.name = f"obj{obj.id}_{label}"
        obj.notes.append(note)

    # ---------------------------------------------------------------- photo-only objects
    def photo_primitives(self, prepared: list[PreparedObject]) -> list[PreparedObject]:
        """With no scan: photo objects no mesh accounts for, as table-sized primitives."""
        if self.scene.points is not None:
            return []
        photo = self.photo_objects()
        if not photo:
            return []
        path = self.photo_path() or Path("photo")
        have = [lookup(p.label) for p in prepared]
        taken: set[int] = set()
        out = []
        for p in photo:
            cat = lookup(p.label)
            hit = next((i for i, m in enumerate(have) if i not in taken and m is not None and cat is not None
                        and m.category.name == cat.category.name), None)
            if hit is not None:
                taken.add(hit)
                continue
            extents, round_ = primitive_extents(p.label, p.size_m)
            rgb = p.rgb01()
            rgba = (*(rgb if rgb is not None else (0.6, 0.6, 0.6)), 1.0)
            shape = "cylinder" if round_ else "box"
            dims = " x ".join(f"{v * 1000:.0f}" for v in extents)
            out.append(prepared_from_mesh(p.label, primitive_mesh(extents, round_), path, rgba,
                                          [f"from the photo ({p.name!r}): no mesh, a {shape} of {dims} mm from the size table"]))
        return out

    # ---------------------------------------------------------------- manifests
    def _context(self, labels: list[str]) -> str:
        supports = ", ".join(f"{p.kind} at {p.height:.2f} m" for p in self.scene.planes) or "a table"
        return f"objects in the scene: {', '.join(sorted(labels))}; supports: {supports}"

    def manifests(self, prepared: list[PreparedObject]) -> list[ObjectManifest]:
        """A manifest per prepared object (offline without Claude: exactly ``estimate_manifest``).

        With Claude and ``scan_manifests``, scan clusters get manifests too (set on the objects).
        """
        offline = [estimate_manifest(p) for p in prepared]
        if not self.use_claude:
            return offline
        scan = [o for o in self.scene.objects if o.source_file is None and o.visual is not None and o.manifest is None] if self.params.scan_manifests else []
        scan_prepared = [prepared_from_mesh(o.label, o.visual, Path(f"scan:{o.name}"), (*(o.color if o.color is not None else (0.6, 0.6, 0.6)), 1.0)) for o in scan]
        scan_offline = [estimate_manifest(p) for p in scan_prepared]
        jobs = list(zip(prepared + scan_prepared, offline + scan_offline))
        names = [p.label for p in prepared] + [o.name for o in scan]
        context = self._context([p.label for p, _ in jobs])
        thumbs: list[bytes | None] = []
        for prep, _ in jobs:  # rendering stays on this thread (one GL context)
            try:
                thumbs.append(thumbnail(prep.visual, prep.rgba, self.cache) if self.params.thumbnails else None)
            except Exception as exc:  # no GL: describe the object in text only
                thumbs.append(None)
                self.scene.warn(f"{prep.label}: no thumbnail ({type(exc).__name__}: {clean_text(exc, 100)})")
        results = self._run(jobs, names, context, thumbs)
        for o, m in zip(scan, results[len(prepared):]):
            apply_manifest(o, m)
        return results[: len(prepared)]

    def _run(self, jobs: list[tuple[PreparedObject, ObjectManifest]], names: list[str], context: str, thumbs: list[bytes | None]) -> list[ObjectManifest]:
        results: list[ObjectManifest | None] = [None] * len(jobs)
        pool = ThreadPoolExecutor(max_workers=max(1, self.params.max_workers), thread_name_prefix="claude-manifest")
        futures = {
            pool.submit(claude_manifest, prep, name=name, context=context, thumbnail_png=thumb, settings=self.settings,
                        log=self.log, cache=self.cache, offline=off): i
            for i, ((prep, off), name, thumb) in enumerate(zip(jobs, names, thumbs))
        }
        started = time.monotonic()
        done, _ = wait(futures, timeout=self.params.timeout_s)
        pool.shutdown(wait=False, cancel_futures=True)
        for fut, i in futures.items():
            prep, off = jobs[i]
            if fut not in done:
                why = f"no answer within the {self.params.timeout_s:g} s deadline for all manifests"
                self._fail(f"{names[i]} manifest", why)
                results[i] = fallback_manifest(off, why)
                continue
            try:
                outcome = fut.result()
            except Exception as exc:  # a bug must not fail the conversion either
                why = f"{type(exc).__name__}: {exc}"
                self._fail(f"{names[i]} manifest", why)
                results[i] = fallback_manifest(off, clean_text(why, 200))
                continue
            if outcome.error:
                self._fail(f"{names[i]} manifest", outcome.error)
            elif outcome.rejected:
                self.scene.warn(f"{names[i]}: Claude value(s) rejected, offline estimate kept: {', '.join(sorted(outcome.rejected))}")
            results[i] = outcome.manifest
        self.elapsed_s = round(time.monotonic() - started, 3)
        return [r for r in results if r is not None]

    # ---------------------------------------------------------------- report
    def finish(self) -> dict[str, Any] | None:
        """Record the ``llm`` section on the scene (``scene.llm``) when Claude was used."""
        if not self.use_claude or (self.log.usage.calls == 0 and self.log.cache_hits == 0 and not self.log.failures):
            return None
        record = self.log.record()
        record["elapsed_s"] = self.elapsed_s
        previous = getattr(self.scene, "llm", None)
        if isinstance(previous, dict):  # another stage already reported: sum
            for k in ("calls", "cache_hits", "input_tokens", "output_tokens", "cost_usd", "elapsed_s"):
                record[k] = previous.get(k, 0) + record[k]
            record["failures"] = list(previous.get("failures", [])) + record["failures"]
            record["prompts"] = {**previous.get("prompts", {}), **record["prompts"]}
        self.scene.llm = record
        return record


def _extents(obj: SceneObject) -> tuple[np.ndarray, bool, bool]:
    """(yaw-free extents, cylinder, prism) of a completed scan object."""
    cyl = is_cylinder(obj.visual, obj.size)
    prism = not cyl and is_prism(obj.visual)
    if prism:
        return np.asarray(obj.visual.bounding_box_oriented.primitive.extents, float), cyl, prism
    return np.asarray(obj.size, float), cyl, prism


def apply_manifest(obj: SceneObject, manifest: ObjectManifest) -> None:
    """Put a manifest's mass properties and contact parameters on a SceneObject."""
    ixx, iyy, izz, ixy, ixz, iyz = manifest.inertia
    obj.mass = manifest.mass_kg
    obj.com = np.asarray(manifest.com, dtype=np.float64)
    obj.inertia = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
    obj.friction = tuple(manifest.friction)
    obj.solref = tuple(manifest.solref)
    obj.manifest = manifest
