"""Point lists in text: XYZ (``x y z [r g b]`` a line, spaces or commas) and Leica PTS (a
point-count line, then ``x y z intensity r g b``), as surveying and scanning apps export them.
A first line of column names (CloudCompare's ``//X Y Z R G B Nx Ny Nz``, a CSV's ``x,y,z``)
says which column is which."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from realsim.errors import InputError

COLUMN_NAMES = {"x": "x", "y": "y", "z": "z", "r": "r", "red": "r", "g": "g", "green": "g", "b": "b", "blue": "b"}


def _header(line: bytes) -> list[str] | None:
    """The column names of a header line naming x, y and z (``//X Y Z R G B``, ``x,y,z``), or
    None (data, or a ``#`` comment)."""
    tokens = line.strip().lstrip(b"/#").replace(b",", b" ").replace(b";", b" ").split()
    names = [t.decode("utf-8", "replace").strip("\"'").lower() for t in tokens]
    return names if {"x", "y", "z"} <= {COLUMN_NAMES.get(n) for n in names} else None


def _rows(path: Path, skip: int = 0) -> np.ndarray:
    """The numeric table after ``skip`` lines, skipping ``#`` comments and single-number lines (PTS point counts)."""
    with path.open("rb") as fh:
        head = [ln for ln in (fh.readline() for _ in range(3 + skip)) if ln.strip()][skip:]
    single = len(head) > 0 and len(head[0].replace(b",", b" ").split()) == 1
    try:  # the common case, fast: one optional count line, then a uniform table
        return np.loadtxt(path, ndmin=2, skiprows=skip + (1 if single else 0), delimiter="," if head and b"," in head[-1] else None)
    except ValueError:
        pass
    with path.open("rb") as fh:  # several blocks, each with its count line
        lines = fh.readlines()[skip:]
        rows = [r for r in (ln.replace(b",", b" ").split() for ln in lines if not ln.lstrip().startswith(b"#")) if len(r) > 1]
    width = len(rows[0]) if rows else 0
    if any(len(r) != width for r in rows):
        raise InputError(f"{path}: not a point list (lines hold different numbers of values)")
    try:
        return np.array(rows, dtype=np.float64).reshape(-1, max(width, 1))
    except ValueError as exc:
        raise InputError(f"{path}: not a whitespace-separated point list ({str(exc)[:80]})") from None


def read_text_points(path: Path) -> tuple[np.ndarray, np.ndarray | None]:
    """(N, 3) float64 points and (N, 3) colours in [0, 1] (None without colour): ``x y z r g b``
    (XYZ) or ``x y z intensity r g b`` (PTS, 7 values a line), or the columns a header line names."""
    with path.open("rb") as fh:
        first = next((ln for ln in fh if ln.strip()), b"")
    names = _header(first)
    arr = _rows(path, skip=0 if names is None else _line_index(path, first) + 1)
    if arr.shape[1] < 3 or len(arr) == 0:
        raise InputError(f"{path}: each line needs x y z")
    if names is not None:
        return _named_columns(path, arr, names)
    start = 4 if arr.shape[1] in (4, 7) else 3  # PTS puts an intensity before the colour
    return arr[:, :3].astype(np.float64), _colours(arr[:, start:start + 3]) if arr.shape[1] >= start + 3 else None


def _line_index(path: Path, line: bytes) -> int:
    """The index of the first line equal to ``line`` (blank lines before a header count)."""
    with path.open("rb") as fh:
        return next(i for i, ln in enumerate(fh) if ln == line)


def _named_columns(path: Path, arr: np.ndarray, names: list[str]) -> tuple[np.ndarray, np.ndarray | None]:
    """Points and colours from the columns a header names (``x y z`` required, ``r g b`` optional)."""
    where = {COLUMN_NAMES[n]: i for i, n in enumerate(names) if n in COLUMN_NAMES and i < arr.shape[1]}
    if len(names) != arr.shape[1] or not {"x", "y", "z"} <= where.keys():
        raise InputError(f"{path}: the header line names columns {' '.join(names)!r} but the rows hold "
                         f"{arr.shape[1]} values; expected x y z columns (then optional r g b)")
    points = arr[:, [where["x"], where["y"], where["z"]]].astype(np.float64)
    return points, _colours(arr[:, [where["r"], where["g"], where["b"]]]) if {"r", "g", "b"} <= where.keys() else None


def _colours(rgb: np.ndarray) -> np.ndarray:
    """Colours in [0, 1] from 0-255 or 0-1 values."""
    return np.clip(rgb / (255.0 if rgb.max(initial=0) > 1 else 1.0), 0.0, 1.0)
