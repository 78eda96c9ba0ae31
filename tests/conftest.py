"""Shared fixtures: paths to the real data in ../shared/data and a per-session cache folder."""

from __future__ import annotations

import fcntl
import os
from pathlib import Path
from typing import Callable, Iterator

import pytest

os.environ.setdefault("MUJOCO_GL", "egl")
if os.environ.get("PYTEST_XDIST_WORKER"):  # the xdist workers already fill the cores: no pools inside them
    os.environ.setdefault("REALSIM_WORKERS", "1")
    os.environ.setdefault("OMP_NUM_THREADS", "1")

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"
MOSD = DATA / "pcl_scenes" / "mOSD"
PCL = DATA / "pcl_scenes"
YCB = DATA / "ycb_google16k"


@pytest.fixture(scope="session", autouse=True)
def _session_env(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """The Panda from the shared data; session fixtures get a cache of their own (never ~/.cache)."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("MENAGERIE_ROOT", os.environ.get("MENAGERIE_ROOT", str(DATA)))
        mp.setenv("REALSIM_CACHE", str(tmp_path_factory.mktemp("realsim-cache")))
        yield


@pytest.fixture(scope="module", autouse=True)
def _module_cache(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """Each test module (and its module-scoped fixtures) gets its own empty realsim cache, so no
    test depends on what another one cached: the suite passes in any order."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("REALSIM_CACHE", str(tmp_path_factory.mktemp("realsim-cache")))
        yield


@pytest.fixture(autouse=True)
def _test_cache(tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch, request: pytest.FixtureRequest) -> None:
    """Each test gets its own empty cache too, unless it is marked ``shared_cache`` (it then sees
    its module's cache, e.g. to use what a module fixture computed)."""
    if request.node.get_closest_marker("shared_cache") is None:
        monkeypatch.setenv("REALSIM_CACHE", str(tmp_path_factory.mktemp("realsim-cache")))


def built_once(factory: pytest.TempPathFactory, key: str, build: Callable[[Path], object]) -> Path:
    """The folder ``build(folder)`` writes, built once per test run for all modules that ask for
    ``key`` (under pytest-xdist, once across the workers: the first to ask builds it under a file
    lock, the others wait for it). It is built with an empty realsim cache of its own, so it is
    the same whichever module asks first. Read only: a test that changes it works on a copy."""
    base = factory.getbasetemp()
    shared = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base  # xdist: <run>/popen-gwN
    pointer = shared / f"built-{key}.path"
    with open(shared / f"built-{key}.lock", "w") as lock, pytest.MonkeyPatch.context() as mp:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if pointer.is_file():
            return Path(pointer.read_text())
        root = factory.mktemp(f"built-{key}")
        mp.setenv("REALSIM_CACHE", str(root / "cache"))
        build(root / key)
        assert (root / key).is_dir(), f"building {key} wrote nothing"
        pointer.write_text(str(root / key))
        return root / key


def converted_scan(factory: pytest.TempPathFactory, name: str) -> Path:
    """The mOSD scan ``name`` converted with the defaults (the Panda placed, seed 0), once per run."""
    from realsim.pipeline import convert

    return built_once(factory, f"mosd-{name}", lambda out: convert(MOSD / f"{name}.pcd", out))


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "shared_cache: the test uses its module's realsim cache instead of its own")


@pytest.fixture(scope="session", autouse=True)
def _warp_accepts_every_written_scene(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """After the suite: MuJoCo Warp accepts every scene the tests wrote (with the per-world contact
    and constraint sizes the scene records) and those sizes hold the contacts at keyframe
    ``initial``. Scenes a test broke on purpose (they no longer compile) are not counted."""
    yield
    scenes = sorted(tmp_path_factory.getbasetemp().rglob("scene.xml"))
    if not scenes:  # importing MuJoCo Warp takes seconds: not for a run that wrote no scene
        return
    from realsim.physics.throughput import warp_available

    if not warp_available():
        return
    import hashlib
    import json

    import mujoco
    import mujoco_warp as mjw

    seen: set[str] = set()
    failures: list[str] = []
    for xml in scenes:
        meta = xml.with_name("scene.json")
        digest = hashlib.sha256(xml.read_bytes()).hexdigest()
        if not meta.is_file() or digest in seen:
            continue
        seen.add(digest)
        try:
            capacity = json.loads(meta.read_text())["settle"]["capacity"]
            model = mujoco.MjModel.from_xml_path(str(xml))
        except Exception:  # no recorded sizes, or a file broken on purpose
            continue
        try:
            data = mujoco.MjData(model)
            if model.nkey and "initial" in [model.key(i).name for i in range(model.nkey)]:
                mujoco.mj_resetDataKeyframe(model, data, model.key("initial").id)
            mujoco.mj_forward(model, data)
            mjw.put_model(model)
            mjw.put_data(model, data, nworld=1, nconmax=model.nconmax, njmax=model.njmax)
            assert (model.nconmax, model.njmax) == (capacity["nconmax"], capacity["njmax"]), "sizes differ from scene.json"
            assert data.ncon <= model.nconmax and data.nefc <= model.njmax, f"{data.ncon} contacts / {data.nefc} rows overflow"
        except Exception as exc:
            failures.append(f"{xml}: {type(exc).__name__}: {exc}")
    assert not failures, "MuJoCo Warp rejects written scenes:\n" + "\n".join(failures)
    print(f"\nMuJoCo Warp accepted all {len(seen)} distinct scenes the tests wrote")
