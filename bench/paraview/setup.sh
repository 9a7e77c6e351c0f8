#!/usr/bin/env bash
# Idempotent setup for the ParaView Surface LIC benchmark (Debian 12).
#
# * installs the Debian packages paraview, xvfb, xauth, python3-numpy with
#   --no-install-recommends (paraview recommends python3-paraview, see below)
# * downloads python3-paraview (same version as the installed paraview) and
#   unpacks it into a private prefix (default /opt/pvpython) WITHOUT
#   installing it: python3-paraview declares "Conflicts: python3-vtk9" and
#   both ship /usr/lib/python3/dist-packages/vtkmodules, so installing it
#   would remove the system VTK 9.1 Python bindings that flowsurf's dev
#   environment (libvtk9-dev / python3-vtk9) relies on.
# * checks that Debian's /usr/bin/python3 imports the LIC module from there
#
# All progress goes to stderr.  The only stdout line is
#     export PYTHONPATH=<prefix>/usr/lib/python3/dist-packages
# so that   eval "$(bench/paraview/setup.sh)"   sets the environment.
#
# Environment: PVPYTHON_PREFIX (default /opt/pvpython).
set -euo pipefail

PREFIX="${PVPYTHON_PREFIX:-/opt/pvpython}"
PY=/usr/bin/python3
SITE="$PREFIX/usr/lib/python3/dist-packages"

log() { echo "[setup.sh] $*" >&2; }

SUDO=""
if [ "$(id -u)" != 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    log "not root and no sudo: cannot install packages"; fi
fi

# --- Debian packages -------------------------------------------------------
"$(dirname "$0")/../../scripts/apt-install.sh" paraview xvfb xauth python3-numpy

PV_VERSION="$(dpkg-query -W -f='${Version}' paraview)"
log "paraview package version: $PV_VERSION"

if dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null | grep -q "install ok installed"; then
  log "note: python3-paraview is installed system-wide; the private prefix is used anyway"
fi

# --- python3-paraview into a private prefix --------------------------------
STAMP="$PREFIX/.python3-paraview-version"
if [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$PV_VERSION" ] && [ -d "$SITE/paraview" ] \
   && [ -f "$SITE/vtkmodules/vtkRenderingLICOpenGL2.so" ]; then
  log "python3-paraview $PV_VERSION already unpacked in $PREFIX"
else
  tmp="$(mktemp -d)"
  # as root, apt downloads as user _apt: let it write there (avoids a warning)
  if [ "$(id -u)" = 0 ] && id _apt >/dev/null 2>&1; then chown _apt "$tmp"; fi
  trap 'rm -rf "$tmp"' EXIT
  log "downloading python3-paraview=$PV_VERSION"
  if ! (cd "$tmp" && apt-get download "python3-paraview=$PV_VERSION" >&2); then
    log "download failed; refreshing package lists and retrying"
    $SUDO apt-get update -qq >&2
    (cd "$tmp" && apt-get download "python3-paraview=$PV_VERSION" >&2)
  fi
  deb="$(ls "$tmp"/python3-paraview_*.deb | head -n1)"
  log "unpacking $(basename "$deb") into $PREFIX (dpkg -x, not installed)"
  $SUDO rm -rf "$PREFIX/usr"
  $SUDO mkdir -p "$PREFIX"
  $SUDO dpkg -x "$deb" "$PREFIX"
  echo "$PV_VERSION" | $SUDO tee "$STAMP" >/dev/null
fi

if [ ! -d "$SITE/vtkmodules" ]; then
  log "ERROR: $SITE/vtkmodules not found after unpacking"
  exit 1
fi

# --- check the import -------------------------------------------------------
if ! out="$(cd / && PYTHONPATH="$SITE" "$PY" - 2>&1 <<'EOF'
import vtkmodules
from vtkmodules.vtkCommonCore import vtkVersion
from vtkmodules.vtkRenderingLICOpenGL2 import vtkSurfaceLICMapper, vtkSurfaceLICInterface
import numpy
print("vtkmodules from %s, VTK %s, numpy %s" % (vtkmodules.__path__[0],
      vtkVersion.GetVTKVersion(), numpy.__version__))
EOF
)"; then
  log "ERROR: $PY cannot import the ParaView VTK modules from $SITE:"
  echo "$out" >&2
  exit 1
fi
log "$out"

echo "export PYTHONPATH=$SITE"
