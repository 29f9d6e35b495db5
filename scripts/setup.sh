#!/usr/bin/env bash
# Installs what the project needs from Debian 12 (only the missing packages,
# so running it again is cheap) and builds everything into ./build.
set -euo pipefail
cd "$(dirname "$0")/.."

# ParaView 5.11 and its bundled VTK 9.2 (python3-paraview conflicts with
# libvtk9-dev: ParaView's VTK is the one VTK). The -dev packages after
# paraview-dev are what find_package(ParaView) asks for
# (../shared/SETUP-NOTES.md); the last lines are our own build and test
# tools: GLPK is the tests' independent LP oracle, libcgal-demo holds the
# real test meshes with known topology, CGAL (header-only, with GMP and MPFR)
# is the tests' independent oracle for self-intersections, OpenVDB (with the
# Boost part its CMake module asks for) is the benchmark's baseline; clang with its libFuzzer and
# sanitizer runtimes, and valgrind, check the core (scripts/test.sh);
# openscad-testing-data holds broken STL files for the bad-input tests;
# libqt5opengl5-dev is what ParaView's Qt asks for when the plugin's GUI
# component builds, and the GUI test drives ParaView's own widgets with
# python3-pyqt5 (in ParaView's Python) and xdotool (a real click).
packages=(
  paraview paraview-dev python3-paraview xvfb xauth
  qtbase5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools libutfcpp-dev
  libopenmpi-dev libhdf5-dev libhdf5-mpi-dev libnetcdf-dev libgdal-dev libdouble-conversion-dev
  liblz4-dev liblzma-dev libjpeg-dev libtiff-dev libfreetype-dev libexpat1-dev libxml2-dev
  libglew-dev libgl2ps-dev libtheora-dev libogg-dev libx11-dev libgl-dev libpugixml-dev
  libjsoncpp-dev libprotobuf-dev protobuf-compiler libcgns-dev libpython3-dev python3-mpi4py
  libavformat-dev libavcodec-dev libavutil-dev libswscale-dev libxt-dev libtbb-dev
  cmake ninja-build g++ libgtest-dev
  libglpk-dev libcgal-demo libcgal-dev libgmp-dev libmpfr-dev libopenvdb-dev libboost-iostreams-dev
  clang libclang-rt-14-dev valgrind openscad-testing-data
  libqt5opengl5-dev python3-pyqt5 xdotool
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "Installing: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j"$(nproc)" >> build.log 2>&1 || { tail -50 build.log; exit 1; }
rm -f build.log
echo "Built into $(pwd)/build"
