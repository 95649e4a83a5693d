#!/usr/bin/env bash
# Sets up a Debian bookworm machine and builds the project (Release, ccache):
#  1. installs the Debian packages in scripts/debian-packages.txt that are missing;
#  2. configures (which unpacks the CC0 example meshes of Debian's libcgal-demo into
#     build/data/meshes) and builds into build/ (or $MOBIUS_BUILD_DIR).
# Quick when everything is already there. Usage: scripts/setup.sh
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MOBIUS_BUILD_DIR:-$root/build}"

# --- 1. Debian packages ------------------------------------------------------------
mapfile -t packages < <(grep -v -E '^\s*(#|$)' "$root/scripts/debian-packages.txt")
missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

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
