#!/usr/bin/env bash
# For the next GPU lease: the surface-pass flake (gpu_hopper.md) with and without
# retired_programs.patch. Carry .gl/ holding glvnd's loader debs, the portable tarball and two
# Release GL test binaries: .gl/gl_tests_base (main) and .gl/gl_tests_fix (the patch applied);
# run from the repository root as `bash doc/bench/gpu/retired_programs_lease.sh` (OUT set by
# the device tool). ~3 minutes.
set -u
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
for v in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
  [ -e "$v" ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$v && break; done
tar -C /tmp -xJf .gl/flowsurf-*.tar.xz
TREE=$(ls -d /tmp/flowsurf-*)
export LD_LIBRARY_PATH=$TREE/lib
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee $OUT/info.txt
F='*GlPath*:*SurfaceRasterSameImage*'
count() { grep -c '^\[  FAILED  \].*ms)$' "$1"; }
for round in 1 2; do
  for v in base fix; do
    timeout 150 .gl/gl_tests_$v --gtest_filter="$F" --gtest_repeat=12 > $OUT/${v}_$round.txt 2>&1
    echo "round $round $v: rc $? failed test runs $(count $OUT/${v}_$round.txt) of $(grep -c '^\[       OK \]\|^\[  FAILED  \].*ms)$' $OUT/${v}_$round.txt)" | tee -a $OUT/summary.txt
  done
done
timeout 200 .gl/gl_tests_fix > $OUT/fix_suite.txt 2>&1; echo "whole GL suite with the fix: rc $?" | tee -a $OUT/summary.txt
tail -5 $OUT/fix_suite.txt; grep '^\[  FAILED  \]' $OUT/fix_suite.txt | head
