#!/usr/bin/env bash
# GPU benchmark (not a test), for a machine that has nothing but a GL driver with EGL: runs
# the portable tarball's `flowsurf bench` over the grid below and prints the machine, the GL
# renderer and driver, then the table and the CSV. Results also go to OUT (default
# ./flowsurf-gpu-bench-<host>/: info.txt, bench.txt, bench.csv).
#   bench/gpu/run.sh TARBALL|UNPACKED_DIR [OUT]
#   FLOWSURF_BENCH_QUICK=1   a small grid (a smoke run: minutes on llvmpipe)
#   FLOWSURF_BENCH_FRAMES=N  timed frames per row (default 20)
#   FLOWSURF_BENCH_TRIANGLES="10000 100000", FLOWSURF_BENCH_SIZES="512x512"   a part of the grid
#   FLOWSURF_GLVND=DIR       glvnd's loaders (libEGL.so.1, libOpenGL.so.0, libGLdispatch.so.0),
#                            brought along for a machine whose driver came without them
# Needs only bash, tar (with xz, or python3 to unpack) and coreutils besides the driver.
set -euo pipefail
SRC=${1:?usage: bench/gpu/run.sh TARBALL|UNPACKED_DIR [OUT]}
OUT=${2:-$PWD/flowsurf-gpu-bench-$(hostname -s 2>/dev/null || echo host)}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# The grid: the three methods, static and dynamic, 10k to 10M triangles, 512² to 4K,
# hybrid filter lengths L = 21/51/81/101, ISA advection grids R = 256/512/1024.
METHODS=isa,ibfvs,hybrid
TRIANGLES=(10000 100000 1000000 10000000)
SIZES=(512x512 1920x1080 3840x2160)
LENGTHS=(21 51 81 101)
GRIDS=(256 512 1024)
FRAMES=${FLOWSURF_BENCH_FRAMES:-20}
# A part of the grid (e.g. one size per run, to fit a time limit): space-separated lists.
[ -n "${FLOWSURF_BENCH_TRIANGLES:-}" ] && read -ra TRIANGLES <<<"$FLOWSURF_BENCH_TRIANGLES"
[ -n "${FLOWSURF_BENCH_SIZES:-}" ] && read -ra SIZES <<<"$FLOWSURF_BENCH_SIZES"
if [ "${FLOWSURF_BENCH_QUICK:-0}" = 1 ]; then
  TRIANGLES=(10000 100000)
  SIZES=(256x256 512x512)
  LENGTHS=(21)
  GRIDS=(128)
  FRAMES=${FLOWSURF_BENCH_FRAMES:-3}
fi

# 1. The tree: an unpacked folder, or the tarball unpacked here.
if [ -d "$SRC" ]; then
  TREE=$(cd "$SRC" && pwd)
elif [ -f "$SRC" ]; then
  if command -v xz >/dev/null; then
    tar -C "$WORK" -xJf "$SRC"
  elif command -v python3 >/dev/null; then
    python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' "$SRC" "$WORK"
  else
    echo "bench/gpu: cannot unpack $SRC (no xz, no python3): unpack it elsewhere and pass the folder" >&2
    exit 2
  fi
  TREE=$(ls -d "$WORK"/flowsurf-*)
else
  echo "bench/gpu: $SRC: no such tarball or folder" >&2
  exit 2
fi
F=$TREE/bin/flowsurf
[ -x "$F" ] || { echo "bench/gpu: $F missing: not a flowsurf tree" >&2; exit 2; }

# 2. The driver: glvnd's loaders brought along, and NVIDIA's EGL vendor file when the driver
# was installed without one (glvnd finds vendors only through such a file).
if [ -n "${FLOWSURF_GLVND:-}" ]; then
  export LD_LIBRARY_PATH=$FLOWSURF_GLVND${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
fi
vendor_dirs=(/usr/share/glvnd/egl_vendor.d /etc/glvnd/egl_vendor.d /usr/local/share/glvnd/egl_vendor.d)
if [ -z "${__EGL_VENDOR_LIBRARY_DIRS:-}${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] \
   && ! ls "${vendor_dirs[@]}" 2>/dev/null | grep -q '\.json$'; then
  for d in /usr/lib/x86_64-linux-gnu /usr/lib64 /usr/lib /lib64; do
    if [ -e "$d/libEGL_nvidia.so.0" ]; then
      mkdir -p "$WORK/egl_vendor.d"
      printf '{"file_format_version": "1.0.0", "ICD": {"library_path": "%s"}}\n' "$d/libEGL_nvidia.so.0" \
        > "$WORK/egl_vendor.d/10_nvidia.json"
      export __EGL_VENDOR_LIBRARY_DIRS=$WORK/egl_vendor.d
      break
    fi
  done
fi

# 3. The grid as bench options; both GL paths when this flowsurf offers the choice.
join() { local IFS=,; echo "$*"; }
args=(--methods "$METHODS" --triangles "$(join "${TRIANGLES[@]}")" --sizes "$(join "${SIZES[@]}")"
      --lengths "$(join "${LENGTHS[@]}")" --grids "$(join "${GRIDS[@]}")" --frames "$FRAMES")
help=$("$F" bench --help)
if grep -q -- '--gl-paths' <<<"$help"; then args+=(--gl-paths fragment,compute); fi
# The bench options take lists as repeated values or comma-separated (CLI11 delimiter ',').
for opt in --triangles --sizes --lengths --grids; do
  grep -q -- "$opt" <<<"$help" || { echo "bench/gpu: this flowsurf bench has no $opt" >&2; exit 2; }
done

mkdir -p "$OUT"
{
  echo "flowsurf GPU benchmark, $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "flowsurf: $("$F" --version) ($TREE)"
  echo "machine: $(uname -srm); $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(nproc) CPUs"
  [ -r /proc/driver/nvidia/version ] && sed -n 1p /proc/driver/nvidia/version
  command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader
  echo "grid: methods $METHODS; triangles $(join "${TRIANGLES[@]}"); sizes $(join "${SIZES[@]}");" \
       "L $(join "${LENGTHS[@]}"); R $(join "${GRIDS[@]}"); $FRAMES frames per row"
  echo "command: flowsurf bench ${args[*]} --csv bench.csv"
} | tee "$OUT/info.txt"
echo
"$F" bench "${args[@]}" --csv "$OUT/bench.csv" | tee "$OUT/bench.txt"
echo
echo "CSV ($OUT/bench.csv):"
cat "$OUT/bench.csv"
