"""Where the project's data folders are: ``pipelines/``, ``size_tables/``, ``prompts/``.

In a source checkout they sit beside the package; ``pip install .`` installs them as the
subpackages ``realsim.pipelines``, ``realsim.size_tables`` and ``realsim.prompts``.
"""

from __future__ import annotations

from functools import lru_cache
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


@lru_cache(maxsize=32)
def load_prompt(name: str) -> tuple[str, str]:
    """(version, text) of ``prompts/<name>``, whose first line reads ``version: ...``."""
    from realsim.errors import InputError

    raw = (data_dir("prompts") / name).read_text(encoding="utf-8")
    first, _, rest = raw.partition("\n")
    if not first.startswith("version:"):
        raise InputError(f"prompts/{name} must start with a 'version:' line")
    return first.split(":", 1)[1].strip(), rest.strip() + "\n"
