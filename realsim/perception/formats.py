"""The file kinds a capture may be, told apart by suffix and header."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Any

from realsim.errors import InputError

POINT_CLOUD_SUFFIXES = {".pcd", ".ply", ".xyz", ".pts"}
MESH_SUFFIXES = {".obj", ".stl", ".ply", ".glb", ".gltf", ".off"}
USD_SUFFIXES = {".usd", ".usda", ".usdc", ".usdz"}


def is_point_cloud_ply(path: Path) -> bool:
    """True when a PLY file declares vertices but no faces."""
    with path.open("rb") as fh:
        header = fh.read(4096)
    if not header:
        raise InputError(f"{path}: the file is empty")
    if not header.startswith(b"ply"):
        raise InputError(f"{path}: not a PLY file (missing 'ply' magic)")
    head = header.split(b"end_header")[0]
    faces = [line for line in head.splitlines() if line.startswith(b"element face")]
    return not faces or faces[0].split()[-1] == b"0"


def read_mesh_file(path: Path) -> Any:
    """``trimesh.load(path, force="mesh", process=False)``, read once per file version: telling a
    lone object from a scene and sampling the scene read the same file (an OBJ of a room takes
    seconds to parse). Callers must not modify the returned mesh; :func:`forget_mesh_files`
    drops it once the capture is loaded."""
    stat = path.stat()
    return _read_mesh_cached(str(path.resolve()), stat.st_mtime_ns, stat.st_size)


@lru_cache(maxsize=1)
def _read_mesh_cached(path: str, mtime_ns: int, size: int) -> Any:
    import trimesh

    return trimesh.load(path, force="mesh", process=False)


def forget_mesh_files() -> None:
    """Release the mesh :func:`read_mesh_file` keeps."""
    _read_mesh_cached.cache_clear()
