#!/usr/bin/env bash
# ParaView's start-up failures on an oversubscribed node, without FlowSurf: N pvbatch runs of
# a script that builds the scaling benchmark's sphere (RedistributeDataSet, ExtractSurface),
# shows it with ParaView's Surface representation and renders once; a run whose first render
# does not come within --timeout seconds failed, and its log (with the stacks pvbatch prints
# when it is ended) is kept.
#
#   bench/paraview/startup_hang.sh [--ranks 8] [--runs 10] [--timeout 200] [--plugin FILE]
#                                  [--xvfb-reset] [--out DIR]
#
# Ranks beyond the cores are oversubscribed, one llvmpipe thread each (as scaling.sh's
# stats runs). --plugin loads a plugin first (e.g. FlowSurf.so, to compare); by default none.
# Xvfb runs with -noreset (scripts/xvfb-args.sh), as in the benchmarks and tests;
# --xvfb-reset leaves it out, to count what it prevents: a rank that connects while Xvfb
# resets after another rank's probe window is refused and aborts ("bad X server
# connection"), the others left in a gather.
# Prints each run's outcome (aborted without an X connection, or hung) and the counts.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
RESET=0 RANKS=8 RUNS=10 TIMEOUT=200 PLUGIN=none OUT="$HERE/../../out/startup_hang"
while [ $# -gt 0 ]; do
  case "$1" in
    --ranks) RANKS=$2; shift 2 ;;
    --runs) RUNS=$2; shift 2 ;;
    --timeout) TIMEOUT=$2; shift 2 ;;
    --plugin) PLUGIN=$2; shift 2 ;;
    --xvfb-reset) RESET=1; shift ;;
    --out) OUT=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
eval "$("$HERE/setup.sh")"
. "$HERE/../../scripts/xvfb-args.sh"
XVFB="$FLOWSURF_XVFB_ARGS"
if [ "$RESET" = 1 ]; then XVFB="${XVFB% -noreset}"; fi
mkdir -p "$OUT"
cat >"$OUT/first_render.py" <<'EOF'
import sys
from paraview.simple import *  # noqa: F401,F403
if sys.argv[1] != 'none':
    LoadPlugin(sys.argv[1], ns=globals())
sphere = Sphere(Radius=1.0, ThetaResolution=1000, PhiResolution=500)  # about 1M triangles
spin = Calculator(Input=sphere, ResultArrayName='V', Function='-coordsY*iHat+coordsX*jHat')
split = RedistributeDataSet(Input=spin)
split.BoundaryMode = 'Assign to one region'
surface = ExtractSurface(Input=split)
surface.UpdatePipeline()
print('PIPELINE', flush=True)
view = CreateRenderView()
view.ViewSize = [1024, 1024]
Show(surface, view)
Render(view)
print('FIRST_RENDER', flush=True)
EOF
ROOTOK=()
[ "$(id -u)" -eq 0 ] && ROOTOK=(--allow-run-as-root)
export LP_NUM_THREADS=1
hung=0 nox=0
for i in $(seq 1 "$RUNS"); do
  log="$OUT/run$i.log"
  start=$SECONDS
  setsid xvfb-run -a -n "$((200 + RANDOM % 600))" -s "$XVFB" timeout -k 10 "$TIMEOUT" \
    mpiexec "${ROOTOK[@]}" --bind-to none --oversubscribe --mca mpi_yield_when_idle 1 -x LP_NUM_THREADS -x PYTHONPATH \
    -np "$RANKS" pvbatch --force-offscreen-rendering "$OUT/first_render.py" "$PLUGIN" >"$log" 2>&1 || true
  if grep -q '^FIRST_RENDER' "$log"; then
    echo "run $i: rendered ($((SECONDS - start)) s)"
  elif grep -q 'bad X server connection' "$log"; then
    nox=$((nox + 1))
    echo "run $i: a rank aborted without an X connection: $log"
  else
    hung=$((hung + 1))
    echo "run $i: no first render in $TIMEOUT s ($(grep -q '^PIPELINE' "$log" && echo 'after the pipeline' || echo 'before the pipeline')): $log"
  fi
done
echo "$((hung + nox)) of $RUNS runs failed: $hung hung, $nox without an X connection ($RANKS ranks, plugin: $PLUGIN, Xvfb: $XVFB)"
