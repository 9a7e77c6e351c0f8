#!/usr/bin/env bash
# Installs the Debian 12 packages flowsurf needs to build, test and make videos.
# Runs apt-get only for what is missing (as root, or through sudo when available).
set -euo pipefail
PACKAGES=(
  build-essential cmake pkg-config              # toolchain
  libvtk9-dev                                   # readers for CFD formats (VTK 9)
  libcgns-dev                                   # CGNS boundary conditions (VTK's reader does not expose them)
  libseccomp-dev                                # the reader process's system-call filter
  libepoxy-dev libegl-dev libgl-dev             # OpenGL 4.5 function loading, EGL headless
  libegl-mesa0 libgl1-mesa-dri                  # Mesa llvmpipe: GL without a GPU
  libglm-dev                                    # vector maths
  libpng-dev                                    # PNG output
  libfreetype-dev fonts-dejavu-core             # labels on compare sheets
  libcli11-dev                                  # command-line parsing
  nlohmann-json3-dev                            # camera path files (JSON)
  libgtest-dev                                  # tests
  ffmpeg                                        # MP4 (H.264) output
  libglfw3-dev libimgui-dev                     # the viewer: window (GLFW 3.3) and panel (Dear ImGui)
  xvfb xauth xdotool                            # viewer tests: a real X window and real input without a display
  pybind11-dev python3-dev python3-numpy        # the Python module
  python3-pytest python3-vedo                   # Python tests (vedo: a real client mesh library)
  clang                                         # fuzz targets (libFuzzer, scripts/fuzz.sh)
  patchelf                                      # the portable tree's $ORIGIN RUNPATHs (test install_portable_tree)
  mkdocs mkdocs-material python3-pymdownx       # the manual (scripts/docs.sh, ctest docs)
  python3-ipywidgets python3-ipykernel jupyter-nbconvert python3-notebook   # Jupyter: the player, the notebook the manual runs
)
exec "$(dirname "$0")/apt-install.sh" "${PACKAGES[@]}"
