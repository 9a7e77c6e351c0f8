# The Debian package (scripts/package.sh runs `cpack -G DEB`): dist/flowsurf_VERSION_amd64.deb
# installs under /usr what `cmake --install` installs (program, reader, library, headers,
# CMake/pkg-config files, the Python module). Depends are computed by dpkg-shlibdeps from the
# binaries (Debian 12's libvtk9.1, libepoxy0, ...); what only some commands need is
# recommended: ffmpeg (MP4 output), the label font, python3 + numpy (the module).
# The module is installed in /usr/lib/python3/dist-packages, where Debian's python3 looks,
# when the build was configured with -DFLOWSURF_PYTHON_INSTALL=lib/python3/dist-packages
# and -DCMAKE_INSTALL_LIBDIR=lib (as scripts/package.sh does).
set(CPACK_PACKAGE_NAME flowsurf)
set(CPACK_PACKAGE_VENDOR "flowsurf")
set(CPACK_PACKAGE_CONTACT "flowsurf maintainers <maintainers@users.noreply.h-seed-45a96946.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Dense, animated flow textures on triangle-mesh surfaces (ISA, IBFVS, hybrid LIC)")
set(CPACK_PACKAGE_DESCRIPTION "Texture-based flow visualization on surfaces, rendered with OpenGL 4.5
(EGL, headless or in a window): the command-line program and interactive viewer, the C++
library with its CMake and pkg-config files, and the Python module.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# BSD 3-Clause (LICENSE), installed as /usr/share/doc/flowsurf/copyright and LICENSE.
set(CPACK_RESOURCE_FILE_LICENSE ${CMAKE_CURRENT_SOURCE_DIR}/LICENSE)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
# Merged with shlibdeps' list: libepoxy opens the GL/EGL loaders with dlopen, so no binary
# names them.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl1, libopengl0 | libgl1")
set(FLOWSURF_DEB_RECOMMENDS "ffmpeg, fonts-dejavu-core")
if(FLOWSURF_PYTHON_EXECUTABLE)
  # The module is built for one Python minor version (its file name says cpython-3XY).
  execute_process(COMMAND ${FLOWSURF_PYTHON_EXECUTABLE} -c
                          "import sys; print(f'{sys.version_info[0]}.{sys.version_info[1]};{sys.version_info[0]}.{sys.version_info[1] + 1}')"
                  OUTPUT_VARIABLE FLOWSURF_PY_RANGE OUTPUT_STRIP_TRAILING_WHITESPACE)
  list(GET FLOWSURF_PY_RANGE 0 FLOWSURF_PY_MIN)
  list(GET FLOWSURF_PY_RANGE 1 FLOWSURF_PY_NEXT)
  string(APPEND FLOWSURF_DEB_RECOMMENDS ", python3 (>= ${FLOWSURF_PY_MIN}), python3 (<< ${FLOWSURF_PY_NEXT}), python3-numpy")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "${FLOWSURF_DEB_RECOMMENDS}")
include(CPack)
