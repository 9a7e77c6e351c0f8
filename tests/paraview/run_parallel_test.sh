#!/usr/bin/env bash
# ctest wrapper of parallel_test.py: the FlowSurf representation on ParaView's distributed
# engine. Renders the split sphere under `mpiexec -np 1, 2, 4` pvbatch (and 4 ranks over 2
# pieces, so two ranks hold nothing), then compares each with the 1-rank images (issue 11:
# mean <= 1 gray level over the surface, every 16x16 tile <= 3). A hang (a rank missing a
# collective step) ends at `timeout`.
# Usage: run_parallel_test.sh PLUGIN.so OUTDIR
set -uo pipefail
PLUGIN="$1"
OUT="$2"
HERE="$(cd "$(dirname "$0")" && pwd)"
PREFIX="${PVPYTHON_PREFIX:-/opt/pvpython}"
[ -f "$PLUGIN" ] || { echo "FlowSurf plugin not found: $PLUGIN (build it with scripts/build-paraview-plugin.sh)"; exit 1; }
rm -rf "$OUT" && mkdir -p "$OUT"
export PYTHONPATH="$PREFIX/usr/lib/python3/dist-packages"
# Open MPI as root (CI) and more ranks than cores; shared-memory transport without
# ptrace-based single copy (refused in containers).
MPI=(mpiexec --allow-run-as-root --oversubscribe --mca btl_vader_single_copy_mechanism none)
# xrun LOG CMD...: CMD under xvfb-run with its output in LOG. Tried again, up to 3 times,
# on two failures that are not ours: a display taken by another xvfb-run starting at the
# same moment (pvbatch aborts with "bad X server connection"), and ParaView's own startup
# hang at 4 ranks on 2 cores (rank 0 in IceT's MPI_Comm_dup before the first render, the
# others waiting; seen in 3 of 11 benchmark runs, 2 of 8 of them without the plugin loaded,
# all with `--bind-to none`, which is why it is not used here: 4 of 4 runs clean without it)
# — a run that printed nothing of ours after 150 s. A hang inside our merge would time out
# every attempt and fail the test.
xrun() {
  local log="$1" rc attempt
  shift
  for attempt in 1 2 3; do
    timeout -k 10 150 xvfb-run -a "$@" >"$log" 2>&1
    rc=$?
    if grep -q -e "bad X server connection" -e "Xvfb failed to start" "$log"; then
      echo "no X display (attempt $attempt), again"
    elif [ $rc -eq 124 ] && ! grep -q "^FLOWSURF_STARTED" "$log"; then
      echo "ParaView hung before its first render (attempt $attempt), again"
      pkill -f "pvbatch $HERE/parallel_test.py" 2>/dev/null
    else
      return $rc
    fi
    sleep 2
  done
  return $rc
}
run() {  # TAG PARTITIONS NP
  echo "== $1: $3 rank(s), partitions $2"
  xrun "$OUT/$1.log" "${MPI[@]}" -np "$3" pvbatch "$HERE/parallel_test.py" "$PLUGIN" "$OUT" render "$1" "$2"
  local rc=$?
  grep -E "RENDERED" "$OUT/$1.log"
  [ $rc -eq 0 ] && grep -q "^RENDERED $1" "$OUT/$1.log" || { echo "$1: pvbatch failed ($rc)"; cat "$OUT/$1.log"; exit 1; }
  grep -q "no 3-component point array 'NoSuchArray'" "$OUT/$1.log" || { echo "$1: no error for a missing array"; exit 1; }
}
run np1 0 1
run np2 0 2
run np4 0 4
run np4of2 2 4
xrun "$OUT/compare.log" pvbatch "$HERE/parallel_test.py" "$PLUGIN" "$OUT" compare np1 np2 np4 np4of2
cat "$OUT/compare.log"
grep -q '^PASSED' "$OUT/compare.log"
