#!/usr/bin/env bash
# Builds flowsurf (Release, in build-package/) and writes the two binary packages:
#   dist/flowsurf_VERSION_amd64.deb                  Debian 12 package (CPack, Depends from shlibdeps)
#   dist/flowsurf-VERSION-linux-x86_64.tar.xz        portable tree: needs only glibc >= 2.36,
#                                                    libstdc++ (GCC >= 12) and a GL driver with EGL
# and prints their paths, the tarball's last. Usage: scripts/package.sh [--tar-only | --deb-only]
# The tarball's shared libraries are walked and patched by scripts/portable_tree.py; the
# check that it runs on a bare Debian root is scripts/check-package.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
MODE=${1:-all}
case "$MODE" in all|--tar-only|--deb-only) ;; *) echo "usage: scripts/package.sh [--tar-only | --deb-only]" >&2; exit 2;; esac
BUILD=$ROOT/build-package
MAX_MIB=64   # the tarball must fit what can be brought to a bare GPU machine

# Tools: patchelf (RUNPATHs), dpkg-dev (dpkg-shlibdeps for the .deb), the font that is bundled.
scripts/apt-install.sh patchelf dpkg-dev binutils xz-utils fonts-dejavu-core

# 1. Build: Release, libraries in PREFIX/lib and the Python module where Debian's python3 looks.
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
generator=()
if command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S . -B "$BUILD" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" -DFLOWSURF_BUILD_TESTS=OFF \
      -DCMAKE_INSTALL_LIBDIR=lib -DFLOWSURF_PYTHON_INSTALL=lib/python3/dist-packages >"$BUILD.configure.log" \
  || { cat "$BUILD.configure.log" >&2; exit 1; }
cmake --build "$BUILD" -j"$(nproc)" >&2
VERSION=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$BUILD/CMakeCache.txt")
mkdir -p dist
outputs=()

# 2. The Debian package.
if [ "$MODE" != --tar-only ]; then
  rm -rf "$BUILD/cpack"
  (cd "$BUILD" && cpack -G DEB -B "$BUILD/cpack" >"$BUILD/cpack.log" 2>&1) || { cat "$BUILD/cpack.log" >&2; exit 1; }
  deb=$(ls "$BUILD"/cpack/flowsurf_"$VERSION"_*.deb)
  mv "$deb" dist/
  outputs+=("$ROOT/dist/$(basename "$deb")")
fi

# 3. The portable tree: install, add the label font, bundle the libraries, check, compress.
if [ "$MODE" != --deb-only ]; then
  NAME=flowsurf-$VERSION-linux-x86_64
  STAGE=$BUILD/stage
  TREE=$STAGE/$NAME
  rm -rf "$STAGE"
  cmake --install "$BUILD" --prefix "$TREE" --strip >/dev/null
  mkdir -p "$TREE/share/flowsurf/fonts"
  cp /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf "$TREE/share/flowsurf/fonts/"
  python3 scripts/portable_tree.py bundle "$TREE" >&2
  # pkg-config: prefix relative to the .pc file, so the unpacked tree can live anywhere.
  sed -i 's|^prefix=.*|prefix=${pcfiledir}/../..|' "$TREE/lib/pkgconfig/flowsurf.pc"
  sed "s/@VERSION@/$VERSION/g" cmake/package/README.txt > "$TREE/README.txt"
  python3 scripts/portable_tree.py check "$TREE" >&2
  tarball=$ROOT/dist/$NAME.tar.xz
  mtime=$(git log -1 --format=%ct 2>/dev/null || date +%s)
  tar -C "$STAGE" --sort=name --owner=0 --group=0 --numeric-owner --mtime="@$mtime" -cf - "$NAME" \
    | xz -9 -T1 > "$tarball.tmp"
  mv "$tarball.tmp" "$tarball"
  size=$(stat -c %s "$tarball")
  echo "flowsurf: $(basename "$tarball"): $((size / 1024 / 1024)) MiB compressed, $(du -sm "$TREE" | cut -f1) MiB unpacked" >&2
  if [ "$size" -ge $((MAX_MIB * 1024 * 1024)) ]; then
    echo "flowsurf: the tarball exceeds $MAX_MIB MiB" >&2
    exit 1
  fi
  outputs+=("$tarball")
fi
printf '%s\n' "${outputs[@]}"
