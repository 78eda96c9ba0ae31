"""Read a 3D Gaussian splat PLY (the INRIA 3DGS layout) for the viewer's backdrop."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from realsim.errors import InputError

SH_C0 = 0.28209479177387814
_PLY_TYPES = {"float": "f4", "float32": "f4", "double": "f8", "float64": "f8", "uchar": "u1", "uint8": "u1",
              "char": "i1", "int8": "i1", "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
              "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4"}


@dataclass
class Splats:
    """Gaussians in the world frame: centres (N,3), covariances (N,3,3), rgb and opacity in [0,1]."""

    centers: np.ndarray
    covariances: np.ndarray
    rgbs: np.ndarray
    opacities: np.ndarray


def read_splat_ply(path: Path, transform: np.ndarray | None = None) -> Splats:
    """Load a binary little-endian 3DGS PLY; ``transform`` (4x4, may scale) maps it to the world."""
    raw = Path(path).read_bytes()
    end = raw.find(b"end_header\n")
    if not raw.startswith(b"ply") or end < 0:
        raise InputError(f"{path}: not a PLY file")
    header = raw[:end].decode("ascii", "replace").splitlines()
    if "format binary_little_endian 1.0" not in header:
        raise InputError(f"{path}: a Gaussian splat PLY must be binary_little_endian")
    count, fields, in_vertex = 0, [], False
    for line in header:
        parts = line.split()
        if parts[:1] == ["element"]:
            in_vertex = parts[1] == "vertex"
            count = int(parts[2]) if in_vertex else count
        elif parts[:1] == ["property"] and in_vertex:
            if parts[1] == "list" or parts[1] not in _PLY_TYPES:
                raise InputError(f"{path}: unsupported vertex property {' '.join(parts[1:])}")
            fields.append((parts[2], "<" + _PLY_TYPES[parts[1]]))
    names = {n for n, _ in fields}
    needed = {"x", "y", "z", "f_dc_0", "f_dc_1", "f_dc_2", "opacity", "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2", "rot_3"}
    if not needed <= names:
        raise InputError(f"{path}: not a Gaussian splat PLY (missing {', '.join(sorted(needed - names))})")
    v = np.frombuffer(raw, dtype=np.dtype(fields), count=count, offset=end + len(b"end_header\n"))
    centers = np.column_stack([v["x"], v["y"], v["z"]]).astype(np.float64)
    rgbs = np.clip(0.5 + SH_C0 * np.column_stack([v["f_dc_0"], v["f_dc_1"], v["f_dc_2"]]), 0, 1)
    opacities = 1.0 / (1.0 + np.exp(-v["opacity"].astype(np.float64)))
    scales = np.exp(np.column_stack([v["scale_0"], v["scale_1"], v["scale_2"]]).astype(np.float64))
    q = np.column_stack([v["rot_0"], v["rot_1"], v["rot_2"], v["rot_3"]]).astype(np.float64)  # w, x, y, z
    q /= np.maximum(np.linalg.norm(q, axis=1, keepdims=True), 1e-12)
    w, x, y, z = q.T
    rot = np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], 1)
    rs = rot * scales[:, None, :]
    cov = rs @ rs.transpose(0, 2, 1)
    if transform is not None:
        a, t = np.asarray(transform)[:3, :3], np.asarray(transform)[:3, 3]
        centers = centers @ a.T + t
        cov = a @ cov @ a.T
    return Splats(centers.astype(np.float32), cov.astype(np.float32), rgbs.astype(np.float32), opacities[:, None].astype(np.float32))


def is_splat_ply(path: Path) -> bool:
    """True for a 3D Gaussian splat PLY (vertex properties ``f_dc_0`` and ``opacity``)."""
    with path.open("rb") as fh:
        head = fh.read(8192).split(b"end_header")[0]
    return b"property float f_dc_0" in head and b"property float opacity" in head


def find_splat(scene_json: dict) -> Path | None:
    """``splat.ply`` in the capture folder recorded in scene.json (or next to the capture file)."""
    source = scene_json.get("capture", {}).get("source")
    if not source:
        return None
    src = Path(source)
    if src.is_file() and src.suffix.lower() == ".ply":
        if is_splat_ply(src):  # the capture itself is a splat: its centres were the points
            return src
    folder = src if src.is_dir() else src.parent
    for name in ("splat.ply", "splats.ply", "gaussians.ply"):
        if (folder / name).is_file():
            return folder / name
    return None
