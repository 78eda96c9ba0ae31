"""The file kinds a capture may be, told apart by suffix and header."""

from __future__ import annotations

from pathlib import Path

from realsim.errors import InputError

POINT_CLOUD_SUFFIXES = {".pcd", ".ply", ".xyz", ".pts"}
MESH_SUFFIXES = {".obj", ".stl", ".ply", ".glb", ".gltf", ".off"}
USD_SUFFIXES = {".usd", ".usda", ".usdc", ".usdz"}


def is_point_cloud_ply(path: Path) -> bool:
    """True when a PLY file declares vertices but no faces."""
    with path.open("rb") as fh:
        header = fh.read(4096)
    if not header.startswith(b"ply"):
        raise InputError(f"{path}: not a PLY file (missing 'ply' magic)")
    head = header.split(b"end_header")[0]
    faces = [line for line in head.splitlines() if line.startswith(b"element face")]
    return not faces or faces[0].split()[-1] == b"0"
