"""Scene understanding end to end: `convert` with the local Messages server, and offline."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import trimesh
import yaml
from PIL import Image

sys.path.insert(0, str(Path(__file__).parent))
from anthropic_server import Reply, tool_use  # noqa: E402
from test_understanding import RECORD_CAN, VALUES_CAN, RoutingServer, tool_name, user_text  # noqa: E402

from conftest import DATA, REPO, YCB  # noqa: E402
from realsim.assets import prepare_object  # noqa: E402
from realsim.cache import DiskCache  # noqa: E402
from realsim.perception.pcd_io import read_pcd  # noqa: E402
from realsim.physics import estimate_manifest  # noqa: E402
from realsim.pipeline import convert  # noqa: E402
from realsim.understanding.manifest_claude import RECORD_TOOL, VALUES_TOOL  # noqa: E402
from realsim.understanding.photo import PHOTO_TOOL  # noqa: E402

NO_ROBOT = {"robot": {"enabled": False}}


def manifest_reply(body: dict[str, Any]) -> Reply:
    if tool_name(body) == RECORD_TOOL:
        return tool_use(RECORD_TOOL, RECORD_CAN, input_tokens=800, output_tokens=100)
    # a plausible mass for whatever was measured: 400 kg/m^3 of the stated closed volume
    text = user_text(body)
    volume_cm3 = float(text.split("closed volume ")[1].split(" cm^3")[0])
    return tool_use(VALUES_TOOL, {**VALUES_CAN, "mass_kg": round(max(volume_cm3 * 4e-4, 0.01), 4)}, input_tokens=600, output_tokens=60)


@pytest.fixture(scope="module")
def synthetic(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The synthetic tabletop without its labels, with the RGB of the cloud as ``photo.png``."""
    from realsim.synth.tabletop import make_tabletop_capture

    dest = make_tabletop_capture(tmp_path_factory.mktemp("synthetic") / "capture", seed=0)
    meta = yaml.safe_load((dest / "capture.yaml").read_text())
    meta.pop("labels")
    (dest / "capture.yaml").write_text(yaml.safe_dump(meta))
    cloud = read_pcd(dest / "scene.pcd")
    h, w = cloud.grid_shape
    rgb = np.nan_to_num(cloud.colors.reshape(h, w, 3)) * 255
    Image.fromarray(rgb.astype(np.uint8)).save(dest / "photo.png")
    return dest


def _photo_objects(capture: Path) -> list[dict[str, Any]]:
    """What Claude would report: each ground-truth object at its projected centre in the photo."""
    gt = json.loads((capture / "ground_truth.json").read_text())
    cam = gt["camera"]
    world_to_optical = np.linalg.inv(np.asarray(cam["pose_optical_to_world"]))
    out = []
    for o in gt["objects"]:
        centre = np.asarray(o["position"]) + [0.0, 0.0, o["size"][2] / 2]
        p = world_to_optical[:3, :3] @ centre + world_to_optical[:3, 3]
        u, v = cam["fx"] * p[0] / p[2] + cam["cx"], cam["fy"] * p[1] / p[2] + cam["cy"]
        rgb = [int(255 * c) for c in o["color"]]
        out.append({"name": f"the {o['label'].replace('_', ' ')}", "label": o["label"], "size_m": o["size"], "color": "some",
                    "rgb": rgb, "x": (u + 0.5) / cam["width"], "y": (v + 0.5) / cam["height"]})
    return out


