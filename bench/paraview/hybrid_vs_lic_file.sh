#!/usr/bin/env bash
# flowsurf's hybrid LIC against ParaView's Surface LIC on a surface file, at equal samples
# (L = 2 S + 1, 2 px per step), same image size and camera (flowsurf's default view, handed
# to VTK), both animating (0.5 degrees of orbit per frame), interleaved: R rounds of
# [flowsurf K frames, Surface LIC K frames], so that load on a shared machine hits both.
# Prints each round's ratio (Surface LIC ms / hybrid ms) and their median: a round's two
# timings see the same load, so the per-round ratio is steadier than a ratio of medians.
# Also the ratio of CPU time per frame (all threads of each process, the software
# rasteriser's included): on a shared, loaded machine wall times swing with the other
# jobs, CPU time far less.
#
#   bench/paraview/hybrid_vs_lic_file.sh [FILE FIELD] [--size 512x512] [--steps 40]
#       [--frames 5] [--rounds 5] [--gl-path auto|compute|fragment]
# Default FILE FIELD: ../shared/data/windAroundBuildings_wss.vtp wallShearStress.
# Needs build/python (cmake --build build --target flowsurf_python) and setup.sh's ParaView.
# Environment: BENCH_NICE (e.g. -10, as run.sh); FLOWSURF_PYTHON (default build/python: the
# folder holding the flowsurf module).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
FILE="$ROOT/../shared/data/windAroundBuildings_wss.vtp"
FIELD=wallShearStress
if [ $# -ge 2 ] && [ "${1#--}" = "$1" ]; then FILE=$1; FIELD=$2; shift 2; fi
SIZE=512x512 STEPS=40 FRAMES=5 ROUNDS=5 GLPATH=auto
while [ $# -gt 0 ]; do
  case "$1" in
    --size) SIZE=$2; shift 2 ;;
    --steps) STEPS=$2; shift 2 ;;
    --frames) FRAMES=$2; shift 2 ;;
    --rounds) ROUNDS=$2; shift 2 ;;
    --gl-path) GLPATH=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
[ -f "$FILE" ] || { echo "no surface file $FILE" >&2; exit 1; }
PYDIR="${FLOWSURF_PYTHON:-$ROOT/build/python}"
[ -d "$PYDIR/flowsurf" ] || { echo "no flowsurf module in $PYDIR: build target flowsurf_python" >&2; exit 1; }
L=$((2 * STEPS + 1))
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
NICE=()
if [ -n "${BENCH_NICE:-}" ]; then NICE=(nice -n "$BENCH_NICE"); fi
echo "# $FILE ($FIELD), $SIZE, hybrid L = $L vs Surface LIC S = $STEPS; $FRAMES frames x $ROUNDS rounds;" \
     "$(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), commit" \
     "$(git -C "$ROOT" rev-parse --short HEAD), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "round,hybrid_ms,hybrid_tracing_ms,lic_ms,ratio,hybrid_cpu_ms,lic_cpu_ms,cpu_ratio"
for r in $(seq "$ROUNDS"); do
  h=$(PYTHONPATH="$PYDIR" "${NICE[@]}" /usr/bin/python3 "$HERE/hybrid_file_bench.py" "$FILE" \
        --field "$FIELD" --size "$SIZE" --length "$L" --frames "$FRAMES" --gl-path "$GLPATH" \
        --camera-json "$OUT/camera.json")
  "$HERE/run.sh" --mesh "$FILE" --field "$FIELD" --camera-json "$OUT/camera.json" --sizes "$SIZE" \
    --steps "$STEPS" --frames "$FRAMES" --quiet-vtk --csv "$OUT/lic.csv" >/dev/null 2>&1
  lic=$(tail -n1 "$OUT/lic.csv" | cut -d, -f5 | tr -d '\r')  # the csv module ends rows with CR LF
  licCpu=$(tail -n1 "$OUT/lic.csv" | cut -d, -f6 | tr -d '\r')
  hm=$(echo "$h" | cut -d, -f2) ht=$(echo "$h" | cut -d, -f4) hc=$(echo "$h" | cut -d, -f5)
  echo "$r,$hm,$ht,$lic,$(awk -v a="$lic" -v b="$hm" 'BEGIN{printf "%.2f", a/b}'),$hc,$licCpu,$(awk -v a="$licCpu" -v b="$hc" 'BEGIN{printf "%.2f", a/b}')" \
    | tee -a "$OUT/rounds.csv"
done
LOAD="$(cut -d' ' -f1-3 /proc/loadavg)" /usr/bin/python3 - "$OUT/rounds.csv" <<'PY'
import os, statistics as st, sys
rows = [[float(v) for v in line.split(",")] for line in open(sys.argv[1])]
h, t, l, hc, lc = (st.median(r[i] for r in rows) for i in (1, 2, 3, 5, 6))
print("# median: hybrid %.1f ms (tracing %.1f), Surface LIC %.1f ms; ratio (median of the rounds') %.2f; load %s"
      % (h, t, l, st.median(r[3] / r[1] for r in rows), os.environ["LOAD"]))
print("# CPU per frame (all threads): hybrid %.1f ms, Surface LIC %.1f ms; ratio (median of the rounds') %.2f"
      % (hc, lc, st.median(r[6] / r[5] for r in rows)))
PY
