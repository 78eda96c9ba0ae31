"""Scene understanding: object labels (photo, shape) and physics manifests (Claude, two passes).

- :class:`Understanding` — used by the ``objects`` stage: labels scan clusters, turns photo
  objects without meshes into primitives, computes manifests concurrently with fallbacks.
- :func:`label_photo` / :func:`match_clusters` — objects from a photo and their scan clusters.
- :func:`claude_manifest` — the two Claude passes for one object, validated per value.
- :func:`render_thumbnail` — a 256x256 PNG of a mesh (MuJoCo offscreen).
- :func:`label_from_shape` — the nearest size-table category by extents and cylinder/box.
"""

from realsim.understanding.calls import CallLog
from realsim.understanding.camera import CaptureCamera, capture_camera
from realsim.understanding.manifest_claude import ClaudeManifest, MetricsRecord, claude_manifest, merge, plausible_mass
from realsim.understanding.photo import PhotoObject, find_photo, label_photo, match_clusters
from realsim.understanding.sanitize import clean_text, safe_label
from realsim.understanding.shape_label import ShapeLabel, is_cylinder, label_from_shape
from realsim.understanding.stage import Understanding, UnderstandingParams, apply_manifest
from realsim.understanding.thumbnail import render_thumbnail

__all__ = [
    "CallLog", "CaptureCamera", "ClaudeManifest", "MetricsRecord", "PhotoObject", "ShapeLabel", "Understanding", "UnderstandingParams",
    "apply_manifest", "capture_camera", "claude_manifest", "clean_text", "find_photo", "is_cylinder", "label_from_shape", "label_photo",
    "match_clusters", "merge", "plausible_mass", "render_thumbnail", "safe_label",
]
