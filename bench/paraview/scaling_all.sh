#!/usr/bin/env bash
# Every strong-scaling figure of docs/parallel.md in one run, one plugin build, one machine
# session: scaling.sh at 1M triangles with the oversubscribed 4- and 8-rank counts, then at
# 10M, into OUT/1M and OUT/10M, and both reports in OUT/results.md.
#
#   bench/paraview/scaling_all.sh [--out DIR] [--rounds-1m 5] [--rounds-10m 3] [--stats-rounds 3]
#       [--methods hybrid,isa,ibfvs]
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
OUT="$ROOT/out/paraview_scaling_all"
ROUNDS_1M=5
ROUNDS_10M=3
STATS_ROUNDS=3
METHODS=hybrid,isa,ibfvs
while [ $# -gt 0 ]; do
  case "$1" in
    --out) OUT=$2; shift 2 ;;
    --rounds-1m) ROUNDS_1M=$2; shift 2 ;;
    --rounds-10m) ROUNDS_10M=$2; shift 2 ;;
    --stats-rounds) STATS_ROUNDS=$2; shift 2 ;;
    --methods) METHODS=$2; shift 2 ;;
    *) echo "scaling_all.sh: unknown argument '$1' (see the header for the options)" >&2; exit 2 ;;
  esac
done
mkdir -p "$OUT"
# The plugin is copied once: both sizes run the same build even if the tree is rebuilt meanwhile.
PLUGIN="${FLOWSURF_PLUGIN:-$(find "$ROOT/build-paraview" -name FlowSurf.so 2>/dev/null | head -n1 || true)}"
[ -f "$PLUGIN" ] || { echo "FlowSurf.so not found: scripts/build-paraview-plugin.sh, or set FLOWSURF_PLUGIN" >&2; exit 1; }
cp "$PLUGIN" "$OUT/FlowSurf.so"
export FLOWSURF_PLUGIN="$OUT/FlowSurf.so"
date -u +'start: %F %T UTC' >"$OUT/when.txt"
"$HERE/scaling.sh" --triangles 1000000 --size 1024x1024 --rounds "$ROUNDS_1M" --frames 9 --fxaa off \
  --methods "$METHODS" --ranks-stats 4,8 --stats-rounds "$STATS_ROUNDS" --out "$OUT/1M"
"$HERE/scaling.sh" --triangles 10000000 --size 1024x1024 --rounds "$ROUNDS_10M" --frames 5 --fxaa off \
  --methods "$METHODS" --out "$OUT/10M"
date -u +'end: %F %T UTC' >>"$OUT/when.txt"
{
  cat "$OUT/when.txt"
  echo
  echo "# 1M triangles, 1024², 9 frames"
  cat "$OUT/1M/results.md"
  echo
  echo "# 10M triangles, 1024², 5 frames"
  cat "$OUT/10M/results.md"
} >"$OUT/results.md"
echo "results: $OUT/results.md" >&2
