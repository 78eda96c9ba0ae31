"""Text from the model is data: bound it and reduce it to safe identifiers before use.

Nothing Claude writes reaches a shell, a file path or the sandbox: labels become body names only
through :func:`safe_label` (``[a-z0-9_]``, bounded length); free text is one line, bounded.
"""

from __future__ import annotations

import re

MAX_LABEL = 40
MAX_TEXT = 300


def safe_label(text: object, limit: int = MAX_LABEL, default: str = "object") -> str:
    """``[a-z0-9_]`` only, no leading digits/underscores, at most ``limit`` characters."""
    s = re.sub(r"[^a-z0-9]+", "_", str(text).lower())
    s = re.sub(r"^[0-9_]+", "", s).strip("_")[:limit].strip("_")
    return s or default


def clean_text(text: object, limit: int = MAX_TEXT) -> str:
    """One printable line of at most ``limit`` characters (control characters dropped)."""
    s = "".join(ch if ch.isprintable() else " " for ch in str(text))
    s = " ".join(s.split())
    return s if len(s) <= limit else s[: limit - 3] + "..."
