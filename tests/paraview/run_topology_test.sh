#!/usr/bin/env bash
# ctest wrapper of topology_test.py: the FlowSurf Topology filter under pvbatch, serial (known
# answers on spheres, errors) and under `mpiexec -np 1, 2, 4` pvbatch, whose whole outputs
# must equal the 1-rank one (the same critical points within 1e-6 of the extent, the same
# number of lines of each kind), and the representation's overlay (FlowSurfTopology on) over
# the pieces, whose image must equal the 1-rank one up to anti-aliasing at the seams. A hang
# (a rank missing a collective step) ends at `timeout`.
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
# again (up to 3 times) only when there was no X display, or on ParaView's own startup hang
# at 4 ranks on 2 cores (run_parallel_test.sh): a run that timed out before its first render.
xrun() {
  local log="$1" rc attempt
  shift
  for attempt in 1 2 3; do
    timeout -k 10 150 xvfb-run -a -n "$((200 + RANDOM % 600))" -s "$FLOWSURF_XVFB_ARGS" "$@" >"$log" 2>&1
    rc=$?
    if grep -q -e "bad X server connection" -e "Xvfb failed to start" "$log"; then
      echo "no X display (attempt $attempt), again"
    elif [ $rc -eq 124 ] && grep -q "^RESULT" "$log" && ! grep -q "^FLOWSURF_STARTED" "$log"; then
      echo "ParaView hung before its first render (attempt $attempt), again"
    else
      return $rc
    fi
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

# Each run also renders the representation's FlowSurfTopology over the pieces; np4of2: 4
# ranks over 2 pieces, two of them empty.
for run in np1:1:0 np2:2:0 np4:4:0 np4of2:4:2; do
  IFS=: read -r tag np partitions <<<"$run"
  echo "== $tag"
  xrun "$OUT/$tag.log" "${MPI[@]}" -np "$np" pvbatch "$HERE/topology_test.py" "$PLUGIN" "$OUT" parallel "$tag" render "$partitions"
  rc=$?
  grep -E "^RESULT" "$OUT/$tag.log"
  [ $rc -eq 0 ] && grep -q "^DONE $tag" "$OUT/$tag.log" || { echo "$tag: pvbatch failed ($rc)"; cat "$OUT/$tag.log"; exit 1; }
  # Each error on every rank (ParaView prints each rank's), the survivors on rank 0.
  zero=$(grep -c "zero everywhere" "$OUT/$tag.log")
  [ "$zero" -ge "$np" ] || { echo "$tag: the zero-field error on $zero of $np ranks"; cat "$OUT/$tag.log"; exit 1; }
  # (rank 1 holds a piece: with empty ranks it may not)
  if [ "$np" -gt 1 ] && [ "$partitions" = 0 ]; then
    missing=$(grep -c "no 3-component point array 'V'.* (on process 1 of $np)" "$OUT/$tag.log")
    [ "$missing" -ge "$np" ] || { echo "$tag: rank 1's missing array on $missing of $np ranks"; cat "$OUT/$tag.log"; exit 1; }
  fi
  grep -E "^OVERLAY" "$OUT/$tag.log"
  # The representation's one error: the overlay's analysis of a zero field, on every rank.
  mapper=$(grep -c "vtkFlowSurfMapper.*ERR|" "$OUT/$tag.log")
  overlayZero=$(grep -c "vtkFlowSurfMapper.*ERR|.*FlowSurf input, field 'V': .*zero everywhere" "$OUT/$tag.log")
  echo "$tag: the overlay's zero-field error on $overlayZero of $np ranks, $mapper representation error(s) in all"
  [ "$overlayZero" -ge "$np" ] && [ "$mapper" -eq "$overlayZero" ] && grep -q "^SURVIVED overlay zero" "$OUT/$tag.log" &&
    grep -q "^SURVIVED overlay$" "$OUT/$tag.log" ||
    { echo "$tag: FlowSurfTopology's errors not every rank's, another error, or ParaView stopped"; cat "$OUT/$tag.log"; exit 1; }
done
python3 "$HERE/topology_test.py" "$PLUGIN" "$OUT" compare np1 np2 np4 np4of2 || exit 1
# Under pvbatch, whose Python has numpy.
xrun "$OUT/overlay.log" pvbatch "$HERE/topology_test.py" "$PLUGIN" "$OUT" overlay np1 np2 np4 np4of2
rc=$?
cat "$OUT/overlay.log"
[ $rc -eq 0 ] && grep -q '^PASSED' "$OUT/overlay.log"
