"""The runtime side (run, view, export, planners, robot) reads a scene folder through
realsim.scene_format and never imports a conversion module: a scene runs without the converter."""

from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "realsim"
RUNTIME_SIDE = ("runtime", "viewer", "export", "planner", "robot")
CONVERSION = ("capture", "planes", "segment", "segment_stage", "completion", "compose", "objects_stage", "layout", "settle", "text",
              "understanding", "pipeline", "robot_stage", "appearance", "backdrop", "arena", "synth", "synthetic", "rgbd", "pcd_io",
              "output", "assets")


def imports_of(path: Path) -> set[str]:
    """The realsim modules a file imports (top level and inside functions)."""
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("realsim"):
            found.add(node.module)
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.startswith("realsim"))
    return found


def test_runtime_side_imports_no_conversion_module() -> None:
    crossings = []
    for side in RUNTIME_SIDE:
        for path in sorted((PACKAGE / side).rglob("*.py")):
            for module in imports_of(path):
                parts = module.split(".")
                if len(parts) > 1 and parts[1] in CONVERSION:
                    crossings.append(f"{path.relative_to(PACKAGE)} imports {module}")
    assert not crossings, crossings


STAGE_MODULES = {  # the module behind each name in pipelines/*.yaml
    "load": "capture.py", "planes": "planes.py", "segment": "segment_stage.py", "complete": "completion/stage.py",
    "objects": "objects_stage.py", "compose": "compose.py", "robot": "robot_stage.py", "settle": "settle.py", "write": "output.py",
    "text": "text/stage.py", "photo": "understanding/photo_scene.py",
}
NESTED_PARAMS = {("text/stage.py", "realsim.objects_stage")}  # TextParams nests ObjectsParams (the text path's objects)


def test_no_stage_imports_another_stage() -> None:
    modules = {"realsim." + f.removesuffix(".py").replace("/", "."): f for f in STAGE_MODULES.values()}
    crossings = [f"{f} imports {m}" for f in STAGE_MODULES.values() for m in imports_of(PACKAGE / f)
                 if m in modules and modules[m] != f and (f, m) not in NESTED_PARAMS]
    assert not crossings, crossings
