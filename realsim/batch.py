"""``realsim batch``: many captures into many scene folders, in parallel on Ray.

Captures come from folders (a capture folder itself, or a folder of captures), globs, or list
files (one path per line). Each becomes ``<output>/<name>/`` through the ordinary conversion
(:func:`realsim.pipeline.convert`, same data-safety rules), as one Ray task: a local Ray by
default, an existing cluster with ``--address``. Every worker uses the same ``REALSIM_CACHE``
(on a cluster it must be a shared folder), and expensive per-mesh work is done under a lock
keyed by its cache key, so a mesh met by several captures is decomposed once.

``<output>/batch.json`` records each capture's conversion key (inputs, parameters, code digest:
:func:`realsim.rerun.conversion_key`), status, time and error. A rerun skips a capture whose
scene folder exists and whose key is unchanged; a failure is isolated (the others go on) and
reported, and is not retried while its key is unchanged unless asked (``--retry-failed``). The run ends with a summary table; the exit code is 1 when any
capture failed.
"""

from __future__ import annotations

import glob
import json
import os
import re
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from realsim.errors import InputError

RECORD = "batch.json"
UNCHANGED = " (unchanged since the last run: not retried; --retry-failed runs it again)"
FORMAT = "realsim-batch/1"
CAPTURE_FILES = {".pcd", ".ply", ".xyz", ".obj", ".stl", ".glb", ".gltf", ".txt", ".jpg", ".jpeg", ".png", ".webp"}
LIST_FILES = {".list", ".lst"}
FORWARDED_ENV = ("REALSIM_CACHE", "MENAGERIE_ROOT", "MENAGERIE_CACHE_DIR", "ANTHROPIC_API_KEY", "ANTHROPIC_BASE_URL",
                 "REALSIM_MODEL", "MUJOCO_GL", "REALSIM_REUSE")


@dataclass
class Job:
    """One capture and the scene folder it becomes."""

    capture: Path
    name: str
    key: str | None = None
    status: str = "pending"  # pending | skipped | ok | failed
    seconds: float = 0.0
    objects: int = 0
    warnings: int = 0
    error: str = ""
    extra: dict[str, Any] = field(default_factory=dict)


def _is_capture_folder(path: Path) -> bool:
    return path.is_dir() and (any(path.glob("scene.*")) or (path / "objects").is_dir() or (path / "capture.yaml").is_file()
                              or any(path.glob("photo.*")))


def _is_capture(path: Path) -> bool:
    return _is_capture_folder(path) or (path.is_file() and path.suffix.lower() in CAPTURE_FILES)


def _list_file(path: Path) -> list[Path] | None:
    """The captures a list file names (relative to the file), or None when it is not a list."""
    if not path.is_file() or path.suffix.lower() not in LIST_FILES | {".txt"}:
        return None
    lines = [ln.strip() for ln in path.read_text(encoding="utf-8", errors="replace").splitlines()]
    entries = [ln for ln in lines if ln and not ln.startswith("#")]
    paths = [(path.parent / e).expanduser() if not Path(e).is_absolute() else Path(e) for e in entries]
    if path.suffix.lower() == ".txt" and (not paths or not all(p.exists() for p in paths)):
        return None  # a scene description, not a list
    return paths


def expand_captures(items: list[str]) -> list[Path]:
    """Captures from folders, globs and list files, in order, without duplicates."""
    found: list[Path] = []
    for item in items:
        path = Path(item).expanduser()
        if any(ch in item for ch in "*?["):
            matches = [Path(m) for m in sorted(glob.glob(item))]
            if not matches:
                raise InputError(f"{item}: the pattern matches nothing")
            found += [m for m in matches if _is_capture(m)]
        elif (listed := _list_file(path)) is not None:
            missing = [str(p) for p in listed if not p.exists()]
            if missing:
                raise InputError(f"{item}: lists {len(missing)} path(s) that do not exist, e.g. {missing[0]}")
            found += listed
        elif _is_capture_folder(path):
            found.append(path)
        elif path.is_dir():
            found += [p for p in sorted(path.iterdir()) if _is_capture(p) and not p.name.startswith(".")]
        elif path.is_file():
            found.append(path)
        else:
            raise InputError(f"{item}: no such capture, folder, glob or list file")
    unique = list(dict.fromkeys(p.resolve() for p in found))
    if not unique:
        raise InputError(f"no captures found in {', '.join(items)}; pass capture folders, files, a folder of them, a glob or a list file")
    return unique


def _names(captures: list[Path]) -> list[str]:
    """A folder name per capture: its stem, made safe and unique."""
    names: list[str] = []
    for cap in captures:
        base = re.sub(r"[^A-Za-z0-9_.-]+", "_", cap.stem if cap.is_file() else cap.name).strip("._") or "capture"
        name, k = base, 2
        while name in names:
            name, k = f"{base}_{k}", k + 1
        names.append(name)
    return names


def _convert_task(capture: str, dest: str, kwargs: dict[str, Any], force: bool) -> dict[str, Any]:
    """One conversion inside a worker; every failure is returned, never raised."""
    os.environ["REALSIM_WORKERS"] = "1"  # the batch is the parallelism: one conversion per worker core
    started = time.perf_counter()
    try:
        from realsim.pipeline import convert

        scene = convert(Path(capture), Path(dest), force=force, **kwargs)
        assert scene is not None
        return {"status": "ok", "seconds": time.perf_counter() - started, "objects": len(scene.objects),
                "warnings": len(scene.warnings)}
    except Exception as exc:  # isolated: reported, the batch goes on
        message = " ".join(str(exc).split())[:300] or type(exc).__name__
        return {"status": "failed", "seconds": time.perf_counter() - started, "error": f"{type(exc).__name__}: {message}"}


