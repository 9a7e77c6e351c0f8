#!/bin/bash
# A real ctrl + click into the real GLFW window (run under xvfb-run): dye dropped on the
# sphere right of the panel, a few frames, then q. Usage: dye_click.sh FLOWSURF WORKDIR
F=$1
cd "$2" || exit 1
"$F" view builtin:sphere --size 640x480 --record-events dye.log -q 2> err.txt &
PID=$!
WID=$(timeout 20 xdotool search --sync --name "flowsurf view" | head -1)
[ -n "$WID" ] || { kill $PID; echo "no viewer window"; exit 1; }
sleep 3
# The view is the window's right 640 pixels (the panel is beside it): 100 px right of its centre.
W=$(xdotool getwindowgeometry --shell "$WID" | sed -n 's/^WIDTH=//p')
xdotool mousemove --window "$WID" $((W - 220)) 220; sleep 0.3
xdotool keydown ctrl; sleep 0.2
xdotool click 1; sleep 0.2
xdotool keyup ctrl; sleep 2
xdotool key --window "$WID" q
timeout 20 tail --pid=$PID -f /dev/null
wait $PID
