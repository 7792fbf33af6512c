#!/usr/bin/env python3
"""One version everywhere: the CMake project (libraries, CMake package, plugin), the Python package
(``anatomesh --version``) and the latest released section of CHANGELOG.md must name the same one."""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def find(path, pattern):
    with open(os.path.join(ROOT, path)) as f:
        m = re.search(pattern, f.read(), re.M)
    if not m:
        sys.exit("%s: no version found (%s)" % (path, pattern))
    return m.group(1)


versions = {
    "CMakeLists.txt": find("CMakeLists.txt", r"project\(Anatomesh VERSION (\d+\.\d+\.\d+)"),
    "Wrapping/Python/anatomesh/__init__.py": find("Wrapping/Python/anatomesh/__init__.py",
                                                  r'^__version__ = "(\d+\.\d+\.\d+)"'),
    "CHANGELOG.md": find("CHANGELOG.md", r"^## (\d+\.\d+\.\d+)"),
}
if len(set(versions.values())) != 1:
    print("versions disagree: " + ", ".join("%s %s" % item for item in versions.items()))
    sys.exit(1)
print("version " + versions["CMakeLists.txt"])
