"""Shared fixtures: paths to the real data in ../shared/data and a per-session cache folder."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

os.environ.setdefault("MUJOCO_GL", "egl")

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data"
MOSD = DATA / "pcl_scenes" / "mOSD"
PCL = DATA / "pcl_scenes"
YCB = DATA / "ycb_google16k"


@pytest.fixture(scope="session", autouse=True)
def _isolated_cache(tmp_path_factory: pytest.TempPathFactory) -> None:
    """Every test session gets its own realsim cache unless REALSIM_CACHE is set."""
    if "REALSIM_CACHE" not in os.environ:
        os.environ["REALSIM_CACHE"] = str(tmp_path_factory.mktemp("realsim-cache"))
    os.environ.setdefault("MENAGERIE_ROOT", str(DATA))
