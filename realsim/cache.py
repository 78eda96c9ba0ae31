"""Content-addressed on-disk cache for heavy stages.

A key is the hash of the input bytes, the stage parameters and the code version, so a changed
input, parameter or release never reads a stale entry. Entries live under ``$REALSIM_CACHE``
(default ``~/.cache/realsim``), one pickle per key, written atomically.
"""

from __future__ import annotations

import hashlib
import json
import os
import pickle
import tempfile
from dataclasses import asdict, is_dataclass
from pathlib import Path
from typing import Any, Callable, TypeVar

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
