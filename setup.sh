#!/usr/bin/env bash
# One set-up for both README commands: install the Debian packages centrec needs
# (only those missing), then configure and build in Release into ./build.
# Usage: ./setup.sh [--with-liggghts] [extra cmake args...]   e.g. ./setup.sh -DCENTREC_SANITIZE=ON
#   --with-liggghts (or CENTREC_WITH_LIGGGHTS=1): also install LIGGGHTS 3.8, LAMMPS and Open MPI,
#   for `centrec dem --engine liggghts`, the engine cross-checks and the benchmark's peers
#   (apps/bench/README.md); not needed otherwise.
# Environment: BUILD_DIR (default build), JOBS (default: all cores).
set -euo pipefail
cd "$(dirname "$0")"

WITH_LIGGGHTS="${CENTREC_WITH_LIGGGHTS:-0}"
CMAKE_ARGS=()
for a in "$@"; do
  if [ "$a" = "--with-liggghts" ]; then WITH_LIGGGHTS=1; else CMAKE_ARGS+=("$a"); fi
done

PACKAGES=(
  build-essential cmake pkg-config git
  libeigen3-dev libsundials-dev libhdf5-dev libyaml-cpp-dev
  libgtest-dev libgmock-dev libomp-dev
  python3 python3-matplotlib python3-h5py python3-numpy python3-yaml python3-meshio python3-pandas python3-xarray python3-pip
  nlohmann-json3-dev libcli11-dev
)
if [ "$WITH_LIGGGHTS" = "1" ]; then PACKAGES+=(liggghts lammps openmpi-bin); fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc)}"
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release ${CMAKE_ARGS[@]+"${CMAKE_ARGS[@]}"} >/dev/null
cmake --build "$BUILD_DIR" -j "$JOBS"
