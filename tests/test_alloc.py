"""glibc's allocator keeps freed numpy temporaries for reuse once a pipeline runs."""

import subprocess
import sys
import textwrap

import pytest

from conftest import REPO

# In a fresh process: where a block comes from depends on what the heap already holds (a long
# pytest worker may keep a free chunk big enough for the 100 MB block below).
CHECK = textwrap.dedent('''
    import ctypes

    import numpy as np

    from realsim.alloc import reuse_freed_memory


    class _MallInfo2(ctypes.Structure):
        _fields_ = [(name, ctypes.c_size_t) for name in
                    ("arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks", "uordblks", "fordblks", "keepcost")]


    assert reuse_freed_memory() is True
    assert reuse_freed_memory() is True  # idempotent
    mallinfo2 = ctypes.CDLL(None).mallinfo2
    mallinfo2.restype = _MallInfo2
    before = mallinfo2().hblks  # blocks served by mmap
    block = np.ones((3000, 124))  # a 3 MB temporary: from the heap now, not a fresh mmap
    assert mallinfo2().hblks == before, (mallinfo2().hblks, before)
    big = np.ones((100 << 20) // 8)  # above the threshold: still mmapped (and returned on free)
    assert mallinfo2().hblks == before + 1, (mallinfo2().hblks, before)
    del block, big
''')


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="glibc only")
def test_temporaries_come_from_the_heap() -> None:
    done = subprocess.run([sys.executable, "-c", CHECK], cwd=REPO, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
