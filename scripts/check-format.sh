#!/bin/bash
# The C++ sources as clang-format writes them with the project's .clang-format: lists every file that differs
# and exits 1; exits 77 (ctest's "skipped") without clang-format.
# Usage: scripts/check-format.sh        (format a file with: clang-format -i FILE)
here="$(cd "$(dirname "$0")/.." && pwd)"
cd "$here" || exit 1
command -v clang-format >/dev/null || { echo "clang-format is not installed"; exit 77; }
if [ -d .git ] && command -v git >/dev/null; then
  files=$(git ls-files '*.cxx' '*.h')
else
  files=$(find Filters IO Plugins Testing Wrapping -name '*.cxx' -o -name '*.h')
fi
bad=0
for f in $files; do
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f"
    bad=$((bad + 1))
  fi
done
echo "$bad of $(echo "$files" | wc -w) C++ files differ from clang-format's layout"
[ "$bad" -eq 0 ]
