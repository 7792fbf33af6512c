"""glibc's allocator set, inside a Python process already running, as the ``anatomesh`` command sets
it through ``GLIBC_TUNABLES`` when it starts (why: the comment in Wrapping/anatomesh, and
docs/benchmarks.md#main-job). ``mallopt`` gives all of that setting but the huge pages: large blocks
from the heap (``M_MMAP_MAX`` 0), up to 2 GB of freed space kept for the next filter
(``M_TRIM_THRESHOLD``, an int), two arenas (``M_ARENA_MAX``). The price: the process keeps the memory
of its largest run until it ends.
"""
import ctypes
import os
import sys

# mallopt's parameters (malloc.h).
M_TRIM_THRESHOLD = -1
M_MMAP_MAX = -4
M_ARENA_MAX = -8


def keep_freed_memory():
    """Set glibc's allocator in this process as the ``anatomesh`` command has it. True when set;
    False where it is not: not Linux with glibc, or ``GLIBC_TUNABLES`` set when the process started
    (the user's own setting, or the command's, is kept as it is)."""
    if not sys.platform.startswith("linux") or "GLIBC_TUNABLES" in os.environ:
        return False
    try:
        libc = ctypes.CDLL(None)  # the C library this process runs on
        libc.gnu_get_libc_version  # glibc's own: mallopt's numbering is glibc's
        mallopt = libc.mallopt
    except (OSError, AttributeError):
        return False
    mallopt.argtypes = (ctypes.c_int, ctypes.c_int)
    mallopt.restype = ctypes.c_int
    return all(mallopt(p, v) == 1 for p, v in ((M_MMAP_MAX, 0), (M_TRIM_THRESHOLD, 2**31 - 1), (M_ARENA_MAX, 2)))
