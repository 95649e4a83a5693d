#!/bin/bash
# Installs the .deb that `cpack -G DEB` made (configured with -DCMAKE_INSTALL_PREFIX=/usr) on
# a clean Debian bookworm (a `debootstrap --variant=minbase` chroot) and checks, as a new
# user would and without any environment variable, every item of the package's "done when":
#   apt install ./file.deb pulls in its dependencies; mobius-register and its man page;
#   python3 -c "import mobiusregistration" and register(); pvpython imports it; the plugin is
#   loaded at pvpython and paraview start-up (its filters in the proxy list); the macro, run on
#   two meshes in pvbatch and from the paraview GUI's Macros menu, makes the side-by-side
#   views (screenshots); apt remove and apt purge leave no file of the package behind.
# Run as root on a bookworm machine:
#   scripts/check-deb-in-chroot.sh build-deb/mobius-registration_0.1.0_amd64.deb [CHROOT_DIR]
# The chroot (default $MOBIUS_CHROOT_DIR/deb, /work/chroots/deb) is made on the first run
# (scripts/bookworm-chroot.sh: the machine's own apt sources, its base and .deb files cached)
# and reused: a run removes the package (purge) at its end. The install pulls ParaView and
# its dependencies (~1.5 GB).
# Prints PASS or FAIL per item, a summary, and exits non-zero if any item failed; the
# screenshots are copied to $MOBIUS_CHECK_OUTPUT (default: the .deb's folder).
set -uo pipefail
deb=$(realpath "$1")
root=${2:-${MOBIUS_CHROOT_DIR:-/work/chroots}/deb}
output=$(realpath "${MOBIUS_CHECK_OUTPUT:-$(dirname "$deb")}")
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=bookworm-chroot.sh
source "$here/bookworm-chroot.sh"

"$here/install-debian-packages.sh" "$here/debian-packages-chroot.txt" || exit 1
if [ ! -x "$root/usr/bin/apt-get" ]; then
  chroot_remove "$root" && chroot_create "$root" || exit 1
