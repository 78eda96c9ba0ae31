"""Versioned prompt files in ``prompts/`` (first line ``version: ...``)."""

from __future__ import annotations

from functools import lru_cache

from realsim.errors import InputError
from realsim.resources import data_dir

PHOTO_PROMPT = "photo_objects.md"
RECORD_PROMPT = "manifest_record.md"
VALUES_PROMPT = "manifest_values.md"


@lru_cache(maxsize=16)
def load_prompt(name: str) -> tuple[str, str]:
    """(version, text) of ``prompts/<name>``."""
    raw = (data_dir("prompts") / name).read_text(encoding="utf-8")
    first, _, rest = raw.partition("\n")
    if not first.startswith("version:"):
        raise InputError(f"prompts/{name} must start with a 'version:' line")
    return first.split(":", 1)[1].strip(), rest.strip() + "\n"
