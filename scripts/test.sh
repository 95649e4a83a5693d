#!/usr/bin/env bash
# Sets up and builds (scripts/setup.sh), then runs every test: core unit tests, VTK filter
# tests with regression images, Python wrapping, pvpython plugin tests and the examples.
# Rendering tests need X, so ctest runs under Xvfb; -noreset keeps the server from resetting
# each time its last client leaves, which made the next test's connection fail now and then.
# Exits non-zero if any test fails.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MOBIUS_BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh"
cd "$build"
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure "$@"
