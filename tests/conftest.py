"""Shared fixtures: paths to the real data in ../shared/data and a per-session cache folder."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Iterator

import pytest

os.environ.setdefault("MUJOCO_GL", "egl")

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


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "shared_cache: the test uses its module's realsim cache instead of its own")
