"""glibc's allocator keeps freed numpy temporaries for reuse once a pipeline runs."""

import ctypes
import sys

import numpy as np
import pytest

from realsim.alloc import reuse_freed_memory


class _MallInfo2(ctypes.Structure):
    _fields_ = [(name, ctypes.c_size_t) for name in
                ("arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks", "uordblks", "fordblks", "keepcost")]


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="glibc only")
def test_temporaries_come_from_the_heap() -> None:
    assert reuse_freed_memory() is True
    assert reuse_freed_memory() is True  # idempotent
    mallinfo2 = ctypes.CDLL(None).mallinfo2
    mallinfo2.restype = _MallInfo2
    before = mallinfo2().hblks  # blocks served by mmap
    block = np.ones((3000, 124))  # a 3 MB temporary: from the heap now, not a fresh mmap
    assert mallinfo2().hblks == before
    big = np.ones((100 << 20) // 8)  # above the threshold: still mmapped (and returned on free)
    assert mallinfo2().hblks == before + 1
    del block, big
