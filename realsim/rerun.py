"""Warm reruns: a conversion whose inputs, parameters and code are unchanged is restored, not redone.

:func:`conversion_key` hashes everything a conversion's output depends on: the capture's bytes
(every file of a capture folder, with its relative path), the paths as given (scene.json records
them), the pipeline definition, the seed and every parameter override, the LLM and Menagerie
settings, and :func:`realsim.cache.code_digest` (source, data files, library versions). After
a conversion is written, :func:`remember` stores each output file in the content-addressed
:class:`realsim.cache.BlobStore` and the file list under the key; :func:`restore` writes those
exact bytes into the destination (atomically, under the same data-safety rules as a conversion)
and returns the conversion's Scene record, so a rerun is byte-identical and does no work.

``REALSIM_REUSE=0`` turns restoring off (benchmarks that time the pipeline itself).
"""

from __future__ import annotations

import dataclasses
import hashlib
import os
import time
from pathlib import Path
from typing import Any

from realsim.cache import BlobStore, DiskCache, _canonical, code_digest, output_key
from realsim.scene import Scene

FORMAT = "realsim-conversion/1"
ENV_SETTINGS = ("ANTHROPIC_BASE_URL", "REALSIM_MODEL", "MENAGERIE_ROOT")


def reuse_enabled() -> bool:
    """False when ``REALSIM_REUSE`` is 0/false/no/off."""
    return os.environ.get("REALSIM_REUSE", "1").strip().lower() not in ("0", "false", "no", "off")


def _tree_digest(path: Path, h: Any) -> None:
    """Feed a file, or every file under a folder (sorted relative paths and contents), into ``h``."""
    if path.is_file():
        h.update(hashlib.sha256(path.read_bytes()).digest())
        return
    for file in sorted(p for p in path.rglob("*") if p.is_file()):
        h.update(f"{file.relative_to(path).as_posix()}\0".encode())
        h.update(hashlib.sha256(file.read_bytes()).digest())


def conversion_key(source: Path | None, kwargs: dict[str, Any]) -> str | None:
    """The content key of converting ``source`` with ``kwargs`` (as given to ``run_pipeline``);
    None when the conversion cannot be keyed (an unreadable input: the pipeline reports it)."""
    h = hashlib.sha256()
    overrides = kwargs.get("overrides") or {}
    try:
        if source is not None:
            h.update(f"source {source}\0{Path(source).resolve()}\0".encode())
            _tree_digest(Path(source), h)
        photo = ((overrides.get("objects") or {}).get("understanding") or {}).get("photo")
        if photo:
            h.update(f"photo {photo}\0{Path(photo).resolve()}\0".encode())
            _tree_digest(Path(photo), h)
        pipeline = kwargs.get("pipeline")
        if pipeline is not None and Path(str(pipeline)).is_file():
            h.update(Path(str(pipeline)).read_bytes())
    except OSError:
        return None
    settings = {
        "pipeline": str(kwargs.get("pipeline")),
        "seed": kwargs.get("seed", 0),
        "overrides": _canonical(overrides),
        "env": {name: os.environ.get(name) for name in ENV_SETTINGS},
        "llm": bool(os.environ.get("ANTHROPIC_API_KEY")),
        "inputs": h.hexdigest(),
    }
    return output_key("conversion", params=settings)


def _light(scene: Scene) -> Scene:
    """The Scene as a record: no points, spec, asset bytes or visual meshes (the files hold them)."""
    objects = [dataclasses.replace(o, visual=None, texture_png=None) for o in scene.objects]
    return dataclasses.replace(scene, points=None, colors=None, normals=None, annotations=None, spec=None, assets={}, objects=objects)


def remember(key: str | None, dest: Path, scene: Scene, cache: DiskCache | None = None) -> None:
    """Store the files of the conversion written at ``dest`` and its Scene record under ``key``."""
    if key is None or not reuse_enabled():
        return
    cache = cache or DiskCache()
    blobs = BlobStore(cache.root)
    dest = Path(dest)
    files = {}
    for path in sorted(p for p in dest.rglob("*") if p.is_file()):
        rel = path.relative_to(dest).as_posix()
        if rel.startswith(".realsim") or rel.startswith("runs/"):
            continue  # the destination's own manifest, and logs a run adds later
        files[rel] = blobs.put(path.read_bytes())
    cache.put(key, {"format": FORMAT, "code": code_digest(), "files": files, "scene": _light(scene)})


def restore(key: str | None, dest: Path, *, force: bool = False, cache: DiskCache | None = None) -> Scene | None:
    """Write the conversion stored under ``key`` to ``dest`` and return its Scene; None on a miss
    (or when any stored file is missing or corrupt: the conversion then runs normally)."""
    if key is None or not reuse_enabled():
        return None
    started = time.perf_counter()
    cache = cache or DiskCache()
    entry = cache.get(key)
    if not isinstance(entry, dict) or entry.get("format") != FORMAT:
        return None
    blobs = BlobStore(cache.root)
    contents: dict[str, bytes] = {}
    for rel, digest in entry["files"].items():
        data = blobs.get(digest)
        if data is None:
            return None
        contents[rel] = data
    from realsim.destination import atomic_folder

    with atomic_folder(Path(dest), force=force, kind="scene") as tmp:
        for rel, data in contents.items():
            path = tmp / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(data)
    scene: Scene = entry["scene"]
    scene.assets = {rel.split("/", 1)[1]: data for rel, data in contents.items() if rel.startswith("assets/")}
    if "scene.xml" in contents:  # the spec as written (parsing is cheap; nothing is compiled)
        import mujoco

        scene.spec = mujoco.MjSpec.from_string(contents["scene.xml"].decode())
        scene.spec.assets = scene.assets
    if scene.llm:  # this run asked nothing: every answer came from the first conversion
        llm = dict(scene.llm)
        llm["cache_hits"] = int(llm.get("cache_hits", 0)) + int(llm.get("calls", 0))
        llm.update(calls=0, input_tokens=0, output_tokens=0, cost_usd=0.0, failures=[])
        scene.llm = llm
    scene.timings = {"reused": round(time.perf_counter() - started, 4)}
    return scene
