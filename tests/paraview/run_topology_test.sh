#!/usr/bin/env bash
# ctest wrapper of topology_test.py: the FlowSurf Topology filter under pvbatch, serial (known
# answers on spheres, errors) and under `mpiexec -np 1, 2, 4` pvbatch, whose whole outputs
# must equal the 1-rank one (the same critical points within 1e-6 of the extent, the same
# number of lines of each kind). A hang (a rank missing a collective step) ends at `timeout`.
# Usage: run_topology_test.sh PLUGIN.so OUTDIR
set -uo pipefail
PLUGIN="$1"
OUT="$2"
HERE="$(cd "$(dirname "$0")" && pwd)"
PREFIX="${PVPYTHON_PREFIX:-/opt/pvpython}"
[ -f "$PLUGIN" ] || { echo "FlowSurf plugin not found: $PLUGIN (build it with scripts/build-paraview-plugin.sh)"; exit 1; }
rm -rf "$OUT" && mkdir -p "$OUT"
export PYTHONPATH="$PREFIX/usr/lib/python3/dist-packages"
# As run_parallel_test.sh: Open MPI as root and more ranks than cores, no ptrace single copy.
MPI=(mpiexec --allow-run-as-root --oversubscribe --mca btl_vader_single_copy_mechanism none)
. "$HERE/../../scripts/xvfb-args.sh"
# xrun LOG CMD...: CMD under xvfb-run on a display drawn at random, its output in LOG; tried
# again (up to 3 times) only when there was no X display.
xrun() {
  local log="$1" rc attempt
  shift
  for attempt in 1 2 3; do
    timeout -k 10 150 xvfb-run -a -n "$((200 + RANDOM % 600))" -s "$FLOWSURF_XVFB_ARGS" "$@" >"$log" 2>&1
    rc=$?
    grep -q -e "bad X server connection" -e "Xvfb failed to start" "$log" || return $rc
    echo "no X display (attempt $attempt), again"
    sleep 2
  done
  return $rc
}

echo "== serial"
xrun "$OUT/serial.log" pvbatch "$HERE/topology_test.py" "$PLUGIN" "$OUT" serial
rc=$?
grep -E "points|lines" "$OUT/serial.log"
[ $rc -eq 0 ] && grep -q '^PASSED' "$OUT/serial.log" || { echo "serial: failed ($rc)"; cat "$OUT/serial.log"; exit 1; }
grep -q "no 3-component point array 'NoSuchArray'" "$OUT/serial.log" && grep -q MISSING_ARRAY_SURVIVED "$OUT/serial.log" ||
  { echo "serial: no ParaView error for a missing array, or pvbatch stopped"; cat "$OUT/serial.log"; exit 1; }
grep -q "zero everywhere" "$OUT/serial.log" && grep -q ZERO_FIELD_SURVIVED "$OUT/serial.log" ||
  { echo "serial: no ParaView error for a zero field, or pvbatch stopped"; cat "$OUT/serial.log"; exit 1; }
grep "^overlay" "$OUT/serial.log"

# At 2 ranks also the representation's FlowSurfTopology, refused under MPI (rendering at 4
# ranks on 2 cores meets ParaView's own startup hang now and then: run_parallel_test.sh).
for np in 1 2 4; do
  echo "== np$np"
  render=$([ "$np" = 2 ] && echo render)
  xrun "$OUT/np$np.log" "${MPI[@]}" -np "$np" pvbatch "$HERE/topology_test.py" "$PLUGIN" "$OUT" parallel "np$np" $render
  rc=$?
  grep -E "^RESULT" "$OUT/np$np.log"
  [ $rc -eq 0 ] && grep -q "^DONE np$np" "$OUT/np$np.log" || { echo "np$np: pvbatch failed ($rc)"; cat "$OUT/np$np.log"; exit 1; }
  # Each error on every rank (ParaView prints each rank's), the survivors on rank 0.
  zero=$(grep -c "zero everywhere" "$OUT/np$np.log")
  [ "$zero" -ge "$np" ] || { echo "np$np: the zero-field error on $zero of $np ranks"; cat "$OUT/np$np.log"; exit 1; }
  if [ "$np" -gt 1 ]; then
    missing=$(grep -c "no 3-component point array 'V'.* (on process 1 of $np)" "$OUT/np$np.log")
    [ "$missing" -ge "$np" ] || { echo "np$np: rank 1's missing array on $missing of $np ranks"; cat "$OUT/np$np.log"; exit 1; }
  fi
  if [ -n "$render" ]; then
    refused=$(grep -c "FlowSurfTopology is not available under MPI" "$OUT/np$np.log")
    [ "$refused" -ge "$np" ] && grep -q "^SURVIVED overlay" "$OUT/np$np.log" ||
      { echo "np$np: FlowSurfTopology refused on $refused of $np ranks, or ParaView stopped"; cat "$OUT/np$np.log"; exit 1; }
  fi
done
python3 "$HERE/topology_test.py" "$PLUGIN" "$OUT" compare np1 np2 np4
