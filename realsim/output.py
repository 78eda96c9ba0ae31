"""Write a converted scene to its output folder, atomically.

Everything goes to a temporary sibling folder first; the written ``scene.xml`` is compiled by
MuJoCo from there, and only then is the folder moved into place. A failed run leaves nothing.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

from realsim.destination import atomic_folder
from realsim.render import write_preview
from realsim.scene import Scene
from realsim.scene_format import ASSET_DIR, KEYFRAME, SCENE_FORMAT, jsonable, scene_xml, verify_compiles  # noqa: F401 (scene_xml: re-exported)


def scene_record(scene: Scene) -> dict[str, Any]:
    """The scene.json content: capture, transform, planes, objects, settling and timings."""
    cap = scene.capture
    record: dict[str, Any] = jsonable({
        "format": SCENE_FORMAT,
        "capture": {
            "source": str(cap.source),
            "kind": cap.kind,
            "environment_file": str(cap.environment_file) if cap.environment_file else None,
            "units": cap.units,
            "units_detected": cap.units_detected,
            "units_reason": cap.units_reason,  # why detection chose these units
            "point_spacing": cap.point_spacing,  # m, the capture's own resolution
            "up": cap.up,
            "up_detected": cap.up_detected,
            "faces_turned": cap.faces_turned,  # an environment mesh wound inward was turned
            "input_to_world": cap.input_to_world,
            "point_count": 0 if scene.points is None else len(scene.points),
            "grid_shape": scene.grid_shape,
        },
        "seed": scene.seed,
        "planes": [
            {
                "id": p.id, "kind": p.kind, "observed": p.observed, "normal": p.normal, "height": p.height,
                "offset": p.offset, "polygon": p.polygon, "rectangle": {"center": p.rect_center, "size": p.rect_size, "yaw": p.rect_yaw},
                "inlier_count": p.inlier_count,
            }
            for p in scene.planes
        ],
        "objects": [
            {
                "id": o.id, "name": o.name, "body": o.name, "label": o.label, "position": o.position, "quat_wxyz": o.quat,
                "size": o.size, "support_id": o.support_id, "resting_on": o.resting_on, "point_count": o.point_count,
                "color": o.color, "mass": o.mass, "friction": o.friction, "solref": o.solref,
                "source_file": o.source_file, "manifest": o.manifest, "notes": o.notes,
            }
            for o in scene.objects
        ],
        "robot": scene.robot,
        "keyframe": KEYFRAME,
        "settle": scene.settle_report,
        "timings_s": scene.timings,
        "warnings": scene.warnings,
        "llm": scene.llm,
    })
    return record


def write_scene(scene: Scene, dest: Path, *, force: bool = False) -> Path:
    """Write scene.xml, assets/, scene.json, labels.npy and preview.png to ``dest`` atomically.

    ``dest`` must be new, empty, or realsim output (replaced only with ``force``): see
    :mod:`realsim.destination`.
    """
    with atomic_folder(dest, force=force, kind="scene") as tmp:
        assets = tmp / ASSET_DIR
        assets.mkdir()
        for name, data in sorted(scene.assets.items()):
            (assets / name).write_bytes(data)
        xml = scene.spec.to_xml()
        (tmp / "scene.xml").write_text(xml)
        if scene.labels is not None:
            np.save(tmp / "labels.npy", scene.labels.astype(np.int32))
        (tmp / "scene.json").write_text(json.dumps(scene_record(scene), indent=2) + "\n")
        model = verify_compiles(tmp / "scene.xml", written_from=scene.spec)
        write_preview(tmp, model=model)  # the model just loaded from the written files
    return Path(dest)
