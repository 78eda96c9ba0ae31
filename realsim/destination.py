"""Output destinations that can never destroy a user's data.

realsim writes only into a new path, an empty folder, or a folder it wrote before (recognized by
the manifest it leaves there, ``.realsim-manifest.json``); replacing one needs ``force``. The
working directory, the inputs, their ancestors, the home folder and ``/`` are never an output.
Everything is built in a hidden sibling folder and swapped into place atomically
(``renameat2(RENAME_EXCHANGE)`` on Linux), under a lock on the parent folder, so a failed or
killed run leaves the old output as it was and two runs into one destination cannot mix.
"""

from __future__ import annotations

import ctypes
import errno
import fcntl
import json
import os
import re
import secrets
import shutil
from contextlib import contextmanager
from pathlib import Path
from typing import Iterable, Iterator

from realsim import __version__
from realsim.errors import InputError

MANIFEST = ".realsim-manifest.json"
TMP_TAG = "realsim-tmp"
OLD_TAG = "realsim-old"
# Files `realsim run` adds to a scene folder after conversion (its logs and videos).
RUN_FILES = re.compile(r"^runs/[^/]+\.(json|mp4)$")
# What a scene folder written before manifests existed may hold.
LEGACY_FILES = re.compile(r"^(scene\.xml|scene\.json|labels\.npy|preview\.png|assets/[^/]+)$")


def _written_files(folder: Path) -> list[str]:
    """Every file under ``folder`` as a POSIX path relative to it (the manifest excluded)."""
    return sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*") if p.is_file() or p.is_symlink()
                  if p.name != MANIFEST or p.parent != folder)


def _manifest_files(folder: Path) -> set[str] | None:
    """The files realsim wrote into ``folder`` (from its manifest), or None when it wrote none."""
    manifest = folder / MANIFEST
    if manifest.is_file():
        try:
            return set(json.loads(manifest.read_text())["files"])
        except (OSError, ValueError, KeyError, TypeError):
            return None
    scene_json = folder / "scene.json"
    if scene_json.is_file():  # a scene folder from before manifests: its known file names
        try:
            legacy = str(json.loads(scene_json.read_text()).get("format", "")).startswith("realsim-scene/")
        except (OSError, ValueError, AttributeError):
            legacy = False
        if legacy:
            return {f for f in _written_files(folder) if LEGACY_FILES.match(f)}
    return None


def foreign_files(folder: Path) -> list[str] | None:
    """Files in an existing ``folder`` that realsim did not write; None when realsim never wrote it."""
    owned = _manifest_files(folder)
    if owned is None:
        return None
    return [f for f in _written_files(folder) if f not in owned and not RUN_FILES.match(f)]


def _is_within(path: Path, other: Path) -> bool:
    """True when ``path`` is ``other`` or one of its ancestors."""
    return path == other or path in other.parents


def _nearest_existing(path: Path) -> Path:
    while not path.exists() and path != path.parent:
        path = path.parent
    return path


def _resolve(path: str | Path, what: str) -> Path:
    """``path`` made absolute with its symbolic links followed; InputError on a link loop."""
    try:
        return Path(path).expanduser().resolve()
    except (RuntimeError, OSError) as exc:  # Python 3.11 raises RuntimeError on a loop, 3.13 OSError
        raise InputError(f"{what} {path}: cannot follow its symbolic links ({exc})") from None


def check_destination(dest: str | Path, *, inputs: Iterable[Path | None] = (), force: bool = False,
                      flag: str = "-o") -> Path:
    """Validate an output path before any work starts; return it resolved.

    Raises InputError when the path is empty, protected (``/``, home, the working directory,
    an input or an ancestor of any of them), a folder holding someone else's files, a realsim
    folder without ``force``, or not writable.
    """
    if not str(dest).strip():
        raise InputError(f"{flag} is empty: name a new folder for the output, e.g. {flag} out/scene")
    path = _resolve(dest, flag)
    protected = {Path("/"): "the root folder", Path.home().resolve(): "your home folder"}
    if path in protected:
        raise InputError(f"{flag} {dest}: refusing to write into {protected[path]}; name a new folder")
    if _is_within(path, Path.cwd().resolve()):
        raise InputError(f"{flag} {dest}: is the working directory or one of its parents; name a new folder, e.g. {flag} out/scene")
    for source in inputs:
        if source is not None and _is_within(path, _resolve(source, "input")):
            raise InputError(f"{flag} {dest}: is the input {source} or a folder holding it; name a new folder")
    if path.exists() or path.is_symlink():
        if not path.is_dir() or path.is_symlink():
            raise InputError(f"{flag} {dest}: exists and is not a folder realsim wrote; name a new path")
        if any(path.iterdir()):
            foreign = foreign_files(path)
            if foreign is None:
                raise InputError(f"{flag} {dest}: the folder exists and realsim did not write it; name a new folder (nothing was changed)")
            if foreign:
                shown = ", ".join(foreign[:3]) + (" ..." if len(foreign) > 3 else "")
                raise InputError(f"{flag} {dest}: holds files realsim did not write ({shown}); move them or name a new folder")
            if not force:
                raise InputError(f"{flag} {dest}: already holds realsim output; pass --force to replace it")
    _check_writable(path, dest, flag)
    return path


