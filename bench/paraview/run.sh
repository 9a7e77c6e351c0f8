#!/usr/bin/env bash
# Run the ParaView Surface LIC timing benchmark under Xvfb (GLX, Mesa).
#   bench/paraview/run.sh [surface_lic_bench.py options]
# e.g.
#   bench/paraview/run.sh --triangles 10000,80000 --sizes 512x512 --steps 10,25 \
#       --csv /tmp/pv.csv --images /tmp/pv_images
# Environment: XVFB_SCREEN (default 1920x1080x24), PVPYTHON_PREFIX (see setup.sh),
#   BENCH_NICE (e.g. -10: run the benchmark with that nice value; needs root;
#   use it on a shared machine so that other jobs disturb the timing less).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

eval "$("$HERE/setup.sh")"

SCREEN="${XVFB_SCREEN:-1920x1080x24}"
echo "# xvfb-run -a -s \"-screen 0 $SCREEN\", PYTHONPATH=$PYTHONPATH, python=/usr/bin/python3" >&2
NICE=()
if [ -n "${BENCH_NICE:-}" ]; then NICE=(nice -n "$BENCH_NICE"); fi
exec "${NICE[@]}" xvfb-run -a -s "-screen 0 $SCREEN" \
  env PYTHONPATH="$PYTHONPATH" /usr/bin/python3 "$HERE/surface_lic_bench.py" "$@"
