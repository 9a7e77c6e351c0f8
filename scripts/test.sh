#!/usr/bin/env bash
# The README's second command: install what is missing, build, run the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
# The ParaView plugin too (installs paraview, paraview-dev, xvfb, openmpi-bin; ~4 min the
# first time) and its pvbatch test; FLOWSURF_PARAVIEW=0 skips both.
if [ "${FLOWSURF_PARAVIEW:-1}" = 1 ]; then
  plugin="$(scripts/build-paraview-plugin.sh | tail -n1)"
  cmake -S . -B build -DFLOWSURF_TEST_PARAVIEW_PLUGIN=ON -DFLOWSURF_PARAVIEW_PLUGIN="$plugin" >/dev/null
fi
cd build
ctest --output-on-failure -j2 "$@"
