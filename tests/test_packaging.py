"""The installed package: the command lives inside the realsim namespace, never as a bare ``cli``."""

from __future__ import annotations

import subprocess
import sys
from importlib.metadata import entry_points
from pathlib import Path


def test_command_is_inside_the_package() -> None:
    (script,) = [e for e in entry_points(group="console_scripts") if e.name == "realsim"]
    assert script.value == "realsim.cli:main"


def test_no_top_level_cli_module_is_installed(tmp_path) -> None:
    # outside the checkout only what is installed can be imported
    probe = "import importlib.util as u; print(u.find_spec('cli') is None, u.find_spec('realsim.cli') is not None)"
    out = subprocess.run([sys.executable, "-c", probe], cwd=tmp_path, capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["True", "True"]


def test_every_subpackage_is_packaged() -> None:
    """A package folder missing from pyproject's list would be left out of a wheel (``pip install .``)."""
    import tomllib

    root = Path(__file__).resolve().parents[1]
    listed = set(tomllib.loads((root / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"])
    found = {".".join(p.parent.relative_to(root).parts) for p in (root / "realsim").rglob("__init__.py")}
    assert found <= listed, sorted(found - listed)