fi
chroot_mount "$root" || exit 1
name=$(basename "$deb")
rm -rf "$root/tmp/mobius-check" && mkdir -p "$root/tmp/mobius-check"
cp "$deb" "$root/tmp/mobius-check/"
cp "$here"/check-deb/*.py "$here"/check-deb/*.xml "$root/tmp/mobius-check/"

# Everything below runs inside the chroot with a minimal environment: no PYTHONPATH,
# PV_PLUGIN_PATH, PV_MACRO_PATH or LD_LIBRARY_PATH.
in_chroot() { chroot_run "$root" "$@"; }

results=()
failed=0
# item NAME COMMAND...: runs one check, records PASS or FAIL.
item() {
  local label="$1"; shift
  echo "== $label"
  if "$@"; then results+=("PASS  $label"); else results+=("FAIL  $label"); failed=1; fi
}

# The package must not be there before the test (a previous run purges it).
in_chroot dpkg -s mobius-registration > /dev/null 2>&1 && in_chroot apt-get purge -y -q mobius-registration
in_chroot apt-get update -q > /dev/null

install_deb() {
  # apt resolves the package's dependencies from the archive (ParaView, python3, numpy...).
  in_chroot bash -c "cd /tmp/mobius-check && apt-get install -y -q --no-install-recommends ./$name" \
    > "$root/tmp/mobius-check/apt-install.log" 2>&1 || { tail -30 "$root/tmp/mobius-check/apt-install.log"; return 1; }
  grep -E "^(The following NEW packages|[0-9]+ upgraded)" "$root/tmp/mobius-check/apt-install.log"
  in_chroot dpkg -s mobius-registration | grep -E "^(Status|Version|Depends|Maintainer):"
  in_chroot dpkg -L mobius-registration > "$root/tmp/mobius-check/files.txt"
  echo "$(wc -l < "$root/tmp/mobius-check/files.txt") paths installed"
}
item "apt install ./$name (dependencies from the archive)" install_deb
# Without the package nothing else can be checked.
if [ "$failed" != 0 ]; then printf '%s\n' "${results[@]}"; exit 1; fi

check_program() {
  in_chroot mobius-register --version && in_chroot mobius-benchmark --version || return 1
  in_chroot bash -c 'rm -rf /tmp/demo && mkdir /tmp/demo && cd /tmp/demo &&
    mobius-register --resolution 64 --refine none --quiet --json -o demo > demo.json &&
    test -s demo.vtp && grep -q /usr/share/mobius-registration/meshes/cow.off demo.json' || return 1
  in_chroot bash -c 'cd /tmp/demo && mobius-register --resolution 64 --quiet --force -o demo' || return 1
  echo "the demo ran on the installed cow (Moebius map, then refined)"
}
item "mobius-register runs (version, demo on the installed mesh)" check_program

check_man() {
  in_chroot apt-get install -y -q --no-install-recommends man-db > /dev/null || return 1
  for page in mobius-register mobius-benchmark; do
    in_chroot man -w "$page" || return 1
    in_chroot env MANPAGER=cat MANWIDTH=80 man "$page" 2> /dev/null | head -12
    in_chroot env MANPAGER=cat man "$page" 2> /dev/null | grep -q -- "--help" || return 1
  done
}
item "man mobius-register, man mobius-benchmark" check_man

check_python() {
  in_chroot python3 -c 'import mobiusregistration' || return 1
  in_chroot python3 /tmp/mobius-check/python_register.py
}
item "python3 -c 'import mobiusregistration'; register() on the installed cow" check_python

check_pvpython() {
  in_chroot pvpython --force-offscreen-rendering /tmp/mobius-check/pvpython_plugin.py
}
item "pvpython: plugin loaded at start-up (filters in the proxy list), import mobiusregistration" check_pvpython

# Rendering needs an X server (Debian's ParaView is GLX-only): Xvfb with Mesa's llvmpipe.
in_chroot apt-get install -y -q --no-install-recommends xvfb xauth libgl1-mesa-dri > /dev/null

check_pvbatch_macro() {
  in_chroot xvfb-run -a -s "-screen 0 1280x1024x24" pvbatch /tmp/mobius-check/pvbatch_macro.py || return 1
  cp "$root/tmp/mobius-check/pvbatch-macro.png" "$output/chroot-pvbatch-macro.png" && \
    echo "screenshot: $output/chroot-pvbatch-macro.png"
}
item "pvbatch: the installed macro on two meshes makes the side-by-side views (screenshot)" check_pvbatch_macro

check_gui() {
  # A HOME of its own: no welcome dialog, nothing left in /root. The check macro in the
  # user's macro folder is clicked after the installed one (paraview_gui_events.xml).
  in_chroot bash -c 'rm -rf /tmp/gui-home && mkdir -p /tmp/gui-home/.config/ParaView/Macros &&
    printf "[General]\nGeneralSettings.ShowWelcomeDialog=false\n" > /tmp/gui-home/.config/ParaView/ParaView5.11.0.ini &&
    cp /tmp/mobius-check/gui_check_views.py /tmp/gui-home/.config/ParaView/Macros/ &&
    rm -f /tmp/mobius-check/gui-*.txt /tmp/mobius-check/gui-macro.png'
  in_chroot env HOME=/tmp/gui-home timeout 900 xvfb-run -a -s "-screen 0 1600x1000x24" \
    paraview --script=/tmp/mobius-check/gui_open_meshes.py \
    --test-script=/tmp/mobius-check/paraview_gui_events.xml --exit \
    > "$root/tmp/mobius-check/paraview.log" 2>&1
  local status=$?
  echo "paraview exit status $status"
  cat "$root/tmp/mobius-check/gui-result.txt" 2> /dev/null || { echo "no result from the GUI check macro"; tail -30 "$root/tmp/mobius-check/paraview.log"; return 1; }
  cp "$root/tmp/mobius-check/gui-macro.png" "$output/chroot-paraview-gui-macro.png" && \
    echo "screenshot: $output/chroot-paraview-gui-macro.png"
  grep -q "^ok" "$root/tmp/mobius-check/gui-result.txt" && [ "$status" = 0 ]
}
item "paraview GUI: plugin at start-up, Macros menu -> MobiusRegistrationPipeline on two meshes (screenshot)" check_gui

# What a user's run left (bytecode in the package's Python folder) must go too.
nothing_left() {
  local left=0
  # Every file and link the package had (its folders may be shared: /usr/bin...; the ones
  # of its own are named after it, which the search below finds).
  while read -r path; do
    if [ -L "$root$path" ] || { [ -e "$root$path" ] && [ ! -d "$root$path" ]; }; then
      echo "left behind: $path"; left=1
    fi
  done < "$root/tmp/mobius-check/files.txt"
  for folder in /usr/bin/plugins /usr/bin/Macros; do  # only this package puts these there
    if [ -e "$root$folder" ]; then echo "left behind: $folder"; left=1; fi
  done
  in_chroot bash -c 'find / -xdev \( -iname "*mobius*" -o -iname "*MobiusRegistration*" \) -not -path "/tmp/*" -not -path "/var/cache/*" -not -path "/var/lib/dpkg/*" -not -path "/var/lib/apt/*" -not -path "/var/log/*" -not -path "/proc/*"' \
    > "$root/tmp/mobius-check/left.txt"
  if [ -s "$root/tmp/mobius-check/left.txt" ]; then echo "left behind:"; cat "$root/tmp/mobius-check/left.txt"; left=1; fi
  return $left
}
check_remove() {
  in_chroot apt-get remove -y -q mobius-registration > /dev/null || return 1
  nothing_left && echo "apt remove: no file of the package left"
}
item "apt remove leaves no file of the package" check_remove

check_purge() {
  in_chroot apt-get purge -y -q mobius-registration > /dev/null || return 1
  if in_chroot dpkg -s mobius-registration > /dev/null 2>&1; then echo "dpkg still knows the package"; return 1; fi
  nothing_left && echo "apt purge: the package is unknown to dpkg, no file left"
}
item "apt purge leaves nothing (dpkg forgets the package)" check_purge

echo
echo "== summary ($name in a $(in_chroot cat /etc/debian_version) minbase chroot at $root)"
printf '%s\n' "${results[@]}"
exit $failed
