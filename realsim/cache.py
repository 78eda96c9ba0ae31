"""Content-addressed on-disk cache for heavy stages.

A key is the hash of the input bytes, the stage parameters and the code version, so a changed
input, parameter or release never reads a stale entry. Entries live under ``$REALSIM_CACHE``
(default ``~/.cache/realsim``), one pickle per key, written atomically.

Two notions of code version: :data:`__version__` (the release) keys the expensive asset work,
so editing unrelated code does not throw hours of CoACD away; :func:`code_digest` (the bytes of
every source and data file plus the versions of the libraries that shape the output) keys the
cheap-to-redo but output-defining stages (robot placement, settling, preview, whole
conversions), so a rerun after any code change recomputes them. :class:`BlobStore` keeps file
contents by their SHA-256, so identical files (the Panda's meshes) are stored once.
"""

from __future__ import annotations

import fcntl
import hashlib
import json
import os
import pickle
import tempfile
from contextlib import contextmanager
from dataclasses import asdict, is_dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any, Callable, Iterator, TypeVar

from realsim import __version__

T = TypeVar("T")


def cache_root() -> Path:
    """The cache folder: ``$REALSIM_CACHE`` or ``~/.cache/realsim``."""
    return Path(os.environ.get("REALSIM_CACHE", Path.home() / ".cache" / "realsim"))


def _canonical(value: Any) -> Any:
    if is_dataclass(value) and not isinstance(value, type):
        return _canonical(asdict(value))
    if isinstance(value, dict):
        return {str(k): _canonical(v) for k, v in sorted(value.items(), key=lambda kv: str(kv[0]))}
    if isinstance(value, (list, tuple)):
        return [_canonical(v) for v in value]
    if isinstance(value, Path):
        return str(value)
    if isinstance(value, (str, int, float, bool)) or value is None:
        return value
    return repr(value)


def cache_key(stage: str, *, data: bytes | None = None, files: list[Path] = (), params: Any = None) -> str:
    """A hex key for ``stage`` from raw bytes, file contents and parameters (plus code version)."""
    h = hashlib.sha256()
    h.update(f"{stage}\0{__version__}\0".encode())
    if data is not None:
        h.update(hashlib.sha256(data).digest())
    for f in files:
        h.update(hashlib.sha256(Path(f).read_bytes()).digest())
    h.update(json.dumps(_canonical(params), sort_keys=True).encode())
    return h.hexdigest()


# Libraries whose versions change what a conversion writes.
OUTPUT_LIBRARIES = ("mujoco", "numpy", "scipy", "trimesh", "open3d", "coacd", "manifold3d", "mujoco-menagerie", "mink", "Pillow")


@lru_cache(maxsize=1)
def code_digest() -> str:
    """SHA-256 of realsim's source and data files and of the output-shaping library versions."""
    from importlib import metadata

    from realsim.resources import DATA_FOLDERS, data_dir

    h = hashlib.sha256(f"realsim {__version__}\0".encode())
    package = Path(__file__).resolve().parent
    roots = [(package, "*.py")] + [(data_dir(name), "*") for name in DATA_FOLDERS]
    for root, pattern in roots:
        for path in sorted(p for p in root.rglob(pattern) if p.is_file() and "__pycache__" not in p.parts):
            h.update(f"{path.relative_to(root).as_posix()}\0".encode())
            h.update(hashlib.sha256(path.read_bytes()).digest())
    for lib in OUTPUT_LIBRARIES:
        try:
            version = metadata.version(lib)
        except metadata.PackageNotFoundError:
            version = "-"
        h.update(f"{lib}={version}\0".encode())
    return h.hexdigest()


def output_key(stage: str, *, data: bytes | None = None, params: Any = None) -> str:
    """A key for an output-defining stage: :func:`cache_key` plus :func:`code_digest`."""
    return cache_key(stage, data=data, params={"code": code_digest(), "params": params})


def model_digest(model: Any) -> bytes:
    """SHA-256 of a compiled MjModel (its MJB bytes: everything a simulation of it reads). Cheaper
    than the spec's XML, which MuJoCo compiles again to write."""
    import mujoco
    import numpy as np

    buffer = np.empty(mujoco.mj_sizeModel(model), np.uint8)
    mujoco.mj_saveModel(model, None, buffer)
    return hashlib.sha256(buffer).digest()


class BlobStore:
    """File contents by SHA-256 under ``<cache>/blobs``: each distinct content stored once."""

    def __init__(self, root: Path | None = None) -> None:
        self.root = (Path(root) if root is not None else cache_root()) / "blobs"

    def _path(self, digest: str) -> Path:
        return self.root / digest[:2] / digest

    def put(self, data: bytes) -> str:
        """Store ``data`` (atomically, once) and return its SHA-256."""
        digest = hashlib.sha256(data).hexdigest()
        path = self._path(digest)
        if not path.is_file():
            path.parent.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
            with os.fdopen(fd, "wb") as fh:
                fh.write(data)
            os.replace(tmp, path)
        return digest

    def get(self, digest: str) -> bytes | None:
        """The content with this SHA-256, or None when missing or corrupt."""
        try:
            data = self._path(digest).read_bytes()
        except OSError:
            return None
        return data if hashlib.sha256(data).hexdigest() == digest else None


class DiskCache:
    """Pickle store keyed by :func:`cache_key`; ``enabled=False`` makes every lookup a miss."""

    def __init__(self, root: Path | None = None, enabled: bool = True) -> None:
        self.root = Path(root) if root is not None else cache_root()
        self.enabled = enabled
        self.hits = 0
        self.misses = 0

    def _path(self, key: str) -> Path:
        return self.root / key[:2] / f"{key}.pkl"

    def get(self, key: str) -> Any | None:
        """The stored value, or None on a miss (or an unreadable entry)."""
        if not self.enabled:
            return None
        path = self._path(key)
        try:
            with path.open("rb") as fh:
                value = pickle.load(fh)
        except (OSError, pickle.UnpicklingError, EOFError, AttributeError, ImportError):
            return None
        return value

    def put(self, key: str, value: Any) -> None:
        """Store ``value`` atomically (a crash never leaves a torn entry)."""
        if not self.enabled:
            return
        path = self._path(key)
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        with os.fdopen(fd, "wb") as fh:
            pickle.dump(value, fh, protocol=pickle.HIGHEST_PROTOCOL)
        os.replace(tmp, path)

    @contextmanager
    def lock(self, key: str) -> Iterator[None]:
        """An exclusive lock on ``key`` shared by every process using this cache folder (also on
        other machines when the folder is shared): expensive work for one key happens once."""
        path = self.root / "locks" / f"{key}.lock"
        path.parent.mkdir(parents=True, exist_ok=True)
        with path.open("a") as fh:
            fcntl.flock(fh, fcntl.LOCK_EX)
            try:
                yield
            finally:
                fcntl.flock(fh, fcntl.LOCK_UN)

    def get_or_compute(self, key: str, compute: Callable[[], T]) -> T:
        """Return the cached value for ``key`` or compute, store and return it."""
        value = self.get(key)
        if value is not None:
            self.hits += 1
            return value
        self.misses += 1
        value = compute()
        self.put(key, value)
        return value
