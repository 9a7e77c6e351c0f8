#!/usr/bin/env bash
# ctest wrapper of plugin_test.py: pvbatch under xvfb-run with the private python3-paraview
# prefix; passes when the script passes and the missing-array case left ParaView's error
# (the mapper's message through vtkErrorMacro) and pvbatch ran on.
# Usage: run_plugin_test.sh PLUGIN.so OUTDIR
set -uo pipefail
PLUGIN="$1"
OUT="$2"
PREFIX="${PVPYTHON_PREFIX:-/opt/pvpython}"
. "$(dirname "$0")/../../scripts/xvfb-args.sh"
if [ ! -f "$PLUGIN" ]; then
  echo "FlowSurf plugin not found: $PLUGIN (build it with scripts/build-paraview-plugin.sh)"
  exit 1
fi
mkdir -p "$OUT"
log="$OUT/plugin_test.log"
# No X connection (a display taken by another xvfb-run starting at the same moment): only
# that is retried. Xvfb with -noreset (scripts/xvfb-args.sh).
for attempt in 1 2 3; do
  PYTHONPATH="$PREFIX/usr/lib/python3/dist-packages" xvfb-run -a -n "$((200 + RANDOM % 600))" \
    -s "$FLOWSURF_XVFB_ARGS" pvbatch \
    "$(dirname "$0")/plugin_test.py" "$PLUGIN" "$OUT" >"$log" 2>&1
  rc=$?
  grep -q -e "bad X server connection" -e "Xvfb failed to start" "$log" || break
  echo "no X display (attempt $attempt), again"
  sleep 2
done
cat "$log"
[ $rc -eq 0 ] || { echo "pvbatch exited with $rc"; exit 1; }
grep -q "no 3-component point array 'NoSuchArray'" "$log" || { echo "missing array: no ParaView error"; exit 1; }
grep -q MISSING_ARRAY_SURVIVED "$log" || { echo "missing array: pvbatch did not run on"; exit 1; }
# The surface pass: one (the look reproduced) by default, ParaView's with a specular highlight.
grep -q "one surface pass" "$log" || { echo "the one-surface-pass path was never taken"; exit 1; }
grep -q "ParaView's surface pass, then" "$log" || { echo "the fallback surface pass was never taken"; exit 1; }
grep -q '^PASSED' "$log"
