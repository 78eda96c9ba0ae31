"""The ``segment`` stage: objects from the scan, as SceneObjects with ids, supports and labels."""

from __future__ import annotations

import numpy as np

from realsim.compose import safe_name
from realsim.scene import Scene, SceneObject
from realsim.segment import SegmentParams, segment_objects

__all__ = ["SegmentParams", "segment_scene"]


def _label_for(scene: Scene, mask: np.ndarray) -> str:
    """The name capture.yaml gives the annotated object most of the cluster's points belong to."""
    names = scene.capture.metadata.get("labels") or {}
    if not names or scene.annotations is None:
        return "object"
    annotated = scene.annotations[mask]
    ids = annotated[annotated >= 20] // 10
    if len(ids) < 0.5 * mask.sum():
        return "object"
    majority = int(np.bincount(ids.astype(np.int64)).argmax())
    label = names.get(majority, names.get(str(majority)))
    return str(label) if label else "object"


def segment_scene(scene: Scene, params: SegmentParams = SegmentParams()) -> Scene:
    """Label every input point (0 support, -1 noise, k object) and create one SceneObject per k."""
    if scene.points is None:
        return scene
    result = segment_objects(scene.points, scene.colors, scene.planes, scene.grid_shape, params, seed=scene.seed)
    scene.labels = result.labels.astype(np.int32)
    counts = np.bincount(scene.labels[scene.labels > 0], minlength=int(scene.labels.max(initial=0)) + 1)
    scene.objects = []
    for k in range(1, len(counts)):
        if counts[k] == 0:
            continue
        label = _label_for(scene, scene.labels == k)
        scene.objects.append(
            SceneObject(
                id=k,
                name=f"obj{k}_{safe_name(label)}",
                label=label,
                position=np.zeros(3),
                quat=np.array([1.0, 0.0, 0.0, 0.0]),
                size=np.zeros(3),
                support_id=result.support_of.get(k),
                resting_on=result.resting_on.get(k),
                point_count=int(counts[k]),
            )
        )
    return scene