def _check_writable(path: Path, dest: str | Path, flag: str) -> None:
    """InputError unless the nearest existing folder above ``path`` can be written to."""
    parent = _nearest_existing(path.parent)
    if not os.access(parent, os.W_OK | os.X_OK):
        reason = "read-only file system" if _read_only(parent) else "permission denied"
        raise InputError(f"{flag} {dest}: cannot write in {parent} ({reason}); choose a writable folder")


def _read_only(folder: Path) -> bool:
    try:
        return bool(os.statvfs(folder).f_flag & os.ST_RDONLY)
    except OSError:
        return False


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _sibling(dest: Path, tag: str) -> Path:
    return dest.parent / f".{dest.name}.{tag}.{os.getpid()}.{secrets.token_hex(4)}"


def clean_stale(dest: Path) -> None:
    """Remove build folders that killed runs left beside ``dest`` (only realsim's own, only dead ones).

    An interrupted swap's old folder is moved back when ``dest`` itself is missing.
    """
    pattern = re.compile(rf"^\.{re.escape(dest.name)}\.({TMP_TAG}|{OLD_TAG})\.(\d+)\.[0-9a-f]{{8}}$")
    if not dest.parent.is_dir():
        return
    for entry in sorted(dest.parent.iterdir()):
        match = pattern.match(entry.name)
        if not match or _pid_alive(int(match.group(2))):
            continue
        if match.group(1) == OLD_TAG and not dest.exists():
            os.rename(entry, dest)
        else:
            shutil.rmtree(entry, ignore_errors=True)


@contextmanager
def _locked(folder: Path) -> Iterator[None]:
    """An exclusive lock on ``folder`` (flock on the directory itself: nothing is left behind)."""
    fd = os.open(folder, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        fcntl.flock(fd, fcntl.LOCK_UN)
        os.close(fd)


def _exchange(a: Path, b: Path) -> bool:
    """Atomically swap two paths (Linux renameat2); False where the system cannot."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        renameat2 = libc.renameat2
    except (OSError, AttributeError):
        return False
    at_fdcwd, rename_exchange = -100, 2
    if renameat2(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange) == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.EINVAL, errno.ENOSYS, errno.ENOTSUP):
        return False
    raise OSError(err, os.strerror(err), str(b))


def normal_permissions(folder: Path) -> None:
    """Give ``folder`` (or a file) and everything in it the user's normal modes (umask), whatever
    wrote them (temporary-file helpers create 0600 files and 0700 folders)."""
    umask = os.umask(0)
    os.umask(umask)
    for path in [folder, *folder.rglob("*")]:
        if not path.is_symlink():
            path.chmod((0o777 if path.is_dir() else 0o666) & ~umask)


def write_manifest(folder: Path, kind: str) -> None:
    """Record every file in ``folder`` as written by realsim (what a later ``--force`` may replace)."""
    record = {"written_by": f"realsim {__version__}", "kind": kind, "files": _written_files(folder)}
    (folder / MANIFEST).write_text(json.dumps(record, indent=1) + "\n")


def publish(tmp: Path, dest: Path, *, force: bool = False, kind: str = "scene") -> None:
    """Move the complete folder ``tmp`` to ``dest`` atomically, replacing realsim's old output.

    ``dest`` is checked again under the parent folder's lock, so a concurrent run cannot slip in
    between the check and the swap; the old folder is removed only after the swap.
    """
    write_manifest(tmp, kind)
    normal_permissions(tmp)
    with _locked(dest.parent):
        check_destination(dest, force=force, flag="output")
        if not dest.exists():
            os.rename(tmp, dest)
        elif _exchange(tmp, dest):
            shutil.rmtree(tmp)  # now the old output: only files realsim wrote (checked above)
        else:
            old = _sibling(dest, OLD_TAG)
            os.rename(dest, old)
            os.rename(tmp, dest)
            shutil.rmtree(old)


def build_folder(dest: Path) -> Path:
    """A new hidden sibling folder of ``dest`` to build in (stale ones of dead runs removed first)."""
    dest.parent.mkdir(parents=True, exist_ok=True)
    clean_stale(dest)
    tmp = _sibling(dest, TMP_TAG)
    tmp.mkdir()
    return tmp


@contextmanager
def atomic_folder(dest: Path, *, force: bool = False, kind: str = "scene") -> Iterator[Path]:
    """Yield a new hidden folder that replaces ``dest`` when the block succeeds.

    ``dest`` must pass :func:`check_destination`. The old folder stays untouched until the new
    one is complete; on failure nothing changes. Folders get the user's normal permissions (umask).
    """
    dest = Path(dest).resolve()
    tmp = build_folder(dest)
    try:
        yield tmp
        publish(tmp, dest, force=force, kind=kind)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)


def check_file_destination(dest: str | Path, *, inputs: Iterable[Path | None] = (), force: bool = False,
                           flag: str = "-o") -> Path:
    """Validate an output *file* path (protected paths as :func:`check_destination`); an existing
    file is replaced only with ``force``."""
    if not str(dest).strip():
        raise InputError(f"{flag} is empty: name a new file for the output")
    path = _resolve(dest, flag)
    if path.is_dir():
        raise InputError(f"{flag} {dest}: is a folder; name a file")
    if path.exists() and not force:
        raise InputError(f"{flag} {dest}: the file exists; pass --force to replace it")
    for source in inputs:
        if source is not None and _resolve(source, "input") == path:
            raise InputError(f"{flag} {dest}: is the input {source}; name a new file")
    _check_writable(path, dest, flag)
    return path
