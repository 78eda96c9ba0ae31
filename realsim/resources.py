"""Where the project's data folders are: ``pipelines/``, ``size_tables/``, ``prompts/``.

In a source checkout they sit beside the package; ``pip install .`` installs them as the
subpackages ``realsim.pipelines``, ``realsim.size_tables`` and ``realsim.prompts``.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

DATA_FOLDERS = ("pipelines", "size_tables", "prompts")


def data_dir(name: str) -> Path:
    """The folder holding the project's ``name`` data (one of :data:`DATA_FOLDERS`)."""
    if name not in DATA_FOLDERS:
        raise ValueError(f"unknown data folder {name!r}")
    source = Path(__file__).resolve().parents[1] / name
    if source.is_dir():
        return source
    return Path(str(resources.files(f"realsim.{name}")))
