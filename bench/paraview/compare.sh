#!/usr/bin/env bash
# flowsurf's hybrid LIC against ParaView's Surface LIC, in one run, on the same meshes
# (UV spheres in solid-body rotation), image sizes, camera framing (ParaView's
# ResetCamera) and streak length: ParaView integrates S steps each way at 2 px per step;
# flowsurf's filter length L = 2 S + 1 samples at 2 px per step. Both are timed while
# animating (the LIC recomputed every frame). Prints the joined table with the ratio.
#
#   bench/paraview/compare.sh [--triangles 10000,1000000] [--sizes 512x512] [--steps 25,50] [--frames 3]
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TRIS=  # default: flowsurf bench's mesh sizes
SIZES=512x512,1024x1024,1920x1080
STEPS=10,25,50,100
FRAMES=3
OUT="${OUT:-$ROOT/out/paraview_compare}"
while [ $# -gt 0 ]; do
  case "$1" in
    --triangles) TRIS=$2; shift 2 ;;
    --sizes) SIZES=$2; shift 2 ;;
    --steps) STEPS=$2; shift 2 ;;
    --frames) FRAMES=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
mkdir -p "$OUT"
LENGTHS=$(echo "$STEPS" | tr ',' '\n' | awk '{printf "%s%d", (NR>1?",":""), 2*$1+1}')
FLOWSURF="$ROOT/build/apps/flowsurf"
[ -x "$FLOWSURF" ] || { echo "build flowsurf first (scripts/build.sh)" >&2; exit 1; }
[ -n "$TRIS" ] || TRIS=$("$FLOWSURF" bench --help | sed 's/.*--triangles [^=]*=\[\([0-9,]*\)\].*/\1/;t;d')

echo "# flowsurf hybrid, L = $LENGTHS" >&2
"$FLOWSURF" bench --methods hybrid --lengths "$LENGTHS" --triangles "$TRIS" --sizes "$SIZES" \
  --dynamic-only --camera paraview --frames "$FRAMES" --csv "$OUT/flowsurf.csv" >&2
echo "# ParaView Surface LIC, steps = $STEPS" >&2
"$HERE/run.sh" --triangles "$TRIS" --sizes "$SIZES" --steps "$STEPS" --frames "$FRAMES" \
  --csv "$OUT/paraview.csv" --images "$OUT/images" >&2
/usr/bin/python3 "$HERE/join_results.py" "$OUT/flowsurf.csv" "$OUT/paraview.csv" | tee "$OUT/ratio.md"
