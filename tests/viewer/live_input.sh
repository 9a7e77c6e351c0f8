#!/bin/bash
# Real X input into the real GLFW window (run under xvfb-run): xdotool drags, presses m
# (next method) and p (screenshot), then q. Usage: live_input.sh FLOWSURF WORKDIR
F=$1
cd "$2" || exit 1
"$F" view builtin:tori --size 640x480 --record-events live.log -q -o live.png 2> err.txt &
PID=$!
WID=$(timeout 20 xdotool search --sync --name "flowsurf view" | head -1)
[ -n "$WID" ] || { kill $PID; echo "no viewer window"; exit 1; }
sleep 1
xdotool mousemove --window "$WID" 450 240; sleep 0.3
xdotool mousedown 1; sleep 0.2
for x in 470 490 510 530 550; do xdotool mousemove --window "$WID" $x 240; sleep 0.15; done
xdotool mouseup 1; sleep 0.3
xdotool key --window "$WID" m; sleep 0.5
xdotool key --window "$WID" p; sleep 0.5
xdotool key --window "$WID" q
timeout 20 tail --pid=$PID -f /dev/null
wait $PID
