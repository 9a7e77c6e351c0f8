#!/usr/bin/env bash
# The GL test suite on a lent GPU machine (bare: NVIDIA driver only). Carry a folder holding
# glvnd's loader debs and fonts-dejavu-core's deb (the legend tests need the label font), the
# portable tarball (for its libraries) and a Release flowsurf_gl_tests copied from build/tests;
# the device tool sets OUT. Runs the tests that remake a method at once (the surface-pass flake
# of doc/bench/gpu_hopper.md) REPEAT times, then the whole suite SUITES times. ~3 minutes.
#   bench/gpu/gl_tests.sh CARRIED_DIR [REPEAT] [SUITES]
set -uo pipefail
DIR=${1:?usage: bench/gpu/gl_tests.sh CARRIED_DIR [REPEAT] [SUITES]}
REPEAT=${2:-24}
SUITES=${3:-2}
OUT=${OUT:-$PWD/gpu-gl-tests}
mkdir -p "$OUT"
. "$(dirname "$0")/prepare.sh"
export LD_LIBRARY_PATH=$TREE/lib
T="$DIR"/flowsurf_gl_tests
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee "$OUT/summary.txt"
failed() { grep -c '^\[  FAILED  \].*ms)$' "$1"; }
ran() { grep -c '^\[       OK \].*ms)$\|^\[  FAILED  \].*ms)$' "$1"; }
timeout 200 "$T" --gtest_filter='*GlPath*:*SurfaceRasterSameImage*' --gtest_repeat="$REPEAT" >"$OUT/remade.txt" 2>&1
echo "remade methods x$REPEAT: rc $? failed $(failed "$OUT/remade.txt") of $(ran "$OUT/remade.txt") test runs" | tee -a "$OUT/summary.txt"
for i in $(seq "$SUITES"); do
  timeout 200 "$T" >"$OUT/suite_$i.txt" 2>&1
  echo "whole GL suite, run $i: rc $? failed $(failed "$OUT/suite_$i.txt") of $(ran "$OUT/suite_$i.txt")" | tee -a "$OUT/summary.txt"
done
grep -h '^\[  FAILED  \].*ms)$' "$OUT"/remade.txt "$OUT"/suite_*.txt | sed 's/ (.*//' | sort | uniq -c || true
