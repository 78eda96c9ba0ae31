"""Scene understanding: photo labels, label-from-shape and two-pass Claude manifests.

Every Claude call goes through the real anthropic SDK to the local Messages-API server on
127.0.0.1 (tests/anthropic_server.py); nothing reaches the internet.
"""

from __future__ import annotations

import base64
import io
import json
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import trimesh
from PIL import Image

sys.path.insert(0, str(Path(__file__).parent))
from anthropic_server import MessagesServer, Reply, error, tool_use  # noqa: E402

from realsim import llm  # noqa: E402
from realsim.cache import DiskCache  # noqa: E402
from realsim.perception.capture_config import CameraIntrinsics, CaptureConfig  # noqa: E402
from realsim.physics import estimate_manifest  # noqa: E402
from realsim.understanding import (  # noqa: E402
    CallLog,
    Understanding,
    UnderstandingParams,
    claude_manifest,
    label_from_shape,
    label_photo,
    match_clusters,
    safe_label,
)
from realsim.understanding.manifest_claude import RECORD_TOOL, VALUES_TOOL  # noqa: E402
from realsim.understanding.photo import PHOTO_TOOL, PhotoObject  # noqa: E402
from realsim.understanding.primitives import prepared_from_mesh, primitive_mesh  # noqa: E402
from realsim.understanding.prompts import load_prompt  # noqa: E402

Router = Callable[[dict[str, Any]], Reply]


class RoutingServer(MessagesServer):
    """The local Messages server, answering each request by its content (for concurrent calls)."""

    def __init__(self, router: Router | None = None) -> None:
        self.router = router
        super().__init__()

    def _handler(self):  # type: ignore[override]
        base = super()._handler()
        server = self

        class Handler(base):  # type: ignore[misc, valid-type]
            def do_POST(self) -> None:  # noqa: N802
                if server.router is None:
                    return super().do_POST()
                raw = self.rfile.read(int(self.headers.get("content-length") or 0))
                body = json.loads(raw or b"{}")
                with server._lock:
                    server.requests.append(body)
                reply = server.router(body)
                if reply.delay_s:
                    time.sleep(reply.delay_s)
                self._send(reply)

        return Handler


def user_text(body: dict[str, Any]) -> str:
    content = body["messages"][0]["content"]
    return " ".join(b.get("text", "") for b in content if isinstance(b, dict)) if isinstance(content, list) else str(content)


def tool_name(body: dict[str, Any]) -> str:
    return body["tool_choice"]["name"]


RECORD_CAN = {
    "material": "tinplate", "material_reason": "a steel food can", "hollow": True, "hollow_reason": "a can",
    "wall_thickness_mm": 0.2, "fill": "full", "fill_fraction": 0.95, "contents": "soup", "surface_finish": "printed paper label",
    "parts": [{"name": "can", "joint": "none", "reason": "one rigid piece"}],
}
VALUES_CAN = {
    "mass_kg": 0.35, "friction": 0.42, "restitution": 0.3, "joint_type": "free", "joint_axis": None, "joint_range": None,
    "hollow": True, "material_class": "tinplate", "reasons": {"mass_kg": "shell plus 300 ml of soup"},
}


