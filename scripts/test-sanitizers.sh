#!/usr/bin/env bash
# The sanitizer build and the fuzz minute (CI runs this after scripts/test.sh):
#  1. installs the Debian packages of scripts/debian-packages.txt and
#     scripts/debian-packages-sanitizers.txt that are missing (clang, compiler-rt, llvm);
#  2. builds the project with clang, RelWithDebInfo, AddressSanitizer and
#     UndefinedBehaviorSanitizer (every report is fatal) into build-sanitizers/ (or
#     $MOBIUS_SANITIZER_BUILD_DIR), with the libFuzzer target (MOBIUS_FUZZ);
#  3. runs the tests labelled Core, MobiusRegistration::Filters (the VTK filter tests,
#     image tests included, under Xvfb), Applications (mobius-register run by its Python
#     test), Hostile (the hostile-input suite) and Fuzz (the fuzzer's regression inputs);
#  4. fuzzes the mesh readers and the conformal map for $MOBIUS_FUZZ_SECONDS (60) seconds
#     from the seeds in Testing/Fuzz/Corpus.
# Exits non-zero on a failed test, on any sanitizer report (also one a test's harness
# swallowed: reports are written to files, which are checked afterwards) and on a fuzzer
# finding, whose input is left in <build>/fuzz/artifacts: fix the bug and add the input to
# Testing/Fuzz/Regressions.
#
# Not run here: the ParaView plugin and pvpython tests, and the Python wrapping tests
# (ParaView, pvpython and Debian's python3 are not built with AddressSanitizer, so they
# cannot load instrumented libraries); the build turns the plugin and the wrapping off.
# The Applications test skips its out-of-memory case: AddressSanitizer cannot start under the
# address-space limit (RLIMIT_AS) it sets.
# Nothing is suppressed. Mesa's software OpenGL driver is preloaded into the tests (see
# below) so that LeakSanitizer sees what the driver keeps; our code is checked in full.
# Usage: scripts/test-sanitizers.sh [extra ctest arguments]
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Paths below the checkout are hashed relative to it, so a second clone (CI's) reuses
# the compiler cache of the first.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}"
build="${MOBIUS_SANITIZER_BUILD_DIR:-$root/build-sanitizers}"
fuzz_seconds="${MOBIUS_FUZZ_SECONDS:-60}"
# A fixed seed makes the CI minute the same sequence of inputs on every run (a failure
# replays; a slower machine runs a prefix of it); MOBIUS_FUZZ_SEED=0 picks one at random.
fuzz_seed="${MOBIUS_FUZZ_SEED:-20181}"
start=$SECONDS

# --- 1. Debian packages ------------------------------------------------------------
"$root/scripts/install-debian-packages.sh" "$root/scripts/debian-packages.txt" \
  "$root/scripts/debian-packages-sanitizers.txt"

# --- 2. Configure and build -------------------------------------------------------
# -fno-sanitize-recover=all: a UBSan finding ends the program like an ASan one, so that no
# test can pass with a report in its output. The frame pointers make the stacks complete.
sanitize="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
if [ ! -f "$build/CMakeCache.txt" ]; then
  # MOBIUS_PARAVIEW=OFF builds against ParaView's VTK without the plugin.
  cmake -S "$root" -B "$build" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang-14 \
    -DCMAKE_CXX_COMPILER=clang++-14 \
    -DCMAKE_C_FLAGS="$sanitize" \
    -DCMAKE_CXX_FLAGS="$sanitize" \
    -DCMAKE_EXE_LINKER_FLAGS="$sanitize" \
    -DCMAKE_SHARED_LINKER_FLAGS="$sanitize" \
    -DCMAKE_MODULE_LINKER_FLAGS="$sanitize" \
    -DCMAKE_C_COMPILER_LAUNCHER=ccache \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -DPython3_EXECUTABLE=/usr/bin/python3 \
    -DMOBIUS_PARAVIEW=OFF \
    -DVTK_DIR=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk \
    -DMOBIUS_WRAP_PYTHON=OFF \
    -DMOBIUS_FUZZ=ON
fi
cmake --build "$build" --parallel "$(nproc)"
echo "test-sanitizers: built in $build after $((SECONDS - start)) s"

# --- 3. Sanitized tests -------------------------------------------------------------
# Every report ends the program with status 86 (no test expects that status) and is also
# written to $reports/<tool>.<pid>, checked below: a test that runs a program and only looks
# at its output could otherwise miss a report. allocator_may_return_null: an allocation too
# large for the machine throws std::bad_alloc, as without ASan (the programs report it as an
# error; ASan would otherwise end them).
reports="$build/sanitizer-reports"
rm -rf "$reports"
mkdir -p "$reports"
asan_options="halt_on_error=1:exitcode=86:allocator_may_return_null=1:detect_leaks=1"
ubsan_options="halt_on_error=1:exitcode=86:print_stacktrace=1"
export ASAN_OPTIONS="$asan_options:log_path=$reports/asan:log_exe_name=1"
export UBSAN_OPTIONS="$ubsan_options:log_path=$reports/ubsan:log_exe_name=1"
export LSAN_OPTIONS="exitcode=86"
export ASAN_SYMBOLIZER_PATH=/usr/bin/llvm-symbolizer-14

check_reports() {
  if compgen -G "$reports/*" > /dev/null; then
    echo "test-sanitizers: sanitizer reports ($1):"
    for report in "$reports"/*; do
      echo "=== $report"
      cat "$report"
    done
    return 1
  fi
}

# The image tests render with Mesa's software driver (swrast_dri.so), which Mesa loads when
# a window opens and unloads when it closes: what the driver still held then was reported
# as leaks with no stack ("<unknown module>"), impossible to tell apart or to suppress by
# name. Preloaded, the driver stays loaded and its memory reachable.
mesa_driver=/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so
cd "$build"
status=0
LD_PRELOAD="$mesa_driver" xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure --parallel 2 \
  -L '^(Core|MobiusRegistration::Filters|Applications|Hostile|Fuzz)$' "$@" || status=1
check_reports "tests" || status=1
echo "test-sanitizers: tests done after $((SECONDS - start)) s"
if [ "$status" -ne 0 ]; then
  exit "$status"
fi

# --- 4. Fuzzing ---------------------------------------------------------------------
# New inputs go to a scratch corpus; the seeds stay as they are. Each input gets at most
# 10 s and 2 GB (a hang or a runaway allocation is a finding); inputs up to 4 kB.
fuzz="$build/fuzz"
rm -rf "$fuzz/corpus" "$fuzz/artifacts"
mkdir -p "$fuzz/corpus" "$fuzz/artifacts"
# The fuzzer's reports go to the terminal, with its own.
export ASAN_OPTIONS="$asan_options" UBSAN_OPTIONS="$ubsan_options"
"$build/bin/mobius-fuzz-mesh" "$fuzz/corpus" "$root/Testing/Fuzz/Corpus" \
  -max_total_time="$fuzz_seconds" -seed="$fuzz_seed" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
  -artifact_prefix="$fuzz/artifacts/" -print_final_stats=1 || {
  echo "test-sanitizers: the fuzzer found a bug; the input is in $fuzz/artifacts"
  echo "  (replay: $build/bin/mobius-fuzz-mesh FILE; once fixed, add it to Testing/Fuzz/Regressions)"
  exit 1
}
echo "test-sanitizers: done after $((SECONDS - start)) s"
