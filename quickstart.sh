#!/usr/bin/env bash
# Anatomesh quick start, for a fresh Debian 12 machine (run as root, or with sudo available).
#   ./quickstart.sh run    install packages, build, install, run the thorax pipeline on the phantom
#   ./quickstart.sh test   install packages, build, install, run the whole test suite (ctest)
# Idempotent: packages already present are not touched, the build is incremental (ccache).
set -euo pipefail

mode="${1:-run}"
case "$mode" in run|test) ;; *) echo "usage: $0 run|test" >&2; exit 2 ;; esac

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${ANATOMESH_BUILD_DIR:-$here/build}"
jobs="${ANATOMESH_JOBS:-2}"
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi

packages=(
  build-essential cmake ccache pkg-config
  paraview paraview-dev python3-paraview libopenmpi-dev
  libinsighttoolkit5-dev libcgal-dev libtet1.5-dev libeigen3-dev zlib1g-dev libsuitesparse-dev libmetis-dev libopenblas0-pthread
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-numpy python3-matplotlib python3-mpi4py openmpi-bin python3-meshio python3-nibabel xvfb xauth
  qttools5-dev qtxmlpatterns5-dev-tools
)

# The test suite also fuzzes the parsers (clang's libFuzzer), checks the C++ layout (clang-format) and reads the
# meshes back in Gmsh, meshio (whose XDMF reader needs h5py) and FEniCSx (python3-dolfinx, which solves on them).
if [ "$mode" = test ]; then
  packages+=(clang clang-format libclang-rt-14-dev gmsh python3-gmsh python3-h5py python3-dolfinx)
fi

# ParaView 5.11's Python package ships its own VTK 9.2 'vtkmodules' and conflicts with python3-vtk9.
conflicting=()
for p in python3-vtk9; do
  if dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then conflicting+=("$p"); fi
done
if [ ${#conflicting[@]} -gt 0 ]; then
  echo "Anatomesh: ${conflicting[*]} (plain VTK 9.1 for Python) conflicts with python3-paraview, which Anatomesh"
  echo "           builds against (ParaView 5.11's VTK 9.2). Removing ${conflicting[*]} so python3-paraview can be installed."
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq "${conflicting[@]}" >/dev/null
fi
if dpkg-query -W -f='${Status}' libvtk9-dev 2>/dev/null | grep -q "install ok installed"; then
  echo "Anatomesh: libvtk9-dev (plain VTK 9.1) is installed; it is left alone and not used: the build uses ParaView's VTK."
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then missing+=("$p"); fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Anatomesh: installing ${#missing[@]} Debian package(s): ${missing[*]}"
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

echo "Anatomesh: configuring and building in $build"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 \
  -DCMAKE_INSTALL_PREFIX=/usr/local -DANATOMESH_TEST_INSTALLED=ON >"$build.configure.log" 2>&1 || { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j "$jobs" >"$build.build.log" 2>&1 || { tail -60 "$build.build.log"; exit 1; }
$SUDO cmake --install "$build" >"$build.install.log" 2>&1 || { tail -30 "$build.install.log"; exit 1; }
$SUDO ldconfig

# Stock ParaView lists the plugins named in the XML files that /usr/bin/paraview.conf names
# (Debian ships no such file, so its own list is named too, to keep its plugins listed).
pvdir=/usr/lib/x86_64-linux-gnu/paraview-5.11/plugins
for xml in "$pvdir/paraview.plugins.xml" "$pvdir/anatomesh.plugins.xml"; do
  if [ -f "$xml" ] && ! grep -qxF "$xml" /usr/bin/paraview.conf 2>/dev/null; then
    echo "$xml" | $SUDO tee -a /usr/bin/paraview.conf >/dev/null
  fi
done

if [ "$mode" = run ]; then
  out="${ANATOMESH_OUTPUT:-$here/out/thorax}"
  echo "Anatomesh: running Examples/Pipelines/thorax.xml on the embedded thorax phantom -> $out"
  anatomesh run "$here/Examples/Pipelines/thorax.xml" --output "$out" --report
else
  cd "$build"
  ctest --output-on-failure -j "$jobs" --timeout 1500
fi
