"""The allocator setting of long runs applies on glibc (Linux CI) and is harmless elsewhere."""

import ctypes
import ctypes.util
import platform
import sys

import pytest

from asperity.memory import retain_freed_memory

GLIBC = sys.platform.startswith("linux") and platform.libc_ver()[0] == "glibc"


class _MallInfo2(ctypes.Structure):
    _fields_ = [(name, ctypes.c_size_t) for name in (
        "arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks", "uordblks",
        "fordblks", "keepcost")]


def test_retain_freed_memory_applies_on_glibc():
    assert retain_freed_memory(trim_mb=64) is GLIBC


@pytest.mark.skipif(not GLIBC, reason="glibc allocator statistics")
def test_a_freed_block_stays_in_the_heap():
    """After the setting a 20 MB block comes from the heap (not mapped on its own) and its
    memory stays free in the heap once released (glibc's mallinfo2 statistics)."""
    libc = ctypes.CDLL(ctypes.util.find_library("c"))
    if not hasattr(libc, "mallinfo2"):
        pytest.skip("glibc < 2.33 has no mallinfo2")
    libc.mallinfo2.restype = _MallInfo2
    libc.malloc.restype = ctypes.c_void_p
    libc.free.argtypes = [ctypes.c_void_p]
    assert retain_freed_memory(trim_mb=64)
    size = 20 << 20
    before = libc.mallinfo2()
    block = libc.malloc(size)
    ctypes.memset(block, 1, size)
    during = libc.mallinfo2()
    libc.free(block)
    after = libc.mallinfo2()
    assert during.hblkhd == before.hblkhd  # not mmapped
    assert after.fordblks - during.fordblks >= size  # kept, not trimmed
