"""The allocator setting of long runs applies on glibc (Linux CI) and is harmless elsewhere."""

import platform
import sys

from asperity.memory import retain_freed_memory


def test_retain_freed_memory_applies_on_glibc():
    glibc = sys.platform.startswith("linux") and platform.libc_ver()[0] == "glibc"
    assert retain_freed_memory(trim_mb=64) is glibc