@pytest.fixture
def server(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Iterator[RoutingServer]:
    with RoutingServer() as srv:
        monkeypatch.setenv("ANTHROPIC_API_KEY", "sk-test-local")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", srv.base_url)
        monkeypatch.setenv("REALSIM_CACHE", str(tmp_path / "cache"))
        yield srv


def fast(timeout: float = 5.0, retries: int = 2) -> llm.LLMSettings:
    return llm.LLMSettings(timeout_s=timeout, max_retries=retries)


def can(label: str = "can") -> Any:
    return prepared_from_mesh(label, primitive_mesh(np.array([0.068, 0.068, 0.10]), True), Path("can.obj"), (0.8, 0.2, 0.1, 1.0))


def run_manifest(settings: llm.LLMSettings | None = None, prepared: Any = None, thumb: bytes | None = b"\x89PNG fake",
                 cache: DiskCache | None = None) -> tuple[Any, CallLog]:
    log = CallLog()
    out = claude_manifest(prepared or can(), name="soup can", context="objects in the scene: can", thumbnail_png=thumb,
                          settings=settings or fast(), log=log, cache=cache or DiskCache())
    return out, log


# ---------------------------------------------------------------------------- offline pieces
def test_safe_label_bounds_model_text() -> None:
    assert safe_label("Red Mug") == "red_mug"
    assert safe_label("../../etc/passwd; rm -rf /") == "etc_passwd_rm_rf"
    assert safe_label("__import__('os')") == "import_os"
    assert safe_label("42") == "object" and safe_label("") == "object"
    assert len(safe_label("a" * 500)) == 40
    assert set(safe_label("Ünïcode ☃ mug\n")) <= set("abcdefghijklmnopqrstuvwxyz0123456789_")


def test_label_from_shape_uses_size_and_roundness() -> None:
    assert label_from_shape(np.array([0.068, 0.068, 0.10]), True).label == "can"
    assert label_from_shape(np.array([0.16, 0.07, 0.21]), False).label == "cracker_box"
    assert label_from_shape(np.array([0.16, 0.16, 0.06]), True).label == "bowl"
    assert label_from_shape(np.array([0.05, 0.05, 0.05]), False).label != label_from_shape(np.array([0.05, 0.05, 0.05]), True).label
    assert label_from_shape(np.array([3.0, 0.01, 0.01]), False) is None


def test_match_clusters_by_image_position_size_and_colour() -> None:
    photo = [
        PhotoObject(name="red mug", label="mug", size_m=(0.09, 0.09, 0.1), color="red", x=0.3, y=0.6),
        PhotoObject(name="blue can", label="can", size_m=(0.07, 0.07, 0.12), color="blue", x=0.7, y=0.55),
    ]
    sizes = [np.array([0.07, 0.07, 0.12]), np.array([0.09, 0.09, 0.1]), np.array([0.5, 0.5, 0.7])]
    xy = [np.array([0.69, 0.56]), np.array([0.31, 0.61]), np.array([0.1, 0.1])]
    assert match_clusters(sizes, xy, [None, None, None], photo) == {0: 1, 1: 0}
    # no camera: size and colour decide
    cols = [np.array([0.1, 0.2, 0.8]), np.array([0.8, 0.1, 0.1]), None]
    assert match_clusters(sizes[:2], [None, None], cols, photo) == {0: 1, 1: 0}


def test_no_key_manifests_are_the_offline_estimates(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    from realsim.scene import CaptureInfo, Scene

    scene = Scene(CaptureInfo(Path("x"), "objects", None, "m", "+z", False, False, np.eye(4)))
    objs = [can(), can("cracker_box")]
    u = Understanding(scene, UnderstandingParams(), DiskCache(enabled=False))
    got = u.manifests(objs)
    assert [m.model_dump() for m in got] == [estimate_manifest(p).model_dump() for p in objs]
    assert u.finish() is None and getattr(scene, "llm", None) is None


# ---------------------------------------------------------------------------- two passes
def test_two_passes_through_the_sdk(server: RoutingServer) -> None:
    server.push(tool_use(RECORD_TOOL, RECORD_CAN, input_tokens=900, output_tokens=120),
                tool_use(VALUES_TOOL, VALUES_CAN, input_tokens=700, output_tokens=80))
    from realsim.understanding.thumbnail import render_thumbnail

    prepared = can()
    png = render_thumbnail(prepared.visual, prepared.rgba)
    assert Image.open(io.BytesIO(png)).size == (256, 256)
    out, log = run_manifest(prepared=prepared, thumb=png)
    assert out.error is None and out.rejected == {}
    m = out.manifest
    assert m.mass_kg == pytest.approx(0.35) and m.friction[0] == pytest.approx(0.42) and m.restitution == pytest.approx(0.3)
    for k in ("mass_kg", "friction", "restitution", "joint_type", "hollow", "material_class"):
        assert m.sources[k] == "claude", k
    assert m.sources["inertia"] == "geometry"
    off = estimate_manifest(prepared)
    assert m.inertia[0] == pytest.approx(off.inertia[0] * 0.35 / off.mass_kg, rel=1e-6)
    assert any("manifest-record-1" in n for n in m.notes)
    # pass one: the thumbnail as a base64 PNG image block, forced tool use, versioned system prompt
    first, second = server.requests
    assert tool_name(first) == RECORD_TOOL and tool_name(second) == VALUES_TOOL
    image = first["messages"][0]["content"][0]
    assert image["type"] == "image" and image["source"]["media_type"] == "image/png"
    assert base64.b64decode(image["source"]["data"]) == png
    assert first["system"] == load_prompt("manifest_record.md")[1]
    assert "68 x 68 x 100 mm" in user_text(first) and "soup can" in user_text(first)
    assert '"material":"tinplate"' in user_text(second) and "tinplate" in user_text(second)
    assert (log.usage.calls, log.usage.input_tokens, log.usage.output_tokens) == (2, 1600, 200)
    assert log.usage.cost_usd > 0 and log.record()["prompts"] == {"manifest_record.md": "manifest-record-1", "manifest_values.md": "manifest-values-1"}


def test_replies_are_cached_and_prompt_version_is_in_the_key(server: RoutingServer, monkeypatch: pytest.MonkeyPatch) -> None:
    server.push(tool_use(RECORD_TOOL, RECORD_CAN), tool_use(VALUES_TOOL, VALUES_CAN))
    first, _ = run_manifest()
    again, log = run_manifest()
    assert server.calls == 2 and log.usage.calls == 0 and log.cache_hits == 2
    assert again.manifest.model_dump() == first.manifest.model_dump()
    from realsim.understanding import manifest_claude

    real = manifest_claude.load_prompt
    monkeypatch.setattr(manifest_claude, "load_prompt", lambda name: ("manifest-record-2", real(name)[1]) if name == "manifest_record.md" else real(name))
    server.push(tool_use(RECORD_TOOL, RECORD_CAN))
    _, log = run_manifest()
    # a new pass-one version asks again; pass two's input (same record, same prompt) is still cached
    assert server.calls == 3 and log.usage.calls == 1 and log.cache_hits == 1


def test_overload_529_is_retried_by_the_sdk(server: RoutingServer) -> None:
    server.push(error(529), tool_use(RECORD_TOOL, RECORD_CAN), error(429), tool_use(VALUES_TOOL, VALUES_CAN))
    out, log = run_manifest(fast(retries=2))
    assert out.error is None and out.manifest.sources["mass_kg"] == "claude"
    assert server.calls == 4 and log.usage.calls == 2


def test_overload_529_that_persists_falls_back(server: RoutingServer) -> None:
    server.push(error(529), error(529))
    out, log = run_manifest(fast(retries=1))
    off = estimate_manifest(can())
    assert out.error and "529" in out.error
    m = out.manifest
    assert m.mass_kg == off.mass_kg and m.friction == off.friction
    assert all(m.sources[k] == "fallback" for k in ("mass_kg", "friction", "restitution", "joint_type"))
    assert m.sources["inertia"] == "geometry" and any("claude manifest failed" in n for n in m.notes)
    assert log.usage.calls == 0


def test_timeout_falls_back(server: RoutingServer) -> None:
    server.push_delay(2.0, tool_use(RECORD_TOOL, RECORD_CAN))
    started = time.monotonic()
    out, _ = run_manifest(fast(timeout=0.4, retries=0))
    assert time.monotonic() - started < 1.9
    assert out.error and "timed out" in out.error and out.manifest.sources["mass_kg"] == "fallback"


def test_invalid_json_body_falls_back(server: RoutingServer) -> None:
    server.push_raw(200, b"{not json")
    out, _ = run_manifest(fast(retries=0))
    assert out.error and out.manifest.sources["friction"] == "fallback"


def test_invalid_record_falls_back(server: RoutingServer) -> None:
    server.push(tool_use(RECORD_TOOL, {"material": "", "hollow": "maybe", "parts": "lots"}))
    out, log = run_manifest()
    assert out.error and "pass one record invalid" in out.error and server.calls == 1
    assert out.manifest.sources["mass_kg"] == "fallback"


def test_out_of_range_values_fall_back_one_by_one(server: RoutingServer) -> None:
    bad = {**VALUES_CAN, "mass_kg": 40.0, "friction": 5.0, "restitution": 1.5, "joint_type": "hinge", "joint_axis": [0, 0, 1],
           "joint_range": [0, 1.5], "material_class": "unobtainium"}
    server.push(tool_use(RECORD_TOOL, RECORD_CAN), tool_use(VALUES_TOOL, bad))
    out, _ = run_manifest()
    m, off = out.manifest, estimate_manifest(can())
    assert set(out.rejected) == {"mass_kg", "friction", "restitution", "joint_type", "material_class"}
    assert "kg/m^3" in out.rejected["mass_kg"] and "parts" in out.rejected["joint_type"]
    assert (m.mass_kg, m.friction, m.restitution, m.joint_type) == (off.mass_kg, off.friction, off.restitution, "free")
    assert m.material_class == off.material_class
    assert all(m.sources[k] == "fallback" for k in out.rejected)
    assert m.sources["hollow"] == "claude"
    assert sum("rejected" in n for n in m.notes) == 5


def test_strings_and_wrong_types_are_rejected(server: RoutingServer) -> None:
    weird = {**VALUES_CAN, "mass_kg": "heavy", "friction": None, "joint_type": "teleport"}
    server.push(tool_use(RECORD_TOOL, RECORD_CAN), tool_use(VALUES_TOOL, weird))
    out, _ = run_manifest()
    assert {"mass_kg", "friction", "joint_type"} <= set(out.rejected)
    assert out.manifest.sources["restitution"] == "claude" and out.manifest.sources["mass_kg"] == "fallback"


def test_hinge_needs_parts_and_a_multi_part_mesh(server: RoutingServer) -> None:
    hulls = [trimesh.creation.box(extents=[0.4, 0.4, 0.3]).apply_translation([0, 0, 0.15]),
             trimesh.creation.box(extents=[0.4, 0.02, 0.3]).apply_translation([0, 0.21, 0.15])]
    prepared = prepared_from_mesh("cabinet", trimesh.util.concatenate(hulls), Path("cab.obj"))
    prepared.hulls = hulls
    record = {**RECORD_CAN, "material": "wood", "hollow": True, "wall_thickness_mm": 15, "fill": "empty",
              "parts": [{"name": "carcass", "joint": "none"}, {"name": "door", "joint": "hinge"}]}
    values = {**VALUES_CAN, "mass_kg": 8.0, "joint_type": "hinge", "joint_axis": [0, 0, 2], "joint_range": [0, 1.6], "material_class": "wood"}
    server.push(tool_use(RECORD_TOOL, record), tool_use(VALUES_TOOL, values))
    out, _ = run_manifest(prepared=prepared)
    m = out.manifest
    assert out.rejected == {} and m.joint_type == "hinge" and m.joint_axis == (0.0, 0.0, 1.0) and m.joint_range == (0.0, 1.6)
    assert m.is_openable and not m.is_graspable and m.sources["joint_type"] == "claude"


# ---------------------------------------------------------------------------- concurrency
def _manifest_router(delay: float = 0.0) -> Router:
    def route(body: dict[str, Any]) -> Reply:
        reply = tool_use(RECORD_TOOL, RECORD_CAN) if tool_name(body) == RECORD_TOOL else tool_use(VALUES_TOOL, VALUES_CAN)
        return Reply(reply.status, reply.body, reply.headers, delay_s=delay)

    return route


def _scene() -> Any:
    from realsim.scene import CaptureInfo, Scene

    return Scene(CaptureInfo(Path("capture"), "objects", None, "m", "+z", False, False, np.eye(4)))


def test_objects_run_concurrently(server: RoutingServer) -> None:
    """Requests overlap: while one waits on its 0.4 s reply, others arrive (judged from arrival
    times at the server, not from wall time, so a loaded machine cannot make it flaky)."""
    arrivals: list[float] = []
    route = _manifest_router(delay=0.4)

    def timed(body: dict[str, Any]) -> Reply:
        arrivals.append(time.monotonic())
        return route(body)

    server.router = timed
    scene = _scene()
    objs = [can(f"can_{i}") for i in range(4)]
    u = Understanding(scene, UnderstandingParams(max_workers=4, thumbnails=False), DiskCache())
    got = u.manifests(objs)
    in_flight = max(sum(1 for u_ in arrivals if t <= u_ < t + 0.4) for t in arrivals)
    assert in_flight >= 3, f"at most {in_flight} request(s) in flight at once"
    assert server.calls == 8 and all(m.sources["mass_kg"] == "claude" for m in got)
    record = u.finish()
    assert record["calls"] == 8 and record["input_tokens"] == 800 and scene.llm == record


def test_global_deadline_falls_back_without_waiting(server: RoutingServer) -> None:
    server.router = _manifest_router(delay=1.5)
    scene = _scene()
    u = Understanding(scene, UnderstandingParams(max_workers=2, thumbnails=False, timeout_s=0.3), DiskCache())
    started = time.monotonic()
    got = u.manifests([can(), can("mug")])
    assert time.monotonic() - started < 1.2
    assert all(m.sources["mass_kg"] == "fallback" for m in got)
    assert any("deadline" in w for w in scene.warnings)
    assert len(u.finish()["failures"]) == 2


# ---------------------------------------------------------------------------- photo
def _photo(path: Path, size: tuple[int, int] = (320, 240)) -> Path:
    Image.new("RGB", size, (200, 180, 160)).save(path)
    return path


PHOTO_REPLY = {"objects": [
    {"name": "red mug", "label": "Mug", "size_m": [0.09, 0.09, 0.1], "color": "red", "rgb": [200, 30, 30], "x": 0.3, "y": 0.6},
    {"name": "box; rm -rf /", "label": "../../cracker box", "size_m": [0.16, 0.07, 0.21], "color": "yellow", "x": 0.6, "y": 0.5},
    {"name": "ghost", "label": "ghost", "size_m": [-1, 0.1, 0.1], "color": "white", "x": 0.5, "y": 0.5},
    {"name": "far", "label": "far", "size_m": [0.1, 0.1, 0.1], "color": "white", "x": 3.0, "y": 0.5},
]}


def test_photo_objects_are_structured_and_sanitized(server: RoutingServer, tmp_path: Path) -> None:
    server.push(tool_use(PHOTO_TOOL, PHOTO_REPLY))
    log = CallLog()
    result = label_photo(_photo(tmp_path / "kitchen.png"), settings=fast(), log=log, cache=DiskCache())
    assert [o.label for o in result.objects] == ["mug", "cracker_box"]
    assert result.objects[1].name == "box; rm -rf /"  # kept as display data only; labels are safe
    assert len(result.notes) == 2
    req = server.requests[0]
    img = req["messages"][0]["content"][0]
    assert img["type"] == "image" and img["source"]["media_type"] == "image/jpeg"
    assert Image.open(io.BytesIO(base64.b64decode(img["source"]["data"]))).size == (320, 240)
    assert req["tool_choice"] == {"type": "tool", "name": PHOTO_TOOL}
    assert req["tools"][0]["input_schema"]["properties"]["objects"]["items"]["required"] == ["name", "label", "size_m", "color", "x", "y"]


def test_photo_without_scan_becomes_the_object_list(server: RoutingServer, tmp_path: Path) -> None:
    def route(body: dict[str, Any]) -> Reply:
        if tool_name(body) == PHOTO_TOOL:
            return tool_use(PHOTO_TOOL, PHOTO_REPLY)
        return _manifest_router()(body)

    server.router = route
    scene = _scene()
    u = Understanding(scene, UnderstandingParams(photo=str(_photo(tmp_path / "p.jpg")), thumbnails=False), DiskCache())
    prims = u.photo_primitives([can("cracker_box")])  # the cracker box has a mesh; the mug does not
    assert [p.label for p in prims] == ["mug"]
    mug = prims[0]
    assert mug.size[0] == pytest.approx(mug.size[1]) and mug.solid_method == "primitive"  # a cylinder from the table
    assert any("from the photo" in w for w in mug.warnings)


def test_photo_failure_is_noted_not_fatal(server: RoutingServer, tmp_path: Path) -> None:
    server.push(error(500), error(500))
    scene = _scene()
    u = Understanding(scene, UnderstandingParams(photo=str(_photo(tmp_path / "p.png"))), DiskCache())
    u.params = UnderstandingParams(photo=u.params.photo)
    u.settings = fast(retries=1)
    assert u.photo_primitives([]) == []
    assert any("photo p.png: Claude failed" in w for w in scene.warnings)


def test_unreadable_photo_is_an_input_error(server: RoutingServer, tmp_path: Path) -> None:
    from realsim.errors import InputError

    bad = tmp_path / "photo.jpg"
    bad.write_bytes(b"not an image")
    with pytest.raises(InputError, match="not a readable image"):
        label_photo(bad, settings=fast(), log=CallLog(), cache=DiskCache())
    assert server.calls == 0


def test_capture_camera_projects_points_to_their_pixels() -> None:
    from realsim.perception.capture import up_rotation
    from realsim.scene import CaptureInfo, Scene
    from realsim.synth.tabletop import backproject
    from realsim.understanding import capture_camera

    h, w = 48, 64
    depth = 0.8 + 0.4 * np.random.default_rng(0).random((h, w))
    optical = backproject(depth, 45.0).reshape(-1, 3)
    T = np.eye(4)
    T[:3, :3] = up_rotation("-y") @ np.array([[1, 0, 0], [0, np.cos(0.3), -np.sin(0.3)], [0, np.sin(0.3), np.cos(0.3)]])
    T[:3, 3] = [0.2, -0.1, 1.1]
    world = optical @ T[:3, :3].T + T[:3, 3]
    scene = Scene(CaptureInfo(Path("c"), "pointcloud", None, "m", "-y", False, False, T, camera_view=True), points=world, grid_shape=(h, w))
    uv = capture_camera(scene).project(world)
    rows, cols = np.divmod(np.arange(h * w), w)
    assert np.allclose(uv[:, 0], (cols + 0.5) / w, atol=1e-9) and np.allclose(uv[:, 1], (rows + 0.5) / h, atol=1e-9)
    # intrinsics from capture.yaml win over the default field of view
    f = 2 * 0.5 * h / np.tan(np.radians(22.5))
    scene.capture.config = CaptureConfig(camera=CameraIntrinsics(fx=f, fy=f))
    uv2 = capture_camera(scene).project(world)
    assert np.allclose(uv2[:, 0] - 0.5, 2 * (uv[:, 0] - 0.5), atol=0.02)
    scene.capture.camera_view = False
    assert capture_camera(scene) is None


def test_objects_stage_with_only_a_photo_places_primitives(server: RoutingServer, tmp_path: Path) -> None:
    from realsim.composition.objects import ObjectsParams, prepare_scene_objects

    def route(body: dict[str, Any]) -> Reply:
        return tool_use(PHOTO_TOOL, PHOTO_REPLY) if tool_name(body) == PHOTO_TOOL else _manifest_router()(body)

    server.router = route
    scene = _scene()
    params = ObjectsParams(understanding=UnderstandingParams(photo=str(_photo(tmp_path / "p.png"))))
    scene = prepare_scene_objects(scene, params)
    assert [o.name for o in scene.objects] == ["obj1_mug", "obj2_cracker_box"]
    assert all(o.manifest.sources["mass_kg"] == "claude" and o.mass == pytest.approx(0.35) for o in scene.objects)
    assert all(o.position[2] > 0.7 for o in scene.objects)  # placed on the assumed table
    assert scene.llm["calls"] == 5
