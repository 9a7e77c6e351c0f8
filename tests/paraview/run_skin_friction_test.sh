#!/usr/bin/env bash
# ctest wrapper of skin_friction_test.py: the FlowSurf Skin Friction filter under pvbatch on
# the shipped laminar cavity (tests/unit/data/openfoam_cavity_laminar), read by ParaView's own
# OpenFOAM reader. Usage: run_skin_friction_test.sh PLUGIN.so OUTDIR
set -uo pipefail
PLUGIN="$1"
OUT="$2"
HERE="$(cd "$(dirname "$0")" && pwd)"
PREFIX="${PVPYTHON_PREFIX:-/opt/pvpython}"
[ -f "$PLUGIN" ] || { echo "FlowSurf plugin not found: $PLUGIN (build it with scripts/build-paraview-plugin.sh)"; exit 1; }
rm -rf "$OUT" && mkdir -p "$OUT"
export PYTHONPATH="$PREFIX/usr/lib/python3/dist-packages"
. "$HERE/../../scripts/xvfb-args.sh"
CASE="$HERE/../unit/data/openfoam_cavity_laminar/case.foam"
timeout -k 10 150 xvfb-run -a -n "$((200 + RANDOM % 600))" -s "$FLOWSURF_XVFB_ARGS" \
  pvbatch "$HERE/skin_friction_test.py" "$PLUGIN" "$CASE" >"$OUT/skin_friction.log" 2>&1
rc=$?
grep -E "wall faces" "$OUT/skin_friction.log"
[ $rc -eq 0 ] && grep -q '^PASSED' "$OUT/skin_friction.log" || { echo "failed ($rc)"; cat "$OUT/skin_friction.log"; exit 1; }
grep -q "no block with volume cells" "$OUT/skin_friction.log" && grep -q NO_VOLUME_SURVIVED "$OUT/skin_friction.log" ||
  { echo "no ParaView error for an input without volume, or pvbatch stopped"; cat "$OUT/skin_friction.log"; exit 1; }
echo "skin friction: passed"
