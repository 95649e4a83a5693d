#!/usr/bin/env bash
# Sets up and builds (scripts/setup.sh), then runs every test: core unit tests, VTK filter
# tests with regression images, Python wrapping, pvpython plugin tests and the examples.
# Rendering tests need X, so ctest runs under Xvfb. Exits non-zero if any test fails.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MOBIUS_BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh"
cd "$build"
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure "$@"
