#!/usr/bin/env bash
# Sets up a Debian bookworm machine and builds the project (Release, ccache):
#  1. installs the Debian packages in scripts/debian-packages.txt that are missing;
#  2. configures (which unpacks the CC0 example meshes of Debian's libcgal-demo into
#     build/data/meshes) and builds into build/ (or $MOBIUS_BUILD_DIR).
# Quick when everything is already there. Usage: scripts/setup.sh
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Paths below the checkout are hashed relative to it, so a second clone (CI's) reuses
# the compiler cache of the first.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}"
build="${MOBIUS_BUILD_DIR:-$root/build}"

# --- 1. Debian packages ------------------------------------------------------------
"$root/scripts/install-debian-packages.sh" "$root/scripts/debian-packages.txt"

# --- 2. Configure and build -------------------------------------------------------
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" \
    -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -DCMAKE_C_COMPILER_LAUNCHER=ccache
fi
cmake --build "$build" --parallel "$(nproc)"
echo "setup: built in $build"
