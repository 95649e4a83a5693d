#!/usr/bin/env bash
# Plays a new user on a fresh Debian bookworm machine: a fresh `debootstrap --variant=minbase
# bookworm` chroot (scripts/bookworm-chroot.sh: the machine's own apt sources, /proc, /sys,
# /dev/shm and /dev/pts bind-mounted), a fresh clone of the committed HEAD in it, and there,
# as root without any environment variable, the README's commands:
#   (default)      ./scripts/demo.sh, then ./scripts/test.sh (ParaView 5.11 and its VTK)
#   --plain-vtk    docs/testing.md's "Without ParaView" commands, verbatim (Debian's VTK 9.1, no
#                  ParaView); CMAKE_<LANG>_COMPILER_LAUNCHER=ccache is added so that a second
#                  run builds from the compiler cache
# It prints each command's result (status, time, the ctest summary and failed tests), and
# exits non-zero if one failed, so that a package missing from scripts/debian-packages.txt
# or a test that passes only on a used machine shows. Uncommitted changes are not checked.
# Run as root: scripts/check-fresh-machine.sh [--plain-vtk]
# The chroot is $MOBIUS_CHROOT_DIR/fresh-<variant> (default /work/chroots), made anew at
# each run and left for inspection, with the commands' logs beside it (fresh-<variant>-logs).
# Cached across runs (scripts/bookworm-chroot.sh): the debootstrap base, the .deb files and
# the compiler cache (mounted as the chroot's ~/.cache/ccache, ccache's default folder).
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(dirname "$here")"
# shellcheck source=bookworm-chroot.sh
source "$here/bookworm-chroot.sh"

variant=paraview
case "${1:-}" in
  "") ;;
  --plain-vtk) variant=plain-vtk ;;
  *) echo "usage: $0 [--plain-vtk]" >&2; exit 2 ;;
esac
chroots="${MOBIUS_CHROOT_DIR:-/work/chroots}"
root="$chroots/fresh-$variant"
logs="$chroots/fresh-$variant-logs"
checkout=/root/mobius-registration
ccache_dir="$chroot_cache/ccache"

"$here/install-debian-packages.sh" "$here/debian-packages-chroot.txt" || exit 1
commit="$(git -C "$repo" rev-parse HEAD)" || exit 1
if [ -n "$(git -C "$repo" status --porcelain --untracked-files=no)" ]; then
  echo "check-fresh-machine: uncommitted changes in $repo are not checked"
fi

SECONDS=0
chroot_remove "$root" || exit 1
rm -rf "$logs" && mkdir -p "$logs" "$ccache_dir"
remove_seconds=$SECONDS
chroot_create "$root" || { echo "check-fresh-machine: could not make the chroot"; exit 1; }
chroot_mount "$root" "$ccache_dir:/root/.cache/ccache" || exit 1
git clone -q --no-hardlinks "$repo" "$root$checkout" &&
  git -C "$root$checkout" checkout -q --detach "$commit" || exit 1
base_seconds=$((SECONDS - remove_seconds))
CCACHE_DIR="$ccache_dir" ccache --zero-stats > /dev/null 2>&1

results=()
failed=0
# step LABEL LOG COMMAND...: runs COMMAND (in the chroot, from the checkout), records its
# status and time, shows the end of its log if it failed.
step() {
  local label="$1" log="$logs/$2"; shift 2
  local start=$SECONDS status
  echo "== $label (log: $log)"
  chroot_run "$root" bash -c "cd $checkout && $*" > "$log" 2>&1 < <(yes)
  status=$?
  local summary
  summary="$(grep -E "tests passed, [0-9]+ tests failed out of|^Demo ground truth" "$log" | tail -1)"
  if [ "$status" = 0 ]; then
    results+=("PASS  $label  ($((SECONDS - start)) s)  $summary")
  else
    results+=("FAIL  $label  ($((SECONDS - start)) s, exit status $status)  $summary")
    failed=1
    tail -40 "$log"
  fi
  # The failed tests, by name, from ctest's list.
  local test
  while read -r test; do results+=("      $test"); done < <(
    sed -n '/The following tests FAILED:/,$p' "$log" | grep -E "^\s+[0-9]+ - ")
  return "$status"
}

if [ "$variant" = paraview ]; then
  step "./scripts/demo.sh" demo.log ./scripts/demo.sh &&
    for output in demo.vtp demo.csv demo.png; do
      [ -s "$root$checkout/mobius-demo/$output" ] ||
        { results+=("FAIL  the demo wrote no mobius-demo/$output"); failed=1; }
    done
  step "./scripts/test.sh" test.log ./scripts/test.sh
else
  # docs/testing.md's block of commands after "**Without ParaView.**".
  commands="$(awk '/^\*\*Without ParaView\.\*\*/ { section = 1 }
                   section && /^```shell/ { inside = 1; next }
                   inside && /^```/ { exit }
                   inside { print }' "$repo/docs/testing.md")"
  if [ -z "$commands" ]; then
    echo "check-fresh-machine: no commands under **Without ParaView.** in docs/testing.md"; exit 1
  fi
  printf '%s\n' "$commands" > "$logs/commands.sh"
  chroot_run "$root" apt-get install -y -q --no-install-recommends ccache \
    > "$logs/ccache-install.log" 2>&1 || { tail -20 "$logs/ccache-install.log"; exit 1; }
  step "docs/testing.md, Without ParaView (ccache as compiler launcher)" plain-vtk.log \
    "export CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache; set -e; $commands"
fi

echo
echo "== summary: $variant check of ${commit:0:7} in a Debian $(chroot_run "$root" cat /etc/debian_version)" \
     "minbase chroot at $root"
chroot_run "$root" dpkg-query -W -f '   ${Package} ${Version}\n' libexpat1 paraview libvtk9.1 2> /dev/null
echo "   previous chroot removed in ${remove_seconds} s, chroot made and cloned in ${base_seconds} s;" \
     "total $SECONDS s"
CCACHE_DIR="$ccache_dir" ccache --print-stats 2> /dev/null | awk '
  $1 ~ /^(direct_cache_hit|preprocessed_cache_hit)$/ { hits += $2 } $1 == "cache_miss" { misses = $2 }
  END { if (hits + misses) printf "   compiler cache: %d hits, %d misses\n", hits, misses }'
printf '%s\n' "${results[@]}"
exit $failed
