#!/usr/bin/env bash
# The README's first command: install what is missing, build, render the built-in demo
# to out/demo.png (final frame) and out/demo.mp4 (the animation).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/apps/flowsurf render builtin:tori --method isa --size 800x500 --frames 120 -o out/demo.png
build/apps/flowsurf render builtin:tori --method isa --size 800x500 --frames 179 --orbit 1 -o out/demo.mp4
echo "demo: out/demo.png out/demo.mp4"