def _load_record(output: Path) -> dict[str, dict[str, Any]]:
    try:
        data = json.loads((output / RECORD).read_text())
        return {j["capture"]: j for j in data.get("captures", [])} if data.get("format") == FORMAT else {}
    except (OSError, ValueError, KeyError, TypeError):
        return {}


def _write_record(output: Path, jobs: list[Job], summary: dict[str, Any]) -> None:
    data = {"format": FORMAT, "summary": summary,
            "captures": [{**{k: v for k, v in asdict(j).items() if k != "extra"}, "capture": str(j.capture)} for j in jobs]}
    tmp = output / f".{RECORD}.tmp"
    tmp.write_text(json.dumps(data, indent=1) + "\n")
    os.replace(tmp, output / RECORD)


def run_batch(items: list[str], output: Path, *, seed: int = 0, overrides: dict[str, Any] | None = None,
              address: str | None = None, workers: int | None = None, force: bool = False, retry_failed: bool = False,
              progress: bool = True) -> tuple[list[Job], dict[str, Any]]:
    """Convert every capture of ``items`` into ``output/<name>``; returns the jobs and a summary.

    Unchanged captures are not run again: a converted one is skipped, a failed one keeps its
    error (``retry_failed`` runs it again, e.g. after a network failure)."""
    import ray
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    from realsim.rerun import conversion_key

    captures = expand_captures(items)
    output = Path(output).expanduser().resolve()
    if output.is_dir() and any(output.iterdir()) and not (output / RECORD).is_file():
        raise InputError(f"-o {output}: not empty and not a batch output (no {RECORD}); name a new or empty folder")
    if any(output == c or c in output.parents for c in captures):
        raise InputError(f"-o {output}: is a capture or inside one; name a folder elsewhere")
    output.mkdir(parents=True, exist_ok=True)
    kwargs = {"seed": seed, "overrides": overrides or {}}
    previous = _load_record(output)
    jobs = [Job(cap, name) for cap, name in zip(captures, _names(captures))]
    todo: list[Job] = []
    for job in jobs:
        job.key = conversion_key(job.capture, kwargs)
        before = previous.get(str(job.capture))
        same = before is not None and before.get("key") == job.key and not force
        if same and before.get("status") in ("ok", "skipped") and (output / job.name / "scene.xml").is_file():
            job.status, job.objects, job.seconds = "skipped", int(before.get("objects", 0)), 0.0
        elif same and before.get("status") == "failed" and not retry_failed:  # the same inputs and code fail the same way
            job.status, job.error = "failed", str(before.get("error", "")).removesuffix(UNCHANGED) + UNCHANGED
        else:
            todo.append(job)
    started = time.perf_counter()
    if todo:
        env = {k: os.environ[k] for k in FORWARDED_ENV if k in os.environ}
        init: dict[str, Any] = {"address": address, "include_dashboard": False, "log_to_driver": False,
                                "runtime_env": {"env_vars": env}, "ignore_reinit_error": True}
        if address is None:
            init["num_cpus"] = workers or os.cpu_count() or 1
        ray.init(**init)
        try:
            task = ray.remote(num_cpus=1, max_retries=0)(_convert_task)
            limit = workers or max(1, int(ray.available_resources().get("CPU", 1)))
            pending: dict[Any, Job] = {}
            queue = list(todo)
            columns = (TextColumn("batch"), BarColumn(), TextColumn("{task.completed}/{task.total}"), TimeElapsedColumn())
            with Progress(*columns, disable=not progress, transient=True) as bar:
                tid = bar.add_task("batch", total=len(todo))
                while queue or pending:
                    while queue and len(pending) < limit:
                        job = queue.pop(0)
                        dest = output / job.name
                        refresh = dest.exists()  # an earlier run's folder (changed capture or failed): replace it
                        pending[task.remote(str(job.capture), str(dest), kwargs, refresh)] = job
                    ready, _ = ray.wait(list(pending), num_returns=1)
                    for ref in ready:
                        job = pending.pop(ref)
                        result = ray.get(ref)
                        job.status, job.seconds = result["status"], round(result["seconds"], 3)
                        job.objects, job.warnings, job.error = result.get("objects", 0), result.get("warnings", 0), result.get("error", "")
                        bar.advance(tid)
                        _write_record(output, jobs, {})
        finally:
            ray.shutdown()
    wall = time.perf_counter() - started
    counts = {s: sum(j.status == s for j in jobs) for s in ("ok", "skipped", "failed")}
    summary = {"captures": len(jobs), **counts, "wall_s": round(wall, 3), "workers": workers, "address": address}
    _write_record(output, jobs, summary)
    return jobs, summary


def print_summary(jobs: list[Job], summary: dict[str, Any], output: Path) -> None:
    """The per-capture table and the totals."""
    from rich.console import Console
    from rich.table import Table

    table = Table(title="batch", title_justify="left")
    for col in ("capture", "scene", "status", "objects", "time s", "error"):
        table.add_column(col)
    for j in jobs:
        table.add_row(str(j.capture), j.name, j.status, str(j.objects) if j.status != "failed" else "-", f"{j.seconds:.1f}", j.error)
    console = Console()
    console.print(table)
    console.print(f"{summary['ok']} converted, {summary['skipped']} unchanged (skipped), {summary['failed']} failed "
                  f"in {summary['wall_s']:.1f} s; record: {output / RECORD}")
