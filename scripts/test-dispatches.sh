#!/usr/bin/env bash
# Runs the accuracy-sensitive tests (ctest label Accuracy) of the build again under other
# CPU dispatches of this machine, so that a bound that holds only with this CPU's math
# routines fails here before it fails on a user's CPU (docs/testing.md, "Other CPUs"):
#   - glibc's math routines without FMA and AVX2 (GLIBC_TUNABLES=glibc.cpu.hwcaps=-FMA,-AVX2):
#     exp, log, pow, sin, cos, atan2... take the SSE2 versions a CPU without FMA runs;
#   - OpenBLAS's Haswell kernels (OPENBLAS_CORETYPE=Haswell: those of AVX2 CPUs without
#     AVX-512, AMD's Zen included), or its Sandybridge ones where Haswell's are already the
#     default or the CPU cannot run them. CHOLMOD's supernodal factorizations (meshes of
#     50,000 vertices and more) and LAPACK go through them.
# Each setting is checked to take effect first (glibc ignores a name it does not know, and
# OpenBLAS one the CPU cannot run). Then the default map of CGAL's cow onto a bent copy of it
# is computed under each dispatch and must be the same bit for bit (docs/accuracy.md,
# "Reproducibility across CPUs").
# Usage: scripts/test-dispatches.sh [--glibc-only] [ctest options...]   (after scripts/setup.sh
# or test.sh; MOBIUS_BUILD_DIR as for test.sh). --glibc-only: glibc's dispatch alone (CI's
# run: it is the one that moves maps below 50,000 vertices). Exits non-zero if a test fails
# under any dispatch.
set -euo pipefail
glibc_only=0
if [ "${1:-}" = --glibc-only ]; then
  glibc_only=1
  shift
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MOBIUS_BUILD_DIR:-$root/build}"
register="$build/bin/mobius-register"
if [ ! -x "$register" ]; then
  echo "test-dispatches: no build in $build: run scripts/setup.sh first" >&2
  exit 2
fi
# The Python the build was configured with (it has numpy), as the tests use it.
python="$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt")"

# --- The dispatches -------------------------------------------------------------------
# glibc: the FMA bit (CPUID leaf 1, ECX bit 12) and the AVX2 bit (leaf 7, EBX bit 5) of the
# features ld.so lets its routines use, with and without the tunable.
glibc_feature() { # [VAR=value...] -> "FMA AVX2", 1 where usable
  local diagnostics leaf1_ecx leaf7_ebx
  diagnostics="$(env "$@" /lib64/ld-linux-x86-64.so.2 --list-diagnostics)"
  leaf1_ecx="$(sed -n 's/^x86.cpu_features.features\[0x0\].active\[0x2\]=//p' <<<"$diagnostics")"
  leaf7_ebx="$(sed -n 's/^x86.cpu_features.features\[0x1\].active\[0x1\]=//p' <<<"$diagnostics")"
  echo "$(((${leaf1_ecx:-0} >> 12) & 1)) $(((${leaf7_ebx:-0} >> 5) & 1))"
}
openblas_core() { # ENV... -> the core OpenBLAS picks (it prints it when the library loads)
  env OPENBLAS_VERBOSE=2 "$@" "$register" --version 2>&1 | sed -n 's/^Core: //p' | head -n 1
}

glibc_tunable="GLIBC_TUNABLES=glibc.cpu.hwcaps=-FMA,-AVX2"
read -r fma avx2 <<<"$(glibc_feature)"
read -r tuned_fma tuned_avx2 <<<"$(glibc_feature "$glibc_tunable")"
if [ "$tuned_fma$tuned_avx2" != "00" ]; then
  echo "test-dispatches: $glibc_tunable left FMA=$tuned_fma AVX2=$tuned_avx2 usable: not applied" >&2
  exit 2
fi
dispatches=("$glibc_tunable")
notes=("glibc math without FMA and AVX2 (this CPU: FMA $fma, AVX2 $avx2)")

default_core="$(openblas_core)"
if [ "$glibc_only" = 1 ]; then
  echo "test-dispatches: --glibc-only: OpenBLAS's other kernels not tried"
elif [ -z "$default_core" ]; then
  echo "test-dispatches: OpenBLAS does not say its core (libblas.so.3 is not OpenBLAS?): its run skipped"
else
  other_core=Haswell
  if [ "$default_core" = Haswell ] || [ "$default_core" = Zen ] || [ "$avx2" != 1 ]; then
    other_core=Sandybridge
  fi
  if [ "$(openblas_core OPENBLAS_CORETYPE=$other_core)" = "$other_core" ]; then
    dispatches+=("OPENBLAS_CORETYPE=$other_core")
    notes+=("OpenBLAS $other_core kernels (default here: $default_core)")
  else
    echo "test-dispatches: OpenBLAS does not take OPENBLAS_CORETYPE=$other_core here: its run skipped"
  fi
fi

# --- The accuracy-sensitive tests under each ------------------------------------------
status=0
summary=()
for i in "${!dispatches[@]}"; do
  echo "test-dispatches: ctest -L Accuracy with ${dispatches[$i]}: ${notes[$i]}"
  start=$SECONDS
  if (cd "$build" && env "${dispatches[$i]}" \
      xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest -L Accuracy --output-on-failure "$@"); then
    result=passed
  else
    result=FAILED
    status=1
  fi
  summary+=("${dispatches[$i]}: $result in $((SECONDS - start)) s")
done

# --- The same default map under every dispatch ------------------------------------------
# CGAL's cow onto a bent, rotated copy of it, the copy made once (the bend's sines and
# cosines are the CPU's too), mapped under each dispatch: the CSVs, 17 digits a number, must
# be the same bytes.
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"${python:-python3}" "$root/Examples/pvbatch/make_test_collection.py" "$work" "$build/data/meshes/cow.off" >/dev/null
map_pair() { # NAME [VAR=value...]
  local name=$1
  shift
  env "$@" "$register" "$work/cow.off" "$work/cow_bent.off" -o "$work/$name" --quiet --force
}
map_pair default
for i in "${!dispatches[@]}"; do
  map_pair "dispatch$i" "${dispatches[$i]}"
  if cmp -s "$work/default.csv" "$work/dispatch$i.csv"; then
    summary+=("cow onto its bent copy with ${dispatches[$i]}: the same map, bit for bit")
  else
    summary+=("cow onto its bent copy with ${dispatches[$i]}: the map DIFFERS from the default dispatch's")
    status=1
  fi
done
printf 'test-dispatches: %s\n' "${summary[@]}"
exit $status
