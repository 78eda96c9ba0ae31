"""The runtime side (run, view, export, planners, robot) reads a scene folder through
realsim.scene_format and never imports a conversion module: a scene runs without the converter."""

from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "realsim"
RUNTIME_SIDE = ("runtime", "viewer", "export", "planner", "robot")
CONVERSION = ("perception", "composition", "completion", "text", "understanding", "pipeline", "stages", "synth", "output", "assets")


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


def _stage_modules() -> dict[str, str]:
    """Stage name -> the module whose function it runs (the algorithm behind each thin adapter)."""
    from realsim.stages import STAGES

    behind = {"realsim.stages.load": "realsim.perception.capture", "realsim.stages.write": "realsim.output"}  # adapters with a little glue
    return {name: behind.get(stage.run.__module__, stage.run.__module__) for name, stage in STAGES.items()}


NESTED_PARAMS = {("realsim.text.stage", "realsim.composition.objects")}  # TextParams nests ObjectsParams (the text path's objects)


def _file(module: str) -> Path:
    path = PACKAGE.parent / (module.replace(".", "/") + ".py")
    return path if path.exists() else PACKAGE.parent / module.replace(".", "/") / "__init__.py"


def test_no_stage_imports_another_stage() -> None:
    modules = set(_stage_modules().values())
    crossings = [f"{m} imports {other}" for m in sorted(modules) for other in imports_of(_file(m))
                 if other in modules and other != m and (m, other) not in NESTED_PARAMS]
    assert not crossings, crossings


def test_every_adapter_is_thin() -> None:
    """Each module in realsim/stages/ imports only the stage base, the algorithm it runs and plain types."""
    allowed = {"realsim.stages.base", "realsim.scene", "realsim.errors"}
    for path in sorted((PACKAGE / "stages").glob("*.py")):
        if path.name in ("__init__.py", "base.py"):
            continue
        imported = imports_of(path) - allowed
        assert len({m.split(".")[1] for m in imported}) == 1, (path.name, imported)


def test_runtime_side_loads_no_conversion_module() -> None:
    """Transitively too: importing the runtime, viewer and export leaves every conversion module unloaded."""
    import subprocess
    import sys

    probe = ("import sys, realsim.runtime, realsim.viewer, realsim.export; "
             f"print(sorted(m for m in sys.modules if m.startswith('realsim.') and m.split('.')[1] in {CONVERSION!r}))")
    loaded = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout.strip()
    assert loaded == "[]", loaded
