"""fork_map: the plain loop's results, shared with a forked helper, whatever the helper does."""

from __future__ import annotations

import os
import sys
import time

import numpy as np
import pytest
import trimesh

from realsim.completion.hull import from_arrays, mesh_arrays, trimesh_hull
from realsim.forkmap import Ahead, can_fork, fork_map

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="fork_map forks on Linux only")


@pytest.fixture(autouse=True)
def _two_workers(monkeypatch: pytest.MonkeyPatch) -> None:
    """The suite runs with one worker per process (tests/conftest.py): these tests allow the fork."""
    monkeypatch.setenv("REALSIM_WORKERS", "2")


def test_results_in_order_and_both_processes_work() -> None:
    parent = os.getpid()

    def work(i: int) -> tuple[int, int]:
        time.sleep(0.02)
        return i * i, os.getpid()

    out = fork_map(work, 40)
    assert [r for r, _ in out] == [i * i for i in range(40)]
    pids = {pid for _, pid in out}
    assert parent in pids and len(pids) == 2


def test_fewer_items_than_least_are_the_plain_loop() -> None:
    parent = os.getpid()
    assert fork_map(lambda i: os.getpid(), 3, least=4) == [parent] * 3
    assert len(set(fork_map(lambda i: time.sleep(0.02) or os.getpid(), 8, least=4))) == 2


def test_numpy_results_are_bit_identical() -> None:
    rng = np.random.default_rng(3)
    data = [rng.normal(size=(500, 3)) for _ in range(12)]
    out = fork_map(lambda i: np.linalg.svd(data[i] @ data[i].T / 7.0)[1], len(data))
    for i, s in enumerate(out):
        assert np.array_equal(s, np.linalg.svd(data[i] @ data[i].T / 7.0)[1])


def test_what_the_helper_fails_on_is_computed_here() -> None:
    parent = os.getpid()

    def work(i: int) -> int:
        if os.getpid() != parent:
            raise RuntimeError("helper only")
        time.sleep(0.01)
        return i + 1

    assert fork_map(work, 10) == list(range(1, 11))


def test_a_silent_helper_is_given_up() -> None:
    parent = os.getpid()

    def work(i: int) -> int:
        if os.getpid() != parent:
            time.sleep(30)
        return -i

    started = time.perf_counter()
    assert fork_map(work, 4, timeout=0.5) == [0, -1, -2, -3]
    assert time.perf_counter() - started < 10


def test_an_error_here_is_raised() -> None:
    def work(i: int) -> int:
        if i == 3:
            raise ValueError("item 3")
        return i

    with pytest.raises(ValueError, match="item 3"):
        fork_map(work, 6)


def test_one_worker_is_the_plain_loop(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "1")
    assert fork_map(lambda i: os.getpid(), 5) == [os.getpid()] * 5


def test_meshes_travel_exactly() -> None:
    rng = np.random.default_rng(0)
    for _ in range(20):
        mesh = trimesh_hull(rng.normal(size=(60, 3)))
        back = from_arrays(mesh_arrays(mesh))
        assert np.array_equal(back.vertices, mesh.vertices) and np.array_equal(back.faces, mesh.faces)
        assert np.array_equal(back.face_normals, mesh.face_normals) and back.volume == mesh.volume
    box = trimesh.creation.box((0.1, 0.2, 0.3))
    assert np.array_equal(from_arrays(mesh_arrays(box)).face_normals, box.face_normals)


def _in_pool_worker(_: int) -> bool:
    return can_fork()


def test_a_pool_worker_does_not_fork() -> None:
    import multiprocessing

    with multiprocessing.get_context("fork").Pool(1) as pool:
        assert pool.map(_in_pool_worker, [0]) == [False]


def test_no_helper_to_be_had_is_the_plain_loop(monkeypatch: pytest.MonkeyPatch) -> None:
    import multiprocessing.context

    def refuse(*_: object, **__: object) -> None:
        raise OSError("no semaphores here")

    def work(i: int) -> tuple[int, int]:
        time.sleep(0.05)  # long enough for a helper, were there one, to take some
        return i, os.getpid()

    monkeypatch.setattr(multiprocessing.context.ForkContext, "Value", refuse, raising=False)
    assert fork_map(work, 8) == [(i, os.getpid()) for i in range(8)]


def test_ahead_works_while_this_process_does_other_work() -> None:
    parent = os.getpid()

    def work(i: int) -> tuple[int, int]:
        time.sleep(0.05)
        return i * 3, os.getpid()

    with Ahead(work, 6) as ahead:
        time.sleep(0.2)  # the helper goes on meanwhile
        out = ahead.results()
    assert [r for r, _ in out] == [i * 3 for i in range(6)]
    assert sum(pid != parent for _, pid in out) >= 3  # it took the items while this process slept


def test_ahead_left_unasked_is_stopped() -> None:
    with pytest.raises(RuntimeError):
        with Ahead(lambda i: time.sleep(30), 3) as ahead:
            helper = ahead.helper
            raise RuntimeError("an error before the results are asked for")
    assert helper is not None and not helper.is_alive()


HELPER_RSS = '''
import os, time
import numpy as np
from realsim.alloc import reuse_freed_memory
from realsim.forkmap import fork_map

def rss() -> int:
    return int(open("/proc/self/statm").read().split()[1]) * os.sysconf("SC_PAGE_SIZE")

reuse_freed_memory()
block = np.ones((48 << 20) // 8)  # 48 MB from the heap, then freed: kept there for reuse, resident
del block
parent = os.getpid()
out = fork_map(lambda i: time.sleep(0.05) or (os.getpid(), rss()), 6)
mine, helper = [r for p, r in out if p == parent], [r for p, r in out if p != parent]
assert mine and helper, out
print(min(mine) - max(helper))
'''


def test_the_helper_lets_go_of_the_free_heap() -> None:
    """The helper hands its view of the parent's kept free heap back (``malloc_trim``): those pages are the
    parent's alone, so its temporaries write them in place instead of copying each one first."""
    import subprocess

    from conftest import REPO

    env = {**os.environ, "REALSIM_WORKERS": "2"}
    done = subprocess.run([sys.executable, "-c", HELPER_RSS], cwd=REPO, capture_output=True, text=True, timeout=120, env=env)
    assert done.returncode == 0, done.stderr
    assert int(done.stdout.split()[-1]) > 32 << 20  # the helper holds at least 32 of the 48 MB less