def test_scan_with_photo_labels_clusters_and_claude_manifests(synthetic: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    photo = _photo_objects(synthetic)

    def route(body: dict[str, Any]) -> Reply:
        if tool_name(body) == PHOTO_TOOL:
            return tool_use(PHOTO_TOOL, {"objects": photo}, input_tokens=1500, output_tokens=300)
        return manifest_reply(body)

    with RoutingServer(route) as server:
        monkeypatch.setenv("ANTHROPIC_API_KEY", "sk-test-local")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", server.base_url)
        monkeypatch.setenv("REALSIM_CACHE", str(tmp_path / "cache"))
        scene = convert(synthetic, tmp_path / "out", overrides=NO_ROBOT)
        calls, requests = server.distinct_calls, server.calls
        gt = json.loads((synthetic / "ground_truth.json").read_text())
        # every ground-truth object names the cluster that holds its points (the annotation says which)
        for o in scene.objects:
            ids = scene.annotations[scene.labels == o.id]
            ids = ids[ids >= 20] // 10
            if len(ids) < 0.5 * (scene.labels == o.id).sum():
                continue
            truth = next(g["label"] for g in gt["objects"] if g["id"] == int(np.bincount(ids).argmax()))
            assert o.label == truth, (o.name, truth)
            assert o.name == f"obj{o.id}_{truth}"
            assert o.manifest is not None and o.manifest.sources["mass_kg"] == "claude"
        labelled = {o.label for o in scene.objects}
        assert {g["label"] for g in gt["objects"]} <= labelled
        record = json.loads((tmp_path / "out" / "scene.json").read_text())
        for o in record["objects"]:
            assert o["manifest"]["sources"]["friction"] in ("claude", "fallback")
        assert scene.llm["calls"] == calls and scene.llm["input_tokens"] > 0 and scene.llm["cost_usd"] > 0
        assert sum(tool_name(r) == PHOTO_TOOL for r in server.requests) == 1
        # a rerun is free: every reply comes from the cache
        again = convert(synthetic, tmp_path / "out2", overrides=NO_ROBOT)
        assert server.calls == requests and again.llm["calls"] == 0 and again.llm["cache_hits"] == calls
        assert [o.name for o in again.objects] == [o.name for o in scene.objects]
        assert (tmp_path / "out" / "scene.xml").read_text() == (tmp_path / "out2" / "scene.xml").read_text()


def test_scan_without_key_labels_clusters_from_shape(synthetic: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    scene = convert(synthetic, tmp_path / "out", overrides=NO_ROBOT)
    by_shape = [o for o in scene.objects if any("name from colour" in n for n in o.notes)]
    assert len(by_shape) >= 4
    words = {w for o in by_shape for w in o.label.split("_")}
    assert "box" in words and words & {"cup", "can", "cylinder", "bowl"}  # shoe/cereal boxes; mug, can: colour + shape
    said = ["_".join(w for w in o.label.split("_") if w not in ("tall", "flat")) for o in scene.objects]
    assert len(set(said)) == len(said)  # no two objects share a name a person would use
    assert all(o.manifest is None for o in scene.objects)  # scan objects keep compose's defaults offline
    assert any("photo photo.png: ignored" in w for w in scene.warnings)
    assert getattr(scene, "llm", None) is None


def test_ycb_without_key_keeps_the_offline_manifests(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    capture = tmp_path / "ycb"
    for name in ("061_foam_brick",):  # the 15 YCB objects: see the report (checked once, ~5 min cold)
        (capture / "objects" / name).mkdir(parents=True)
        for f in ("textured.obj", "textured.mtl"):
            (capture / "objects" / name / f).symlink_to(YCB / name / f)
    scene = convert(capture, tmp_path / "out", overrides=NO_ROBOT)
    record = json.loads((tmp_path / "out" / "scene.json").read_text())
    for obj, path in zip(record["objects"], sorted((capture / "objects").rglob("textured.obj"))):
        expected = json.loads(json.dumps(estimate_manifest(prepare_object(path, cache=DiskCache())).model_dump()))
        got = obj["manifest"]
        assert got["sources"] == expected["sources"] and got["notes"] == expected["notes"]
        assert got["mass_kg"] == pytest.approx(expected["mass_kg"], abs=1e-6)
        assert "claude" not in got["sources"].values()
    assert getattr(scene, "llm", None) is None


def test_cli_convert_with_photo_uses_the_local_server(tmp_path: Path) -> None:
    """`realsim convert capture --photo p.png` in a subprocess, ANTHROPIC_* pointing at 127.0.0.1."""
    capture = tmp_path / "capture"
    (capture / "objects").mkdir(parents=True)
    box = trimesh.creation.box(extents=[0.16, 0.07, 0.21])
    box.export(capture / "objects" / "cracker_box.obj")
    (capture / "capture.yaml").write_text("support: {size: [1.0, 0.8], height: 0.75}\n")
    photo = tmp_path / "kitchen.png"
    Image.new("RGB", (64, 48), (120, 100, 90)).save(photo)
    reply = {"objects": [
        {"name": "cracker box", "label": "cracker box", "size_m": [0.16, 0.07, 0.21], "color": "red", "x": 0.3, "y": 0.5},
        {"name": "blue mug", "label": "mug", "size_m": [0.12, 0.09, 0.09], "color": "blue", "x": 0.7, "y": 0.5},
    ]}

    def route(body: dict[str, Any]) -> Reply:
        if tool_name(body) == PHOTO_TOOL:
            return tool_use(PHOTO_TOOL, reply)
        return manifest_reply(body)

    with RoutingServer(route) as server:
        env = {**os.environ, "ANTHROPIC_API_KEY": "sk-test-local", "ANTHROPIC_BASE_URL": server.base_url,
               "REALSIM_CACHE": str(tmp_path / "cache"), "MENAGERIE_ROOT": str(DATA), "MUJOCO_GL": "egl"}
        proc = subprocess.run([sys.executable, str(REPO / "cli.py"), "convert", str(capture), "-o", str(tmp_path / "out"),
                               "--photo", str(photo), "--no-robot", "-q"], env=env, capture_output=True, text=True, timeout=300)
        assert proc.returncode == 0, proc.stderr
        assert server.calls == 5  # photo + 2 passes x 2 objects
    record = json.loads((tmp_path / "out" / "scene.json").read_text())
    assert [o["label"] for o in record["objects"]] == ["cracker_box", "mug"]
    for o in record["objects"]:
        sources = o["manifest"]["sources"]
        assert sources["mass_kg"] == "claude" and sources["friction"] == "claude" and sources["inertia"] == "geometry"
    assert any("from the photo" in n for n in record["objects"][1]["notes"])
