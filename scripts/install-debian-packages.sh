#!/usr/bin/env bash
# Installs the Debian packages listed in the given files (one a line, # comments) that are
# not installed yet; does nothing, quickly, when all are. Uses sudo unless run as root.
# Usage: scripts/install-debian-packages.sh LIST...
set -euo pipefail

packages=()
for list in "$@"; do
  mapfile -t -O "${#packages[@]}" packages < <(grep -v -E '^\s*(#|$)' "$list")
done
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
