#!/usr/bin/python3
"""Functions in Filters/ and IO/ longer than 150 lines: a filter is a thin face over plain cores.

A function body is counted from its opening brace (alone on a line, as clang-format writes a
function's) to the matching closing brace at the same indentation; the check fails on any function
over the limit and names it. Usage: scripts/check-function-length.py
"""
import os
import re
import sys

LIMIT = 150
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SIGNATURE_END = re.compile(r"\)\s*(const)?\s*(override)?\s*(noexcept)?\s*$|\)\s*->.*$")


def functions():
    for top in ("Filters", "IO"):
        for folder, _, names in sorted(os.walk(os.path.join(ROOT, top))):
            for name in sorted(names):
                if not name.endswith((".cxx", ".h", ".txx")):
                    continue
                path = os.path.join(folder, name)
                with open(path, errors="replace") as f:
                    lines = f.read().split("\n")
                i = 0
                while i < len(lines):
                    m = re.match(r"^(\s*)\{\s*$", lines[i])
                    if m and i > 0 and SIGNATURE_END.search(lines[i - 1]):
                        j = i + 1
                        while j < len(lines) and not re.match("^" + m.group(1) + r"\}", lines[j]):
                            j += 1
                        k = i - 1
                        while k > 0 and "(" not in lines[k]:
                            k -= 1
                        head = lines[k].strip()
                        name_match = re.search(r"([\w:~]+)\s*\(", head)
                        yield os.path.relpath(path, ROOT), name_match.group(1) if name_match else head, j - i + 1
                        i = j
                    i += 1


def main():
    long = sorted((p, n, length) for p, n, length in functions() if length > LIMIT)
    for p, n, length in long:
        print("%s: %s is %d lines (at most %d): split it into steps, each a plain function" % (p, n, length, LIMIT))
    print("%d functions over %d lines" % (len(long), LIMIT))
    return 1 if long else 0


if __name__ == "__main__":
    sys.exit(main())
