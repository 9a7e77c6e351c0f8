#!/usr/bin/env bash
# Viewer benchmark (not a test): frame times of `flowsurf view` in a real window under
# Xvfb while a replayed drag orbits the camera, beside the batch `render` ms/frame of the
# same camera motion. Prints a table: median and 95th percentile frame time per method,
# and their ratio to the batch render (what the window, panel and swap add).
#   bench/viewer/run.sh [INPUT] [FIELD] [SIZE] [FRAMES]
set -euo pipefail
cd "$(dirname "$0")/../.."
F=${FLOWSURF:-build/apps/flowsurf}
INPUT=${1:-../shared/data/windAroundBuildings_wss.vtp}
FIELD=${2:-wallShearStress}
SIZE=${3:-800x600}
FRAMES=${4:-120}
STEP_PX=4  # drag per frame: 4 px = 1 degree of turntable rotation (0.25 deg/px)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
W=${SIZE%x*}
H=${SIZE#*x}

# The drag: press at the centre, move STEP_PX to the right every frame, release, quit.
log="$WORK/orbit.log"
{
    echo "# flowsurf events 1"
    echo "at 0 mouse-move $((W / 4)) $((H / 2))"
    echo "at 0 mouse-down left"
    for ((k = 1; k <= FRAMES; k++)); do echo "at $k mouse-move $((W / 4 + k * STEP_PX)) $((H / 2))"; done
    echo "at $FRAMES mouse-up left"
    echo "at $FRAMES quit"
} > "$log"

printf "%-8s %10s %10s %12s %10s\n" method "median ms" "p95 ms" "batch ms" "ratio"
for method in isa ibfvs hybrid; do
    xvfb-run -a -s "-screen 0 $((W + 64))x$((H + 64))x24" "$F" view "$INPUT" --field "$FIELD" --size "$SIZE" \
        --method "$method" --play "$log" --stats "$WORK/$method.json" -q
    # Batch: the same camera motion is an orbit of -1 degree per frame; the cost of
    # loading is removed by timing 0 and FRAMES frames.
    t() {
        local s e
        s=$(date +%s.%N)
        "$F" render "$INPUT" --field "$FIELD" --size "$SIZE" --method "$method" --orbit -1 --frames "$1" -q \
            -o "$WORK/batch.png"
        e=$(date +%s.%N)
        echo "$s $e" | awk '{print $2 - $1}'
    }
    t0=$(t 0)
    t1=$(t "$FRAMES")
    python3 - "$WORK/$method.json" "$t0" "$t1" "$FRAMES" "$method" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
t0, t1, frames, method = float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
ms = sorted(stats["frame_ms"][5:])  # the first frames build programs and caches
median = ms[len(ms) // 2]
p95 = ms[min(len(ms) - 1, int(round(0.95 * (len(ms) - 1))))]
batch = 1000.0 * (t1 - t0) / frames
print(f"{method:8s} {median:10.1f} {p95:10.1f} {batch:12.1f} {median / batch:10.2f}")
PY
done
echo "renderer: $(python3 -c "import json,sys; print(json.load(open('$WORK/isa.json'))['renderer'])")"
