"""Is a capture a photo alone? And the offline answer to one (light: no heavy imports, so the CLI
can refuse a photo without a key at once)."""

from __future__ import annotations

import os
from pathlib import Path

from realsim.errors import InputError

PHOTO_SUFFIXES = (".jpg", ".jpeg", ".png", ".webp")
NEEDS_KEY = ("a photo alone needs Claude to describe it: set ANTHROPIC_API_KEY, or convert a scan, a mesh or a description "
             "(--text \"a table with a mug\")")


def photo_only(source: str | Path | None) -> bool:
    """True for a photo file, or a folder holding photo.* and no scene.*, objects/* or text."""
    if source is None:
        return False
    p = Path(source)
    if p.is_file():
        return p.suffix.lower() in PHOTO_SUFFIXES
    if not p.is_dir() or any(p.glob("scene.*")) or any((p / "objects").glob("*")):
        return False
    yaml_file = p / "capture.yaml"
    if yaml_file.is_file() and "text:" in yaml_file.read_text(errors="replace"):
        return False
    return any(q.suffix.lower() in PHOTO_SUFFIXES for q in p.glob("photo.*"))


def check_photo_offline(source: str | Path | None, text: str | None = None) -> None:
    """InputError (exit 2) for a photo alone when no ANTHROPIC_API_KEY is set."""
    if not text and photo_only(source) and not os.environ.get("ANTHROPIC_API_KEY"):
        raise InputError(NEEDS_KEY)
