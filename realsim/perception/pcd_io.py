"""Read and write PCL ``.pcd`` point-cloud files (PCD v0.7).

``read_pcd`` handles ``DATA ascii``, ``binary`` and ``binary_compressed`` (LZF), organized and
unorganized clouds, the colour fields ``rgb`` (float32 or uint32 whose bits are ``0x00RRGGBB``)
and ``rgba`` (uint32, ``0xAARRGGBB``), an optional ``label`` field, and any other fields (which
are listed in ``PcdData.fields`` but not decoded). NaN points are kept, in file order, so an
organized cloud can be reshaped to its ``(H, W)`` grid.

The parser is our own (a few dozen lines over numpy and the ``lzf`` module that ``pypcd4``
depends on) rather than ``pypcd4.PointCloud``: pypcd4 does not check that the data section is
complete (a truncated binary file silently yields fewer points), mis-reads ``binary_compressed``
fields with ``COUNT > 1``, and writes float ``rgb`` in ascii with ``%.10f``, which turns every
packed colour into ``0.0``. Every failure is reported as :class:`realsim.errors.InputError` with a
one-line message naming the file.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass
from pathlib import Path

import lzf
import numpy as np

from realsim.errors import InputError
from realsim.perception.pcd_write import DEFAULT_VIEWPOINT, ENCODINGS, write_pcd  # noqa: F401 (the writer: re-exported)

__all__ = ["PcdData", "read_pcd", "write_pcd", "ENCODINGS"]


_NUMPY_TYPES = {
    ("F", 4): "<f4",
    ("F", 8): "<f8",
    ("U", 1): "<u1",
    ("U", 2): "<u2",
    ("U", 4): "<u4",
    ("U", 8): "<u8",
    ("I", 1): "<i1",
    ("I", 2): "<i2",
    ("I", 4): "<i4",
    ("I", 8): "<i8",
}
_HEADER_KEYS = ("VERSION", "FIELDS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT", "VIEWPOINT",
                "POINTS", "DATA")
_MAX_HEADER_BYTES = 64 * 1024


@dataclass
class PcdData:
    """The decoded content of one PCD file.

    ``points`` is ``(N, 3)`` float64 in the file's own frame and units, NaN rows kept in file
    order. ``colors`` is ``(N, 3)`` float64 in ``[0, 1]`` (or None when the file has no ``rgb`` /
    ``rgba`` field), ``labels`` is ``(N,)`` int64 from a ``label`` field (or None).
    ``grid_shape`` is ``(H, W)`` for an organized cloud (``HEIGHT > 1``), else None; row-major,
    so ``points.reshape(H, W, 3)`` is the image grid. ``viewpoint`` is the header's
    ``tx ty tz qw qx qy qz``.
    """

    points: np.ndarray
    colors: np.ndarray | None
    labels: np.ndarray | None
    grid_shape: tuple[int, int] | None
    fields: tuple[str, ...]
    viewpoint: np.ndarray
    encoding: str = "binary_compressed"

    @property
    def count(self) -> int:
        return int(self.points.shape[0])

    @property
    def finite_mask(self) -> np.ndarray:
        """``(N,)`` bool: rows whose x, y and z are all finite."""
        return np.isfinite(self.points).all(axis=1)


@dataclass(frozen=True)
class _Header:
    fields: tuple[str, ...]
    sizes: tuple[int, ...]
    types: tuple[str, ...]
    counts: tuple[int, ...]
    width: int
    height: int
    points: int
    viewpoint: tuple[float, ...]
    data: str

    def field_dtypes(self) -> list[tuple[str, np.dtype, int]]:
        out = []
        for i, (name, t, s, c) in enumerate(
            zip(self.fields, self.types, self.sizes, self.counts, strict=True)
        ):
            unique = name if name != "_" else f"_pad{i}"
            out.append((unique, np.dtype(_NUMPY_TYPES[(t, s)]), c))
        return out

    def record_dtype(self) -> np.dtype:
        parts = []
        for name, dt, c in self.field_dtypes():
            parts.append((name, dt, (c,)) if c > 1 else (name, dt))
        return np.dtype(parts)


# --------------------------------------------------------------------------------------------
# reading


def read_pcd(path: Path | str) -> PcdData:
    """Read a ``.pcd`` file; raise :class:`InputError` for anything unreadable.

    Missing, empty, truncated or corrupt files, files without ``x y z`` fields and files with
    zero points are all input errors.
    """
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: no such file; check the path to the point cloud")
    if not path.is_file():
        raise InputError(f"{path}: is not a file; pass a .pcd file")
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise InputError(f"{path}: cannot be read ({exc.strerror or exc})") from exc
    if not raw:
        raise InputError(f"{path}: the file is empty; expected a PCD point cloud")
    try:
        return _decode(path, raw)
    except InputError:
        raise
    except Exception as exc:  # noqa: BLE001 - never let a raw parser error reach the user
        detail = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise InputError(f"{path}: corrupt PCD file ({detail})") from exc


def _decode(path: Path, raw: bytes) -> PcdData:
    header, offset = _parse_header(path, raw)
    names = header.fields
    for axis in ("x", "y", "z"):
        if axis not in names:
            raise InputError(
                f"{path}: the PCD file has no '{axis}' field (fields: {' '.join(names)}); "
                "expected a point cloud with x y z"
            )
    if header.points == 0:
        raise InputError(f"{path}: the point cloud has zero points")

    if header.data == "ascii":
        table = _read_ascii(path, raw[offset:], header)
    elif header.data == "binary":
        table = _read_binary(path, raw[offset:], header)
    else:
        table = _read_binary_compressed(path, raw[offset:], header)

    points = np.stack(
        [np.asarray(table[a], dtype=np.float64).reshape(-1) for a in ("x", "y", "z")], axis=1
    )
    colors = _decode_colors(table, names)
    labels = None
    if "label" in names:
        lab = np.asarray(table["label"]).reshape(header.points, -1)[:, 0]
        if lab.dtype.kind == "f":
            lab = np.nan_to_num(lab, nan=0.0)
        labels = lab.astype(np.int64)
    grid = (header.height, header.width) if header.height > 1 else None
    return PcdData(
        points=points,
        colors=colors,
        labels=labels,
        grid_shape=grid,
        fields=names,
        viewpoint=np.asarray(header.viewpoint, dtype=np.float64),
        encoding=header.data,
    )


def _parse_header(path: Path, raw: bytes) -> tuple[_Header, int]:
    values: dict[str, list[str]] = {}
    pos = 0
    data_seen = False
    while pos < len(raw) and pos < _MAX_HEADER_BYTES:
        end = raw.find(b"\n", pos)
        end = len(raw) if end < 0 else end
        line_bytes = raw[pos:end]
        pos = end + 1
        try:
            line = line_bytes.decode("ascii").strip()
        except UnicodeDecodeError:
            raise InputError(f"{path}: not a PCD file (the header is not text)") from None
        if not line or line.startswith("#"):
            continue
        key, _, rest = line.partition(" ")
        key = key.upper()
        if key not in _HEADER_KEYS:
            raise InputError(f"{path}: not a PCD file (unexpected header line {line[:40]!r})")
        values[key] = rest.split()
        if key == "DATA":
            data_seen = True
            break
    if not data_seen:
        raise InputError(f"{path}: not a PCD file or the header is truncated (no DATA line)")

    def ints(key: str, default: list[int] | None = None) -> list[int]:
        if key not in values:
            if default is None:
                raise InputError(f"{path}: the PCD header has no {key} line")
            return default
        try:
            return [int(v) for v in values[key]]
        except ValueError:
            raise InputError(f"{path}: the PCD header has a bad {key} line") from None

    fields = tuple(values.get("FIELDS", []))
    if not fields:
        raise InputError(f"{path}: the PCD header has no FIELDS line")
    n = len(fields)
    sizes = ints("SIZE")
    types = [t.upper() for t in values.get("TYPE", [])]
    counts = ints("COUNT", [1] * n)
    if not (len(sizes) == len(types) == len(counts) == n):
        raise InputError(
            f"{path}: the PCD header's FIELDS, SIZE, TYPE and COUNT lines disagree in length"
        )
    for t, s in zip(types, sizes, strict=True):
        if (t, s) not in _NUMPY_TYPES:
            raise InputError(f"{path}: unsupported PCD field type {t}{s}")
    if any(c < 1 for c in counts):
        raise InputError(f"{path}: the PCD header has a COUNT below 1")
    width = ints("WIDTH")[:1]
    if not width:
        raise InputError(f"{path}: the PCD header has a bad WIDTH line")
    height = ints("HEIGHT", [1])[:1] or [1]
    w, h = width[0], height[0]
    npts = ints("POINTS", [w * h])[:1] or [w * h]
    if w < 0 or h < 1 or npts[0] < 0:
        raise InputError(f"{path}: the PCD header has a negative WIDTH/HEIGHT/POINTS")
    if npts[0] != w * h:
        raise InputError(
            f"{path}: the PCD header says POINTS {npts[0]} but WIDTH x HEIGHT is {w * h}"
        )
    viewpoint: tuple[float, ...] = DEFAULT_VIEWPOINT
    if "VIEWPOINT" in values:
        try:
            vp = tuple(float(v) for v in values["VIEWPOINT"])
        except ValueError:
            raise InputError(f"{path}: the PCD header has a bad VIEWPOINT line") from None
        if len(vp) != 7:
            raise InputError(f"{path}: the PCD header's VIEWPOINT needs 7 numbers")
        viewpoint = vp
    data = (values["DATA"] or [""])[0].lower()
    if data == "binaryscompressed":
        data = "binary_compressed"
    if data not in ENCODINGS:
        raise InputError(
            f"{path}: unsupported PCD DATA encoding {data!r} (expected ascii, binary or "
            "binary_compressed)"
        )
    header = _Header(fields, tuple(sizes), tuple(types), tuple(counts), w, h, npts[0],
                     viewpoint, data)
    return header, pos


def _read_binary(path: Path, body: bytes, header: _Header) -> np.ndarray:
    dtype = header.record_dtype()
    need = dtype.itemsize * header.points
    if len(body) < need:
        raise InputError(
            f"{path}: truncated PCD file (binary data has {len(body)} of {need} bytes)"
        )
    return np.frombuffer(body, dtype=dtype, count=header.points)


def _read_binary_compressed(path: Path, body: bytes, header: _Header) -> dict[str, np.ndarray]:
    if len(body) < 8:
        raise InputError(f"{path}: truncated PCD file (no compressed data block)")
    csize, usize = struct.unpack("<II", body[:8])
    n = header.points
    expected = sum(dt.itemsize * c for _, dt, c in header.field_dtypes()) * n
    if usize != expected:
        raise InputError(
            f"{path}: corrupt PCD file (uncompressed size {usize} bytes, expected {expected})"
        )
    if len(body) - 8 < csize:
        raise InputError(
            f"{path}: truncated PCD file (compressed data has {len(body) - 8} of {csize} bytes)"
        )
    try:
        buf = lzf.decompress(body[8:8 + csize], usize)
    except Exception:  # noqa: BLE001
        buf = None
    if buf is None or len(buf) != usize:
        raise InputError(f"{path}: corrupt PCD file (the compressed data does not decompress)")
    # binary_compressed stores each field for all points contiguously (structure of arrays).
    out: dict[str, np.ndarray] = {}
    offset = 0
    for name, dt, c in header.field_dtypes():
        nbytes = dt.itemsize * c * n
        arr = np.frombuffer(buf, dtype=dt, count=c * n, offset=offset)
        out[name] = arr.reshape(n, c) if c > 1 else arr
        offset += nbytes
    return out


def _read_ascii(path: Path, body: bytes, header: _Header) -> dict[str, np.ndarray]:
    cols = sum(header.counts)
    try:
        text = body.decode("ascii")
    except UnicodeDecodeError:
        raise InputError(f"{path}: corrupt PCD file (ascii data is not text)") from None
    tokens = text.split()
    need = cols * header.points
    if len(tokens) < need:
        raise InputError(
            f"{path}: truncated PCD file (ascii data has {len(tokens) // cols} of "
            f"{header.points} points)"
        )
    try:
        grid = np.array(tokens[:need], dtype=object).reshape(header.points, cols)
    except ValueError:
        raise InputError(f"{path}: corrupt PCD file (ascii data is malformed)") from None
    out: dict[str, np.ndarray] = {}
    col = 0
    for name, dt, c in header.field_dtypes():
        block = grid[:, col:col + c]
        col += c
        try:
            if name in ("rgb", "rgba") and dt.kind == "f":
                arr = _ascii_packed_float(block)
            elif dt.kind == "f":
                arr = block.astype(np.float64).astype(dt)
            else:
                arr = block.astype(np.float64)
                if not np.isfinite(arr).all():
                    raise ValueError("non-finite integer")
                arr = arr.astype(dt)
        except ValueError:
            raise InputError(
                f"{path}: corrupt PCD file (ascii field '{name}' has a non-numeric value)"
            ) from None
        out[name] = arr.reshape(header.points, c) if c > 1 else arr.reshape(-1)
    return out


def _ascii_packed_float(block: np.ndarray) -> np.ndarray:
    """A float ``rgb`` column in ascii: PCL writes the packed bits as an unsigned integer,
    older writers print the (tiny) float itself. Return float32 whose bits are the colour."""
    vals = block.astype(np.float64).reshape(-1)
    out = np.zeros(vals.shape, dtype=np.uint32)
    as_int = np.isfinite(vals) & (np.abs(vals) >= 1.0)
    out[as_int] = np.clip(vals[as_int], 0, 2**32 - 1).astype(np.uint32)
    fl = ~as_int
    out[fl] = vals[fl].astype(np.float32).view(np.uint32)
    return out.view(np.float32)


def _decode_colors(table: np.ndarray | dict[str, np.ndarray],
                   names: tuple[str, ...]) -> np.ndarray | None:
    for name in ("rgb", "rgba"):
        if name not in names:
            continue
        col = np.asarray(table[name])
        col = col.reshape(col.shape[0], -1)[:, 0]
        if col.dtype.itemsize != 4:
            col = col.astype(np.uint32)  # unusual: treat as an integer colour
        bits = np.ascontiguousarray(col).view(np.uint32)
        rgb = np.stack([(bits >> 16) & 255, (bits >> 8) & 255, bits & 255], axis=1)
        return rgb.astype(np.float64) / 255.0
    return None


# --------------------------------------------------------------------------------------------
# writing
