#!/usr/bin/env bash
# The README's second command: install what is missing, build, run the whole suite.
#   scripts/test.sh [CTEST ARGS]        Release build in build/
#   scripts/test.sh --sanitize [ARGS]   ASan + UBSan build in build-sanitize/; every test
#                                       but the Python module's (python3 itself is not
#                                       instrumented) and the install consumer's
# With CI=true the Release build treats warnings as errors (FLOWSURF_WERROR).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
if [ "${1:-}" = "--sanitize" ]; then
    shift
    # -O1 -g1: half the compile time of -O2 -g (five of the heaviest files: 73 -> 36 CPU-s),
    # file:line in every report; what lets CI afford the whole suite.
    cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFLOWSURF_SANITIZE=ON \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
        -DFLOWSURF_BUILD_PYTHON=OFF >/dev/null
    cmake --build build-sanitize -j"$(nproc)"
    cd build-sanitize
    # Leaks: Mesa, EGL and VTK keep process-lifetime allocations; errors and UB halt.
    export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:strict_string_checks=1
    export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
    ctest --output-on-failure -j2 -LE install "$@"
    exit
fi
werror=OFF
[ "${CI:-}" = true ] && werror=ON  # a newer compiler's new warnings stay warnings elsewhere
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFLOWSURF_WERROR=$werror >/dev/null
scripts/build.sh
# The ParaView plugin too (installs paraview, paraview-dev, xvfb, openmpi-bin; ~4 min the
# first time) and its pvbatch test; FLOWSURF_PARAVIEW=0 skips both.
if [ "${FLOWSURF_PARAVIEW:-1}" = 1 ]; then
  plugin="$(scripts/build-paraview-plugin.sh | tail -n1)"
  cmake -S . -B build -DFLOWSURF_TEST_PARAVIEW_PLUGIN=ON -DFLOWSURF_PARAVIEW_PLUGIN="$plugin" >/dev/null
fi
cd build
ctest --output-on-failure -j2 "$@"
