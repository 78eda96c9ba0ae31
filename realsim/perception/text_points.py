"""Point lists in text: XYZ (``x y z [r g b]`` a line, spaces or commas) and Leica PTS (a
point-count line, then ``x y z intensity r g b``), as surveying and scanning apps export them."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from realsim.errors import InputError


def _rows(path: Path) -> np.ndarray:
    """The numeric table, skipping ``#`` comments and single-number lines (PTS point counts)."""
    with path.open("rb") as fh:
        head = [ln for ln in (fh.readline() for _ in range(3)) if ln.strip()]
    single = len(head) > 0 and len(head[0].replace(b",", b" ").split()) == 1
    try:  # the common case, fast: one optional count line, then a uniform table
        return np.loadtxt(path, ndmin=2, skiprows=1 if single else 0, delimiter="," if head and b"," in head[-1] else None)
    except ValueError:
        pass
    with path.open("rb") as fh:  # several blocks, each with its count line
        rows = [r for r in (ln.replace(b",", b" ").split() for ln in fh if not ln.lstrip().startswith(b"#")) if len(r) > 1]
    width = len(rows[0]) if rows else 0
    if any(len(r) != width for r in rows):
        raise InputError(f"{path}: not a point list (lines hold different numbers of values)")
    try:
        return np.array(rows, dtype=np.float64).reshape(-1, max(width, 1))
    except ValueError as exc:
        raise InputError(f"{path}: not a whitespace-separated point list ({str(exc)[:80]})") from None


def read_text_points(path: Path) -> tuple[np.ndarray, np.ndarray | None]:
    """(N, 3) float64 points and (N, 3) colours in [0, 1] (None without colour): ``x y z r g b``
    (XYZ) or ``x y z intensity r g b`` (PTS, 7 values a line)."""
    arr = _rows(path)
    if arr.shape[1] < 3 or len(arr) == 0:
        raise InputError(f"{path}: each line needs x y z")
    start = 4 if arr.shape[1] in (4, 7) else 3  # PTS puts an intensity before the colour
    colors = None
    if arr.shape[1] >= start + 3:
        rgb = arr[:, start:start + 3]
        colors = np.clip(rgb / (255.0 if rgb.max(initial=0) > 1 else 1.0), 0.0, 1.0)
    return arr[:, :3].astype(np.float64), colors
