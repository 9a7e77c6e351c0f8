#!/usr/bin/env bash
# The whole GPU session in one command, for a lent machine with nothing but the NVIDIA
# driver (device tool: carry a folder holding the portable tarball and glvnd's loader
# debs, see run.sh). Fails within seconds when no GL device is found, so a second try
# still fits the lease. Writes into OUT (default $OUT, else ./gpu-lease):
#   info.txt       machine, GPU, driver, GL renderer
#   transfers.txt  host read-back / upload per layer format (flowsurf bench --transfers)
#   t1.txt         the one-process frame of the parallel benchmark's cases (docs/parallel.md)
#   ranks.txt      those cases with 2 ranks sharing the GPU (flowsurf bench --ranks)
#   grid/          bench/gpu/run.sh's grid (bench.txt streamed row by row, bench.csv at the end)
#   bench/gpu/lease.sh CARRIED_DIR [GRID_SECONDS]
set -uo pipefail
DIR=${1:?usage: bench/gpu/lease.sh CARRIED_DIR [GRID_SECONDS]}
GRID_SECONDS=${2:-330}
OUT=${OUT:-$PWD/gpu-lease}
mkdir -p "$OUT"
. "$(dirname "$0")/prepare.sh"
F=$TREE/bin/flowsurf
{
  date -u '+%Y-%m-%d %H:%M UTC'
  nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv,noheader
  echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2), $(nproc) CPUs; kernel $(uname -r)"
  echo "EGL vendor file: ${__EGL_VENDOR_LIBRARY_FILENAMES:-none}"
  "$F" --version
} 2>&1 | tee "$OUT/info.txt"
# 1. The host transfers; also the check that a GL device works at all.
if ! timeout 60 "$F" bench --transfers --sizes 1024x1024,1920x1080,3840x2160 --frames 20 \
     >"$OUT/transfers.txt" 2>&1; then
  cat "$OUT/transfers.txt"; echo "lease: no working GL device, stopping"; exit 3
fi
cat "$OUT/transfers.txt"
# 2. T(1): the parallel benchmark's cases (hybrid L=31, ISA R=256, IBFVS), camera orbiting.
timeout 120 "$F" bench --methods isa,ibfvs,hybrid --triangles 1000000,10000000 \
  --sizes 1024x1024,1920x1080 --lengths 31 --grids 256 --dynamic-only --frames 20 2>&1 | tee "$OUT/t1.txt"
# 2b. The tiled mode's exchange with ranks sharing this GPU (threads, one context each).
timeout 90 "$F" bench --methods isa,ibfvs,hybrid --triangles 1000000 --sizes 1024x1024,1920x1080 --lengths 31 \
  --grids 256 --dynamic-only --frames 10 --ranks 1,2 2>&1 | tee "$OUT/ranks.txt"
# 3. The grid, bounded in time, the large meshes first: rows stream into grid/bench.txt.
FLOWSURF_BENCH_TRIANGLES=${FLOWSURF_BENCH_TRIANGLES:-1000000 10000000 100000 10000} \
  FLOWSURF_BENCH_FRAMES=${FLOWSURF_BENCH_FRAMES:-10} timeout "$GRID_SECONDS" \
  bash "$(dirname "$0")/run.sh" "$TREE" "$OUT/grid" >/dev/null 2>"$OUT/grid-stderr.txt"
status=$?
pkill -f "$TREE/bin/flowsurf bench" 2>/dev/null
echo "grid exit $status ($(grep -c dynamic "$OUT/grid/bench.txt" 2>/dev/null) dynamic rows)"
tail -5 "$OUT/grid/bench.txt"
