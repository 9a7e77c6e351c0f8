#!/usr/bin/env bash
# The installed package as an outside project sees it: install the build tree into a
# temporary prefix, configure and build examples/cpp against it alone (find_package and
# pkg-config), run it, and check the PNG it writes.
set -euo pipefail
BUILD=${1:?usage: consumer_test.sh BUILD_DIR SOURCE_DIR}
SRC=${2:?usage: consumer_test.sh BUILD_DIR SOURCE_DIR}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cmake --install "$BUILD" --prefix "$WORK/prefix" > "$WORK/install.log"
# Files are read in flowsurf-reader, installed where the library looks for it.
[ -x "$WORK/prefix/libexec/flowsurf/flowsurf-reader" ] || { echo "flowsurf-reader not installed in libexec/flowsurf"; exit 1; }
cmake -S "$SRC/examples/cpp" -B "$WORK/consumer" -DCMAKE_PREFIX_PATH="$WORK/prefix" > "$WORK/configure.log"
cmake --build "$WORK/consumer" > "$WORK/build.log"
LD_LIBRARY_PATH="$WORK/prefix/lib" "$WORK/consumer/spinning_sphere" "$WORK/sphere.png" hybrid
# A PNG of the requested size (IHDR width/height at bytes 16..23), not a stub.
size=$(od -An -tu1 -j16 -N8 "$WORK/sphere.png" | tr -s ' ')
[ "$size" = " 0 0 1 224 0 0 1 104" ] || { echo "unexpected PNG header: $size"; exit 1; }
[ "$(stat -c %s "$WORK/sphere.png")" -gt 20000 ] || { echo "PNG too small to hold a rendered sphere"; exit 1; }
# pkg-config finds the same library.
PKG_CONFIG_PATH="$WORK/prefix/lib/pkgconfig" pkg-config --cflags --libs flowsurf | grep -q -- "-lflowsurf"
# The headers need no GL, EGL or VTK header.
if grep -rE '#include <(GL|EGL|epoxy|vtk|glm)' "$WORK/prefix/include/flowsurf"; then exit 1; fi
echo "consumer: 1 passed, 0 failed"
