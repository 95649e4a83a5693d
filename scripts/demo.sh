#!/usr/bin/env bash
# Sets up and builds (scripts/setup.sh), then runs the main job on the default example:
# mobius-register's demo maps CGAL's cow (CC0, from libcgal-demo) onto a deformed, rotated
# copy of itself and writes mobius-demo/demo.vtp, demo.csv and demo.png in the current
# folder. Extra arguments go to mobius-register (e.g. --force to run it again).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MOBIUS_BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh"
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$build/bin/mobius-register" "$@"
