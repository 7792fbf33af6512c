#!/usr/bin/env bash
# Build and test Anatomesh against plain Debian VTK 9.1 (the secondary target), which cannot be
# installed beside python3-paraview: its packages are unpacked into a private prefix instead.
# C++ modules and GoogleTest suites only (no Python wrapping, no plugin). Run as root.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="${1:-/tmp/anatomesh-vtk91}"
mkdir -p "$work/debs" "$work/root" "$work/build"
# Non-conflicting libraries VTK 9.1's CMake config asks for.
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
  libtbb-dev libdouble-conversion-dev liblz4-dev libexpat1-dev zlib1g-dev libjsoncpp-dev libpugixml-dev \
  liblzma-dev libutfcpp-dev >/dev/null
cd "$work/debs"
[ -n "$(ls libvtk9-dev_*.deb 2>/dev/null)" ] || apt-get download libvtk9-dev libvtk9.1 python3-vtk9 2>/dev/null
for f in *.deb; do dpkg -x "$f" "$work/root"; done
export LD_LIBRARY_PATH="$work/root/usr/lib/x86_64-linux-gnu"
cmake -S "$here" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_DISABLE_FIND_PACKAGE_ParaView=ON \
  -DVTK_DIR="$work/root/usr/lib/x86_64-linux-gnu/cmake/vtk-9.1" -DANATOMESH_WRAP_PYTHON=OFF \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DANATOMESH_SHARED_DATA="$here/../shared/data"
cmake --build "$work/build" -j 2
cd "$work/build" && ctest --output-on-failure -j 2
