"""Property-based tests: the capture readers and the CLI flags never crash, hang or run away.

For any bytes (random, truncated real files, real headers with absurd values) a reader either
returns a scene or raises :class:`InputError` (exit 2, one line) within seconds; the peak
memory of the whole run stays bounded. Examples are derandomized so the suite is repeatable.
"""

from __future__ import annotations

import atexit
import contextlib
import io
import resource
import shutil
import tempfile
import time
from pathlib import Path

import numpy as np
import pytest
import trimesh
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import MOSD
from realsim import cli
from realsim.errors import InputError
from realsim.perception.capture import load_capture
from realsim.perception.capture_config import parse_capture_config, read_capture_config
from realsim.perception.pcd_io import write_pcd
from realsim.pipeline import load_pipeline

FUZZ = settings(max_examples=200, deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
SECONDS_PER_EXAMPLE = 10.0
WORK = Path(tempfile.mkdtemp(prefix="realsim-fuzz-"))
atexit.register(shutil.rmtree, WORK, ignore_errors=True)  # the run's own scratch files go with it


def _seed_files() -> dict[str, list[bytes]]:
    """Small valid files of every reader's format, to truncate and mutate."""
    rng = np.random.default_rng(0)
    pts = np.column_stack([rng.uniform(-1, 1, (300, 2)), rng.normal(0, 0.002, 300)])
    pcd = []
    for encoding in ("ascii", "binary", "binary_compressed"):
        path = WORK / f"seed_{encoding}.pcd"
        write_pcd(path, pts, encoding=encoding)
        pcd.append(path.read_bytes())
    box = trimesh.creation.box((0.3, 0.2, 0.1))
    cloud = trimesh.PointCloud(pts)
    return {
        ".pcd": pcd + [(MOSD / "test0.pcd").read_bytes()[:20000]],
        ".ply": [box.export(file_type="ply", encoding="binary"), box.export(file_type="ply", encoding="ascii"),
                 cloud.export(file_type="ply")],
        ".obj": [box.export(file_type="obj").encode()],
        ".glb": [box.export(file_type="glb")],
    }


SEEDS = _seed_files()
ABSURD = [b"0", b"-1", b"999999999999", b"1e308", b"nan", b"inf", b"-inf", b"4294967296", b"x", b""]


def mutated(suffix: str) -> st.SearchStrategy[bytes]:
    """Random bytes, truncations of a real file, or a real file with one number made absurd."""
    seeds = SEEDS[suffix]
    truncated = st.tuples(st.sampled_from(seeds), st.floats(0, 1)).map(lambda t: t[0][: int(len(t[0]) * t[1])])

    def absurd(t: tuple[bytes, int, bytes]) -> bytes:
        data, pick, value = t
        head = data[:2048]
        numbers = [m for m in __import__("re").finditer(rb"(?<![\w.])\d+(?![\w.])", head)]
        if not numbers:
            return data
        m = numbers[pick % len(numbers)]
        return data[: m.start()] + value + data[m.end():]

    header = st.tuples(st.sampled_from(seeds), st.integers(0, 10_000), st.sampled_from(ABSURD)).map(absurd)
    return st.one_of(st.binary(max_size=4096), truncated, header)


def read(suffix: str, data: bytes) -> None:
    path = WORK / f"capture{suffix}"
    path.write_bytes(data)
    started, cpu = time.monotonic(), time.process_time()
    try:
        load_capture(path)
    except InputError as exc:
        assert str(exc).strip() and "\n" not in str(exc).strip(), repr(exc)
    # CPU seconds (robust to a loaded machine), and a generous wall bound for blocking hangs
    assert time.process_time() - cpu < SECONDS_PER_EXAMPLE and time.monotonic() - started < 6 * SECONDS_PER_EXAMPLE


@pytest.mark.parametrize("suffix", sorted(SEEDS))
def test_readers_never_crash(suffix: str) -> None:
    @FUZZ
    @given(mutated(suffix))
    def run(data: bytes) -> None:
        read(suffix, data)

    run()


@FUZZ
@given(st.one_of(st.binary(max_size=2048), st.text(max_size=400).map(str.encode),
                 st.dictionaries(st.sampled_from(["units", "up", "support_height", "support", "labels", "text", "camera", "suport"]),
                                 st.one_of(st.none(), st.floats(allow_nan=True), st.text(max_size=8),
                                           st.lists(st.floats(), max_size=3), st.dictionaries(st.text(max_size=6), st.floats(), max_size=3)),
                                 max_size=4).map(lambda d: __import__("yaml").safe_dump(d).encode())))
def test_capture_yaml_never_crashes(data: bytes) -> None:
    folder = WORK / "yaml_capture"
    folder.mkdir(exist_ok=True)
    (folder / "capture.yaml").write_bytes(data)
    try:
        config = read_capture_config(folder)
    except InputError as exc:
        assert "\n" not in str(exc).strip()
        return
    parse_capture_config(config.model_dump(exclude_none=True))  # what was accepted validates again


@FUZZ
@given(st.one_of(st.binary(max_size=1024), st.text(max_size=300).map(str.encode)))
def test_pipeline_yaml_never_crashes(data: bytes) -> None:
    path = WORK / "pipeline.yaml"
    path.write_bytes(data)
    try:
        load_pipeline(path)
    except InputError as exc:
        assert "\n" not in str(exc).strip()


NUMBERS = st.one_of(st.integers(-10**12, 10**12).map(str), st.floats(allow_nan=True, allow_infinity=True).map(repr),
                    st.sampled_from(["abc", "", "[1, 2]", "{a: 1}", "true", "null", ".nan", "-.inf", "1e400"]))
SET_KEYS = st.sampled_from(["planes.distance_threshold", "planes.max_planes", "segment.min_points", "settle.max_time",
                            "robot.pose", "robot.enabled", "objects.assets.max_hulls", "objects.layout", "planes",
                            "nosuch.param", "planes.nosuch", "settle.check_time"])


@FUZZ
@given(seed=st.one_of(st.integers(-5, 2**33).map(str), NUMBERS), pose=st.lists(NUMBERS, min_size=0, max_size=4),
       sets=st.lists(st.tuples(SET_KEYS, NUMBERS), max_size=3), units=st.sampled_from(["m", "cm", "mm", "km", ""]),
       output=st.sampled_from(["", ".", "..", "/", "out", str(WORK / "flags_out")]))
def test_cli_flags_never_crash(seed: str, pose: list[str], sets: list[tuple[str, str]], units: str, output: str) -> None:
    argv = ["convert", str(MOSD / "test0.pcd"), "-o", output, "--check", "-q", f"--seed={seed}", f"--units={units}"]
    if pose:
        argv.append(f"--robot-pose={','.join(pose)}")
    for key, value in sets:
        argv += ["--set", f"{key}={value}"]
    err = io.StringIO()
    started = time.process_time()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        try:
            code = cli.main(argv)
        except SystemExit as exc:  # argparse's own usage errors
            code = exc.code
    assert time.process_time() - started < SECONDS_PER_EXAMPLE
    assert code in (0, 2), (argv, err.getvalue())
    if code == 2:
        lines = err.getvalue().strip().splitlines()
        assert len(lines) == 1 and "Traceback" not in err.getvalue(), (argv, err.getvalue())


def test_bounded_memory() -> None:
    """After every example above (same process), the peak resident memory stayed bounded."""
    peak_gb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024**2
    assert peak_gb < 4.0, f"peak RSS {peak_gb:.1f} GB"
