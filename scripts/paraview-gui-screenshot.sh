#!/usr/bin/env bash
# Screenshot of the ParaView GUI (Debian's paraview 5.11) with the FlowSurf plugin, under Xvfb:
# starts `paraview --script=scripts/paraview_gui_screenshot.py` on a virtual screen with the
# plugin auto-loaded through PV_PLUGIN_PATH, waits until the surface is drawn, grabs the whole
# X screen with xwd and writes a downscaled PNG (README: doc/images/paraview_gui.png).
#
# Usage: scripts/paraview-gui-screenshot.sh [OUT.png]
# Environment: FLOWSURF_PLUGIN (FlowSurf.so; default: found under build-paraview),
#   FLOWSURF_GUI_DATA (default /work/shared/data/windAroundBuildings_wss.vtp if present, else a
#   generated sphere), FLOWSURF_GUI_VECTORS / _COLOR / _METHOD (see the .py), GUI_WAIT (seconds
#   to wait before the grab, default 60), GUI_SCREEN (default 1600x1000x24), GUI_WIDTH (PNG
#   width, default 1200), PVPYTHON_PREFIX (default /opt/pvpython: python3-paraview unpacked by
#   bench/paraview/setup.sh; the GUI's Python needs paraview.simple from there).
# Needs: paraview, xvfb, x11-apps (xwd), ffmpeg (xwd to PNG), /usr/bin/python3 with PIL (python3-pil).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
out="${1:-$root/doc/images/paraview_gui.png}"
"$here/apt-install.sh" paraview xvfb xauth x11-apps xdotool python3-pil ffmpeg
plugin="${FLOWSURF_PLUGIN:-$(find "$root/build-paraview" -name FlowSurf.so 2>/dev/null | head -n1 || true)}"
[ -f "$plugin" ] || { echo "FlowSurf.so not found: run scripts/build-paraview-plugin.sh or set FLOWSURF_PLUGIN" >&2; exit 1; }
prefix="${PVPYTHON_PREFIX:-/opt/pvpython}"
[ -d "$prefix/usr/lib/python3/dist-packages/paraview" ] || eval "$("$root/bench/paraview/setup.sh")"
default_data=/work/shared/data/windAroundBuildings_wss.vtp
[ -f "$default_data" ] || default_data=""
export FLOWSURF_GUI_DATA="${FLOWSURF_GUI_DATA-$default_data}"
export PV_PLUGIN_PATH="$(dirname "$plugin")"
export PYTHONPATH="$prefix/usr/lib/python3/dist-packages"
screen="${GUI_SCREEN:-1600x1000x24}"
# The whole screen (no window manager under Xvfb: Qt's -geometry places the main window).
export GUI_GEOMETRY="${GUI_GEOMETRY:-$(cut -dx -f1-2 <<<"$screen")+0+0}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
[ -n "${GUI_KEEP:-}" ] && trap 'echo "kept $tmp" >&2' EXIT
# One shell inside xvfb-run: the GUI in the background, the grab, then the GUI ended by its pid.
# --dr: no user settings (so no saved layout or palette changes the picture).
xvfb-run -a -s "-screen 0 $screen" bash -c '
  paraview -geometry "${GUI_GEOMETRY}" --dr --script="$1" >"$2/paraview.log" 2>&1 &
  pv=$!
  sleep "$3"
  if [ -n "$4" ]; then
    # Widen the left dock (drag the splitter) and type FlowSurf into the Properties search box,
    # so the panel lists the FlowSurf properties; positions are for the default layout (--dr).
    read -r sx sy dx sw sh <<<"$4"
    xdotool mousemove "$sx" "$sy" sleep 0.5 mousedown 1 sleep 0.5 mousemove "$((sx + 20))" "$sy" sleep 0.5 mousemove "$dx" "$sy" sleep 0.5 mouseup 1
    sleep 3
    xdotool mousemove "$sw" "$sh" click 1 type --delay 80 FlowSurf
    sleep "$5"
  fi
  xwd -root -silent >"$2/screen.xwd"
  kill "$pv" 2>/dev/null || true
  wait "$pv" 2>/dev/null || true
' _ "$here/paraview_gui_screenshot.py" "$tmp" "${GUI_WAIT:-60}" "${GUI_CLICKS-296 500 540 140 539}" "${GUI_WAIT_AFTER:-20}"
sed -n '1,40p' "$tmp/paraview.log" >&2
ffmpeg -loglevel error -y -i "$tmp/screen.xwd" "$tmp/screen.png"
mkdir -p "$(dirname "$out")"
/usr/bin/python3 - "$tmp/screen.png" "$out" "${GUI_WIDTH:-1200}" <<'EOF'
import sys
from PIL import Image
src, dst, width = sys.argv[1], sys.argv[2], int(sys.argv[3])
im = Image.open(src).convert('RGB')
im = im.resize((width, round(im.height * width / im.width)), Image.LANCZOS)
if dst.lower().endswith(('.jpg', '.jpeg')):
    im.save(dst, quality=85, optimize=True)
else:
    im = im.quantize(colors=256, method=Image.MEDIANCUT, dither=Image.NONE)
    im.save(dst, optimize=True)
print(dst)
EOF
