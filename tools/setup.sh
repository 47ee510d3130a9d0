#!/usr/bin/env bash
# Installs what polydem needs to build and test, from Debian packages. Idempotent: installs
# only what is missing. Uses sudo only when not root.
set -euo pipefail
packages=(build-essential cmake libcgal-dev libeigen3-dev libyaml-cpp-dev catch2 zlib1g-dev
          python3 python3-vtk9 python3-numpy python3-matplotlib
          xvfb xauth ffmpeg  # polydem render: an X server for VTK's GL without a display; videos
          libopenmpi-dev openmpi-bin)  # MPI (CMake POLYDEM_MPI: built with it when present)
# Not python3-paraview: Debian 12 makes it conflict with python3-vtk9, so render uses VTK itself.
# `setup.sh clang`: also clang, its sanitizer and libFuzzer runtimes and LLVM's OpenMP, for the
# sanitizer and fuzz builds (tools/sanitize.sh, tools/fuzz.sh, tools/tsan.sh).
[ "${1:-}" = clang ] && packages+=(clang libclang-rt-14-dev libomp-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all dependencies present"
  exit 0
fi
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "setup: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
