#!/usr/bin/env bash
# Builds the FlowSurf ParaView plugin (src/paraview) against Debian 12's ParaView 5.11 and
# prints the plugin file's path as its last line (stdout); progress goes to stderr.
#
#   PLUGIN="$(scripts/build-paraview-plugin.sh | tail -n1)"
#   xvfb-run -a pvbatch --force-offscreen-rendering script.py   # script: LoadPlugin(PLUGIN)
#
# What it does (idempotent):
#  1. installs paraview, paraview-dev, libopenmpi-dev, xvfb, xauth, openmpi-bin with
#     --no-install-recommends (paraview recommends python3-paraview, which conflicts with
#     libvtk9-dev / python3-vtk9); refuses if apt would remove anything.
#  2. unpacks python3-paraview into a private prefix (bench/paraview/setup.sh, dpkg -x,
#     never installed): ParaView's CMake package lists its Python modules as imported
#     targets and checks that their files exist under /usr/lib/python3/dist-packages.
#  3. copies ParaView's CMake package next to that prefix with the Python module paths
#     pointed into it and every other path pinned to /usr (the originals compute /usr from
#     their own location), so find_package(ParaView) succeeds without touching /usr; the
#     wrapping hierarchy files (python3-paraview ships them) are taken from the prefix.
#  4. configures and builds src/paraview (its own CMake project: ParaView's VTK 9.2 and
#     Debian's VTK 9.1 cannot meet in one project) into build-paraview/.
#
# Environment: PVPYTHON_PREFIX (/opt/pvpython), FLOWSURF_PV_BUILD (build-paraview),
# JOBS (2).
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
PREFIX="${PVPYTHON_PREFIX:-/opt/pvpython}"
BUILD="${FLOWSURF_PV_BUILD:-$ROOT/build-paraview}"
JOBS="${JOBS:-2}"
PV_CMAKE=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11
PRIVATE_CMAKE="$PREFIX/cmake/paraview-5.11"

log() { echo "[build-paraview-plugin] $*" >&2; }
SUDO=""
if [ "$(id -u)" != 0 ] && command -v sudo >/dev/null 2>&1; then SUDO="sudo"; fi

# --- 1. Debian packages ------------------------------------------------------------------
t0=$SECONDS
"$ROOT/scripts/apt-install.sh" paraview paraview-dev libopenmpi-dev xvfb xauth openmpi-bin python3-numpy cmake g++ pkg-config \
    libglm-dev libepoxy-dev libegl-dev
log "packages ready ($((SECONDS - t0)) s)"

# --- 2. python3-paraview in a private prefix ---------------------------------------------
PVPYTHON_PREFIX="$PREFIX" "$ROOT/bench/paraview/setup.sh" >/dev/null
SITE="$PREFIX/usr/lib/python3/dist-packages"

# --- 3. ParaView's CMake package, pointed at the private Python modules ------------------
STAMP="$PRIVATE_CMAKE/.flowsurf-source"
if [ ! -f "$STAMP" ] || [ "$(cat "$STAMP")" != "$(dpkg-query -W -f='${Version}' paraview-dev)" ]; then
  log "writing $PRIVATE_CMAKE"
  $SUDO rm -rf "$PRIVATE_CMAKE"
  $SUDO mkdir -p "$(dirname "$PRIVATE_CMAKE")"
  $SUDO cp -r "$PV_CMAKE" "$PRIVATE_CMAKE"
  # Pin each file's install-prefix computation to where the original lies.
  (cd "$PRIVATE_CMAKE" && find . -name '*.cmake' -print0) | while IFS= read -r -d '' f; do
    orig="$PV_CMAKE/$(dirname "${f#./}")"
    orig="${orig%/.}"
    $SUDO sed -i \
      -e "s#get_filename_component(_IMPORT_PREFIX \"\${CMAKE_CURRENT_LIST_FILE}\" PATH)#set(_IMPORT_PREFIX \"$orig\")#" \
      -e "s#set(_vtk_module_import_prefix \"\${CMAKE_CURRENT_LIST_DIR}\")#set(_vtk_module_import_prefix \"$orig\")#" \
      -e "s#\"\${CMAKE_CURRENT_LIST_DIR}/../../../../../../\"#\"$orig/../../../../../../\"#" \
      -e "s#\${_IMPORT_PREFIX}/lib/python3/dist-packages#$SITE#g" \
      -e "s#\${_IMPORT_PREFIX}/bin/pvpython#$PREFIX/usr/bin/pvpython#g" \
      -e "s#\"\${_vtk_module_import_prefix}/lib/x86_64-linux-gnu/vtk/hierarchy/#\"$PREFIX/usr/lib/x86_64-linux-gnu/vtk/hierarchy/#g" \
      "$PRIVATE_CMAKE/${f#./}"
  done
  dpkg-query -W -f='${Version}' paraview-dev | $SUDO tee "$STAMP" >/dev/null
fi

# --- 4. the plugin -----------------------------------------------------------------------
t1=$SECONDS
log "configuring $BUILD"
cmake -S "$ROOT/src/paraview" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release \
      -DParaView_DIR="$PRIVATE_CMAKE" >&2
log "building (-j$JOBS)"
cmake --build "$BUILD" -j"$JOBS" >&2
log "plugin built ($((SECONDS - t1)) s)"

plugin="$(find "$BUILD" -name 'FlowSurf.so' -type f | head -n1)"
if [ -z "$plugin" ]; then log "ERROR: FlowSurf.so not found under $BUILD"; exit 1; fi
echo "$plugin"
