#!/bin/bash
# Installs the .deb that `cpack -G DEB` made on a clean Debian bookworm (a debootstrap
# chroot), checks what a new user would use without any environment variable, removes the
# package and checks that nothing is left. Run as root on a bookworm machine:
#   scripts/check-deb-in-chroot.sh build-deb/mobius-registration_0.1.0_amd64.deb [CHROOT_DIR]
# The install pulls ParaView and its dependencies into the chroot (about 1.5 GB).
set -euo pipefail
deb=$(realpath "$1")
root=${2:-/tmp/mobius-deb-chroot}
mirror=http://deb.debian.org/debian

if [ ! -x "$root/usr/bin/apt-get" ]; then
  debootstrap --variant=minbase bookworm "$root" "$mirror"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
mounts=(proc sys dev/shm dev/pts)
for m in "${mounts[@]}"; do
  mkdir -p "$root/$m"
  mountpoint -q "$root/$m" || mount --bind "/$m" "$root/$m"
done
cleanup() { for m in dev/pts dev/shm sys proc; do umount "$root/$m" 2>/dev/null || true; done; }
trap cleanup EXIT
cp "$deb" "$root/tmp/"
name=$(basename "$deb")

# Everything below runs inside the chroot with a minimal environment: no PYTHONPATH,
# PV_PLUGIN_PATH or LD_LIBRARY_PATH.
in_chroot() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
  DEBIAN_FRONTEND=noninteractive "$@"; }

in_chroot apt-get update -q
in_chroot apt-get install -y -q --no-install-recommends "./tmp/$name" \
  || in_chroot apt-get install -y -q --no-install-recommends "/tmp/$name"
in_chroot dpkg -L mobius-registration > "$root/tmp/mobius-files.txt"
echo "== installed files"; cat "$root/tmp/mobius-files.txt"

echo "== mobius-register"
in_chroot mobius-register --version
in_chroot mobius-benchmark --version
test -s "$root/usr/share/man/man1/mobius-register.1" && test -s "$root/usr/share/man/man1/mobius-benchmark.1"
in_chroot bash -c 'rm -rf /tmp/demo && mkdir /tmp/demo && cd /tmp/demo && mobius-register --resolution 64 --refine none --quiet --json -o demo > demo.json && test -s demo.vtp && grep -q /usr/share/mobius-registration/meshes/cow.off demo.json'
in_chroot bash -c 'cd /tmp/demo && mobius-register --resolution 64 --quiet --force -o demo && echo "demo (refined) ran"'

echo "== python3"
in_chroot python3 -c '
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
import mobiusregistration
print(mobiusregistration.__file__)
cow = "/usr/share/mobius-registration/meshes/cow.off"
reader = mobiusregistration.vtkSurfaceMeshReader()
reader.SetFileName(cow)
reader.Update()
positions = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())
result = mobiusregistration.register(cow, cow, resolution=64, refine=False)
print(result)
# The target positions carried over are the mapped points.
assert np.abs(result.transfer(positions) - result.mapped_points).max() < 1e-6'

echo "== pvpython: the plugin loaded at start-up, the Python package importable"
in_chroot pvpython --force-offscreen-rendering -c '
from paraview.simple import *
from paraview import servermanager
assert "SphericalConformalMap" in dir(), "the plugin was not loaded at start-up"
conformal = SphericalConformalMap(Input=Sphere(ThetaResolution=24, PhiResolution=12))
conformal.UpdatePipeline()
assert servermanager.Fetch(conformal).GetNumberOfPoints() > 0
import mobiusregistration
print("pvpython: plugin filters present without LoadPlugin; mobiusregistration from", mobiusregistration.__file__)'

echo "== paraview (GUI, under Xvfb): the filters are there at start-up"
in_chroot apt-get install -y -q --no-install-recommends xvfb xauth  # for this check only
cat > "$root/tmp/gui_check.py" <<'PY'
from paraview.simple import *
with open("/tmp/gui_check.txt", "w") as f:
    f.write("SphericalConformalMap" in globals() and "RefineCorrespondence" in globals() and "found" or "missing")
PY
rm -f "$root/tmp/gui_check.txt"
in_chroot xvfb-run -a paraview --script=/tmp/gui_check.py --exit || true
echo "paraview GUI: the plugin's filters $(cat "$root/tmp/gui_check.txt" 2>/dev/null || echo "not checked: the GUI did not run")"
grep -q found "$root/tmp/gui_check.txt"

echo "== apt remove"
in_chroot apt-get remove -y -q mobius-registration
left=0
while read -r path; do
  if [ -e "$root$path" ] && [ ! -d "$root$path" ]; then echo "left behind: $path"; left=1; fi
done < "$root/tmp/mobius-files.txt"
for dir in /usr/bin/plugins /usr/lib/python3/dist-packages/mobiusregistration /usr/share/mobius-registration \
           /usr/include/MobiusRegistration /usr/lib/x86_64-linux-gnu/cmake/MobiusRegistration \
           /usr/lib/x86_64-linux-gnu/paraview-5.11/plugins/MobiusRegistration /usr/share/doc/mobius-registration; do
  if [ -e "$root$dir" ]; then echo "left behind: $dir"; find "$root$dir" | head; left=1; fi
done
in_chroot bash -c 'find / -xdev \( -iname "*mobius*" -o -iname "*MobiusRegistration*" \) -not -path "/tmp/*" -not -path "/var/cache/*" -not -path "/var/lib/dpkg/*" -not -path "/var/lib/apt/*" -not -path "/var/log/*"' | tee "$root/tmp/mobius-left.txt"
[ -s "$root/tmp/mobius-left.txt" ] && left=1
if [ "$left" != 0 ]; then echo "FAILED: files left after apt remove"; exit 1; fi
echo "the .deb installs, works without environment variables and removes cleanly"
