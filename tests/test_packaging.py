"""The installed package: the command lives inside the realsim namespace, never as a bare ``cli``."""

from __future__ import annotations

import subprocess
import sys
from importlib.metadata import entry_points


def test_command_is_inside_the_package() -> None:
    (script,) = [e for e in entry_points(group="console_scripts") if e.name == "realsim"]
    assert script.value == "realsim.cli:main"


def test_no_top_level_cli_module_is_installed(tmp_path) -> None:
    # outside the checkout only what is installed can be imported
    probe = "import importlib.util as u; print(u.find_spec('cli') is None, u.find_spec('realsim.cli') is not None)"
    out = subprocess.run([sys.executable, "-c", probe], cwd=tmp_path, capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["True", "True"]
