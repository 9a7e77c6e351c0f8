#!/usr/bin/env bash
# The work the tiled parallel mode adds, counted without the machine: the instructions each
# rank executes per frame inside renderFrame, for `flowsurf bench --ranks N --parallel tiles`
# (threads as ranks, one GL context and a slab of the sphere each), under valgrind's
# callgrind, which runs one thread at a time: no rank shares a core or a cache with another
# while it counts, so the sums say what the split costs in work, whatever the cores. llvmpipe
# rasterises in the calling thread (LP_NUM_THREADS=0), so its work is the rank's.
# Per frame: the difference of a run of --frames-b and one of --frames-a frames (the warm-up,
# shader compilation included, cancels), divided by the difference.
#
#   bench/parallel_work.sh [--methods isa,hybrid,ibfvs] [--ranks 1,4,8] [--triangles 1000000]
#       [--size 1024x1024] [--frames-a 2] [--frames-b 6] [--out DIR]
#
# Prints, per method and rank count: Σ instructions per frame, that over 1 rank's, the
# busiest rank over the mean, and LLVM's instructions per frame (shader compilation: ~0 when
# the two runs compiled alike, as they must for the difference to mean one frame); then, per
# method, the functions whose instructions grew most at the most ranks (what the split adds,
# and where: parallel_work.py). Instructions are not time (a cache miss costs more than an
# add): compare with the CPU sums of bench/paraview/scaling.sh's oversubscribed runs to see
# what the cores' sharing adds. About 2-5 minutes per run at 1M triangles; 18 runs by default.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/.." && pwd)"
METHODS=isa,hybrid,ibfvs RANKS=1,4,8 TRIANGLES=1000000 SIZE=1024x1024 FA=2 FB=6 OUT="$ROOT/out/parallel_work"
while [ $# -gt 0 ]; do
  case "$1" in
    --methods) METHODS=$2; shift 2 ;;
    --ranks) RANKS=$2; shift 2 ;;
    --triangles) TRIANGLES=$2; shift 2 ;;
    --size) SIZE=$2; shift 2 ;;
    --frames-a) FA=$2; shift 2 ;;
    --frames-b) FB=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
[ "$FB" -gt "$FA" ] || { echo "--frames-b must exceed --frames-a" >&2; exit 2; }
"$ROOT/scripts/apt-install.sh" valgrind
FLOWSURF="${FLOWSURF_BIN:-$ROOT/build/apps/flowsurf}"
[ -x "$FLOWSURF" ] || { echo "flowsurf not found: scripts/build.sh, or set FLOWSURF_BIN" >&2; exit 1; }
mkdir -p "$OUT"
git -C "$ROOT" log -1 --format='commit: %h %s' >"$OUT/info.txt" 2>/dev/null || true
# llvmpipe keeps the shaders it compiles on disk: a run that compiles them (the first) counts
# that work, a later one does not, and the difference would hold it. So each configuration
# runs once first under valgrind (its CPU features pick the shader variants) to fill the cache.
for m in ${METHODS//,/ }; do
  for n in ${RANKS//,/ }; do
    echo "== $m, $n ranks: shader cache ($(date +%T))" >&2
    LP_NUM_THREADS=0 valgrind --tool=none --smc-check=all-non-file "$FLOWSURF" bench --methods "$m" \
      --triangles "$TRIANGLES" --sizes "$SIZE" --grids 256 --lengths 31 --dynamic-only --frames 1 --no-stage-times \
      --ranks "$n" --parallel tiles >"$OUT/$m.n$n.warm.log" 2>&1 || { echo "failed: see $OUT/$m.n$n.warm.log" >&2; exit 1; }
    for f in "$FA" "$FB"; do
      out="$OUT/$m.n$n.f$f"
      rm -f "$out".cg*
      echo "== $m, $n ranks, $f frames ($(date +%T))" >&2
      LP_NUM_THREADS=0 valgrind --tool=callgrind --smc-check=all-non-file --collect-atstart=no \
        "--toggle-collect=*Renderer::renderFrame*" --separate-threads=yes --callgrind-out-file="$out.cg" \
        "$FLOWSURF" bench --methods "$m" --triangles "$TRIANGLES" --sizes "$SIZE" --grids 256 --lengths 31 \
        --dynamic-only --frames "$f" --no-stage-times --ranks "$n" --parallel tiles >"$out.log" 2>&1 ||
        { echo "failed: see $out.log" >&2; exit 1; }
    done
  done
done
/usr/bin/python3 "$HERE/parallel_work.py" "$OUT" "$FA" "$FB" | tee "$OUT/results.md"
