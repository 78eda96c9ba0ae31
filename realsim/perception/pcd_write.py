"""Write PCD v0.7 files (ascii, binary, binary_compressed) as PCL does: ``x y z`` float32,
optional packed ``rgb`` and ``label``, organized or not; atomic and deterministic."""

from __future__ import annotations

import os
import struct
import tempfile
from pathlib import Path

import lzf
import numpy as np

from realsim.destination import normal_permissions

ENCODINGS = ("ascii", "binary", "binary_compressed")
DEFAULT_VIEWPOINT = (0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)


def write_pcd(
    path: Path | str,
    points: np.ndarray,
    colors: np.ndarray | None = None,
    labels: np.ndarray | None = None,
    grid_shape: tuple[int, int] | None = None,
    encoding: str = "binary_compressed",
    viewpoint: tuple[float, ...] | np.ndarray = DEFAULT_VIEWPOINT,
) -> Path:
    """Write ``x y z`` (float32), optional ``rgb`` and ``label`` fields to a PCD v0.7 file.

    ``points`` is ``(N, 3)`` or ``(H, W, 3)`` (the latter implies ``grid_shape``); NaN rows are
    written as they are. ``colors`` is ``(N, 3)`` floats in ``[0, 1]`` or uint8, stored as PCL's
    float32-packed ``rgb``. ``labels`` is ``(N,)`` non-negative integers, stored as uint32
    ``label``. With ``grid_shape=(H, W)`` the cloud is organized (``WIDTH W HEIGHT H``).
    The file is written to a temporary name and renamed, so a failure leaves no partial file.
    The output is deterministic: the same arrays give the same bytes.
    """
    path = Path(path)
    if encoding not in ENCODINGS:
        raise ValueError(f"encoding must be one of {ENCODINGS}, got {encoding!r}")
    pts = np.asarray(points)
    if pts.ndim == 3 and pts.shape[2] == 3:
        if grid_shape is None:
            grid_shape = (pts.shape[0], pts.shape[1])
        pts = pts.reshape(-1, 3)
    if pts.ndim != 2 or pts.shape[1] != 3:
        raise ValueError(f"points must be (N, 3), got shape {pts.shape}")
    n = pts.shape[0]
    if grid_shape is not None:
        h, w = int(grid_shape[0]), int(grid_shape[1])
        if h * w != n:
            raise ValueError(f"grid_shape {grid_shape} does not match {n} points")
    else:
        h, w = 1, n
    vp = tuple(float(v) for v in np.asarray(viewpoint, dtype=np.float64).reshape(-1))
    if len(vp) != 7:
        raise ValueError("viewpoint needs 7 numbers: tx ty tz qw qx qy qz")

    columns: list[tuple[str, np.ndarray, str, int]] = [
        ("x", pts[:, 0].astype("<f4"), "F", 4),
        ("y", pts[:, 1].astype("<f4"), "F", 4),
        ("z", pts[:, 2].astype("<f4"), "F", 4),
    ]
    if colors is not None:
        columns.append(("rgb", _pack_rgb(np.asarray(colors), n).view("<f4"), "F", 4))
    if labels is not None:
        lab = np.asarray(labels).reshape(-1)
        if lab.shape[0] != n:
            raise ValueError(f"labels must have {n} entries, got {lab.shape[0]}")
        if lab.size and (lab.min() < 0 or lab.max() > 2**32 - 1):
            raise ValueError("labels must be in [0, 2**32)")
        columns.append(("label", lab.astype("<u4"), "U", 4))

    vp_text = " ".join(_fmt_number(v) for v in vp)
    header = (
        "# .PCD v0.7 - Point Cloud Data file format\n"
        "VERSION 0.7\n"
        f"FIELDS {' '.join(c[0] for c in columns)}\n"
        f"SIZE {' '.join(str(c[3]) for c in columns)}\n"
        f"TYPE {' '.join(c[2] for c in columns)}\n"
        f"COUNT {' '.join('1' for _ in columns)}\n"
        f"WIDTH {w}\n"
        f"HEIGHT {h}\n"
        f"VIEWPOINT {vp_text}\n"
        f"POINTS {n}\n"
    )
    if encoding == "binary_compressed":
        uncompressed = b"".join(np.ascontiguousarray(c[1]).tobytes() for c in columns)
        compressed = lzf.compress(uncompressed) if uncompressed else b""
        if compressed is None:  # incompressible: lzf gives up, store as binary instead
            encoding = "binary"
        else:
            body = struct.pack("<II", len(compressed), len(uncompressed)) + compressed
    if encoding == "binary":
        rec = np.empty(n, dtype=[(c[0], c[1].dtype) for c in columns])
        for c in columns:
            rec[c[0]] = c[1]
        body = rec.tobytes()
    elif encoding == "ascii":
        body = _ascii_body(columns, n)
    data = (header + f"DATA {encoding}\n").encode("ascii") + body

    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        normal_permissions(Path(tmp))
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def _pack_rgb(colors: np.ndarray, n: int) -> np.ndarray:
    c = colors.reshape(-1, colors.shape[-1]) if colors.ndim == 3 else colors
    if c.ndim != 2 or c.shape[0] != n or c.shape[1] not in (3, 4):
        raise ValueError(f"colors must be (N, 3) with N={n}, got shape {colors.shape}")
    c = c[:, :3]
    if c.dtype == np.uint8:
        u8 = c.astype(np.uint32)
    else:
        f = np.nan_to_num(c.astype(np.float64), nan=0.0)
        u8 = np.clip(np.rint(f * 255.0), 0, 255).astype(np.uint32)
    return ((u8[:, 0] << 16) | (u8[:, 1] << 8) | u8[:, 2]).astype("<u4")


def _fmt_number(v: float) -> str:
    if float(v).is_integer():
        return str(int(v))
    return repr(float(v))


def _ascii_body(columns: list[tuple[str, np.ndarray, str, int]], n: int) -> bytes:
    texts: list[np.ndarray] = []
    for name, arr, kind, _ in columns:
        if name == "rgb":  # PCL convention: the packed float's bits as an unsigned integer
            texts.append(arr.view("<u4").astype(str))
        elif kind == "F":
            # numpy prints the shortest text that round-trips the float exactly; NaN as 'nan'.
            texts.append(arr.astype(str))
        else:
            texts.append(arr.astype(str))
    if n == 0:
        return b""
    rows = zip(*(t.tolist() for t in texts), strict=True)
    return ("\n".join(" ".join(r) for r in rows) + "\n").encode("ascii")

