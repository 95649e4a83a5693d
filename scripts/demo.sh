#!/usr/bin/env bash
# Sets up and builds (scripts/setup.sh), then runs the main job on the default example and
# writes its results to mobius-demo/ (or the folder given as the first argument).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MOBIUS_BUILD_DIR:-$root/build}"
output="${1:-$PWD/mobius-demo}"
"$root/scripts/setup.sh"
xvfb-run -a -s "-screen 0 1280x1024x24" pvpython --force-offscreen-rendering \
  "$root/Examples/pvpython/center_map.py" \
  --plugin "$build/lib/paraview-5.11/plugins/MobiusRegistration/MobiusRegistration.so" \
  --output "$output"
echo "demo: results in $output"
