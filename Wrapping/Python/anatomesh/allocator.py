"""glibc's allocator set, inside a Python process already running, as the ``anatomesh`` command sets
it when it starts (see docs/benchmarks.md#main-job).

A run allocates and frees arrays of tens to hundreds of megabytes filter after filter. By default
glibc maps each large block afresh and hands it back to the kernel when it is freed, so every page
of the next block costs a page fault, which on a virtual machine costs microseconds. The command
starts itself with ``GLIBC_TUNABLES``; a Python script or notebook is already running when it
imports anatomesh, so it sets the same through ``mallopt``: large blocks from the heap
(``M_MMAP_MAX`` 0), freed space kept for the next filter (``M_TRIM_THRESHOLD`` at its largest, 2 GB
of free space at the heap's top), one heap shared by the worker threads (``M_ARENA_MAX`` 2). Only
huge pages (``glibc.malloc.hugetlb``) have no ``mallopt`` form. The price: the process keeps the
memory of its largest run until it ends.
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
