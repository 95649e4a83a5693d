#!/bin/bash
# A screenshot of the real ParaView GUI after the macro, for the README and docs/paraview.md:
#   Examples/ParaView/gui_screenshot.sh BUILD SOURCE_MESH TARGET_MESH OUTPUT.png
# Starts its own Xvfb (display :77 unless MOBIUS_GUI_DISPLAY is set) and a ParaView with a
# private settings folder (a HOME of its own: no welcome dialog, nothing written to the user's settings), runs
# the macro through gui_screenshot.py, grabs the screen with ImageMagick's `import` and stops
# both. Needs the packages xvfb and imagemagick. With
# MOBIUS_GUI_SCRIPT=Examples/ParaView/gui_screenshot_landmarks.py it picks landmarks with the
# Add Landmark Pair macro instead (docs/paraview.md's Landmarks picture).
set -euo pipefail
build="$1" source_mesh="$2" target_mesh="$3" output="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
display="${MOBIUS_GUI_DISPLAY:-:77}"
work="$(mktemp -d)"
# ParaView keeps its Qt settings in $HOME/.config/ParaView/ParaView<version>.ini.
mkdir -p "$work/home/.config/ParaView"
# The Output Messages window stays closed when messages come (the macros print theirs there).
printf '[General]\nGeneralSettings.ShowWelcomeDialog=false\nOutputMessages.AlwaysOpenForNewMessages=false\n' \
  > "$work/home/.config/ParaView/ParaView5.11.0.ini"
Xvfb "$display" -screen 0 1600x1000x24 -noreset > "$work/xvfb.log" 2>&1 &
xvfb=$!
paraview_pid=""
cleanup() {
  [ -n "$paraview_pid" ] && kill "$paraview_pid" 2> /dev/null || true
  kill "$xvfb" 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
sleep 2
DISPLAY="$display" HOME="$work/home" \
  MOBIUS_PLUGIN="$build/lib/paraview-5.11/plugins/MobiusRegistration/MobiusRegistration.so" \
  MOBIUS_SOURCE="$source_mesh" MOBIUS_TARGET="$target_mesh" \
  MOBIUS_MACRO="$here/MobiusRegistrationPipeline.py" MOBIUS_LANDMARK_MACRO="$here/AddLandmarkPair.py" \
  MOBIUS_DONE="$work/done" \
  paraview -geometry 1600x1000+0+0 --script="${MOBIUS_GUI_SCRIPT:-$here/gui_screenshot.py}" > "$work/paraview.log" 2>&1 &
paraview_pid=$!
for _ in $(seq 1 300); do
  [ -f "$work/done" ] && break
  if ! kill -0 "$paraview_pid" 2> /dev/null; then
    cat "$work/paraview.log" >&2
    echo "gui_screenshot: ParaView ended before the views were drawn" >&2
    exit 1
  fi
  sleep 1
done
[ -f "$work/done" ] || { echo "gui_screenshot: no views after 300 s" >&2; cat "$work/paraview.log" >&2; exit 1; }
sleep 5  # let Qt paint the new layout
DISPLAY="$display" import -window root "$output"
echo "gui_screenshot: wrote $output"
