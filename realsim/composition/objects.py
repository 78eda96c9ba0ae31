"""The ``objects`` stage: object meshes of a capture become physics-ready SceneObjects.

Each mesh in ``objects/`` is normalized and decomposed (:mod:`realsim.assets`, parallel and
cached), gets an offline physics manifest (:mod:`realsim.physics`), and is placed upright on
a support by seeded rejection sampling: the primary support detected in the scan, or the one
``capture.yaml`` declares (``support: {size: [w, d], height: h}``), apart from the objects
already segmented from the scan.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from realsim.assets import AssetParams, PreparedObject, prepare_objects
from realsim.cache import DiskCache
from realsim.composition.layout import LayoutParams, declared_support, footprint, place_on_support
from realsim.geometry import yaw_quat
from realsim.scene import Scene, SceneObject, SupportPlane, primary_support, scene_object
from realsim.scene_format import safe_name
from realsim.understanding import Understanding, UnderstandingParams


@dataclass(frozen=True)
class ObjectsParams:
    """Asset preparation and placement parameters."""

    assets: AssetParams = field(default_factory=AssetParams)
    layout: LayoutParams = field(default_factory=LayoutParams)
    use_cache: bool = True
    progress: bool = True
    drop_clearance: float = 0.002  # m between a placed object's base and its support
    understanding: UnderstandingParams = field(default_factory=UnderstandingParams)  # labels, photo, Claude manifests


def _labels(scene: Scene) -> list[str | None]:
    """Labels from capture.yaml by file stem (``labels: {cracker: cracker_box}``), else None."""
    names = scene.capture.config.labels
    return [names.get(p.stem) or names.get(p.name) for p in scene.object_files]


def _unique_names(labels: list[str], first_id: int) -> list[str]:
    return [f"obj{first_id + i}_{safe_name(label)}" for i, label in enumerate(labels)]


def _support_for(scene: Scene) -> SupportPlane:
    if scene.planes:
        return primary_support(scene)
    support = declared_support(scene.support)
    floor = SupportPlane(0, "floor", np.array([0.0, 0.0, 1.0]), 0.0, support.polygon * 3.0, support.rect_center.copy(),
                         support.rect_size * 3.0, support.rect_yaw, 0, observed=False)
    scene.planes = [floor, support]
    if scene.support is None:
        scene.warn("no scan and no support in capture.yaml: objects are placed on a 1.2 x 0.8 m table at 0.75 m")
    return support


def prepare_scene_objects(scene: Scene, params: ObjectsParams = ObjectsParams()) -> Scene:
    """Prepare every object mesh of the capture and place it on the support.

    Scene understanding (:mod:`realsim.understanding`) names unlabelled scan clusters (photo or
    shape) and gives the manifests: Claude's when a key is set, else ``estimate_manifest``'s.
    """
    cache = DiskCache(enabled=params.use_cache)
    understanding = Understanding(scene, params.understanding, cache)
    understanding.label_scan_objects()
    prepared: list[PreparedObject] = []
    if scene.object_files:
        labels = _labels(scene)
        prepared = prepare_objects(scene.object_files, labels, params.assets, cache, progress=params.progress)
    prepared += understanding.photo_primitives(prepared)
    manifests = understanding.manifests(prepared)
    understanding.finish()
    if not prepared:
        return scene
    first_id = max((o.id for o in scene.objects), default=0) + 1
    names = _unique_names([p.label for p in prepared], first_id)
    new_objects = []
    for i, (prep, name, manifest) in enumerate(zip(prepared, names, manifests)):
        obj = scene_object(prep, manifest, first_id + i, name)
        for warning in prep.warnings:
            scene.warn(f"{prep.source.name}: {warning}")
        new_objects.append(obj)
    support = _support_for(scene)
    obstacles = [_world_footprint(o) for o in scene.objects]
    prints = [footprint(np.vstack([h.vertices[:, :2] for h in o.collision])) for o in new_objects]
    rng = np.random.default_rng(scene.seed)
    for obj, (xy, yaw) in zip(new_objects, place_on_support(prints, support, obstacles, rng, params.layout)):
        obj.position = np.array([xy[0], xy[1], support.height + params.drop_clearance])
        obj.quat = yaw_quat(yaw)
        obj.support_id = support.id
    scene.objects.extend(new_objects)
    return scene


def _world_footprint(obj: SceneObject) -> np.ndarray:
    pts = np.vstack([h.vertices[:, :2] for h in obj.collision]) if obj.collision else np.zeros((1, 2))
    w, z = obj.quat[0], obj.quat[3]
    yaw = 2 * np.arctan2(z, w)
    c, s = np.cos(yaw), np.sin(yaw)
    return footprint(pts @ np.array([[c, s], [-s, c]]) + obj.position[:2])
