#!/usr/bin/env bash
# The portable tree as scripts/package.sh makes it, from this build tree: install into a
# temporary prefix, bundle the libraries (scripts/portable_tree.py), then check that
#  - every ELF file's RUNPATH is $ORIGIN-relative and stays inside the tree, and every library
#    that is not the C library, the compiler runtime or the GL driver resolves inside it
#    (the loader's search and the real loader, ldd);
#  - the check catches a RUNPATH that leaves the tree and a library missing from lib/;
#  - bin/flowsurf renders, and reads a file through the reader process, from another folder,
#    called by path and through PATH.
# With FLOWSURF_TARBALL=dist/flowsurf-*.tar.xz the tarball itself is checked as well.
# Exit 77 (skipped) without patchelf.
set -euo pipefail
BUILD=${1:?usage: portable_tree_test.sh BUILD_DIR SOURCE_DIR}
SRC=${2:?usage: portable_tree_test.sh BUILD_DIR SOURCE_DIR}
command -v patchelf >/dev/null || { echo "patchelf missing (apt-get install patchelf): skipped"; exit 77; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
TOOL=$SRC/scripts/portable_tree.py
passed=0
failed=0
ok() { echo "ok: $1"; passed=$((passed + 1)); }
bad() { echo "FAIL: $1"; failed=$((failed + 1)); }

TREE=$WORK/tree
cmake --install "$BUILD" --prefix "$TREE" > "$WORK/install.log"
python3 "$TOOL" bundle "$TREE" > "$WORK/bundle.log"
if python3 "$TOOL" check "$TREE" > "$WORK/check.log" 2>&1; then ok "$(tail -1 "$WORK/check.log")"
else bad "check of the bundled tree:"; cat "$WORK/check.log"; fi
runpath=$(readelf -dW "$TREE/bin/flowsurf" | sed -n 's/.*(RUNPATH).*\[\(.*\)\]/\1/p')
[ "$runpath" = '$ORIGIN/../lib' ] && ok "bin/flowsurf RUNPATH $runpath" || bad "bin/flowsurf RUNPATH '$runpath'"
grep -q "^libvtkCommonCore-9.1.so.1	libvtk9.1	" "$TREE/share/doc/flowsurf/bundled.txt" \
  && [ -s "$TREE/share/doc/flowsurf/licenses/libvtk9.1.copyright" ] && ok "bundled.txt and licences" \
  || bad "bundled.txt or licences"
grep -q "BSD 3-Clause License" "$TREE/share/doc/flowsurf/LICENSE" && cmp -s "$SRC/LICENSE" "$TREE/share/doc/flowsurf/copyright" \
  && ok "flowsurf's own licence beside them" || bad "share/doc/flowsurf/LICENSE or copyright missing"
if ls "$TREE"/lib | grep -Eq '^(libc\.so|libstdc\+\+|libEGL|libGL|libOpenGL)'; then bad "system or driver library bundled"
else ok "no C library, libstdc++ or GL loader in lib/"; fi

# The check must fail on a tree that is not self-contained.
# (Hard-linked copies; the file patchelf edits is a copy of its own.)
cp -al "$TREE" "$WORK/leak"
rm "$WORK/leak/bin/flowsurf"
cp "$TREE/bin/flowsurf" "$WORK/leak/bin/flowsurf"
patchelf --set-rpath /usr/lib/x86_64-linux-gnu "$WORK/leak/bin/flowsurf"
python3 "$TOOL" check "$WORK/leak" > "$WORK/leak.log" 2>&1 && bad "RUNPATH outside the tree not caught" \
  || { grep -q "bin/flowsurf: RUNPATH entry /usr/lib/x86_64-linux-gnu is not \$ORIGIN-relative" "$WORK/leak.log" \
         && ok "RUNPATH outside the tree caught" || { bad "leak message"; cat "$WORK/leak.log"; }; }
rm -rf "$WORK/leak"
cp -al "$TREE" "$WORK/hole"
rm "$WORK/hole/lib/libpng16.so.16"
python3 "$TOOL" check "$WORK/hole" > "$WORK/hole.log" 2>&1 && bad "missing library not caught" \
  || { grep -q "bin/flowsurf: needs libpng16.so.16, not found through its RUNPATH" "$WORK/hole.log" \
         && ok "missing library caught" || { bad "hole message"; cat "$WORK/hole.log"; }; }
rm -rf "$WORK/hole"

# The tree works from another folder: a render, and a file read in the reader process.
mkdir "$WORK/elsewhere"
cd "$WORK/elsewhere"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n' > quad.obj
env -u LD_LIBRARY_PATH -u FLOWSURF_READER "$TREE/bin/flowsurf" render builtin:tori --size 64x48 --frames 2 -o t.png -q \
  && [ "$(od -An -tu4 --endian=big -j16 -N8 t.png | tr -s ' ')" = " 64 48" ] && ok "render from another folder" \
  || bad "render from another folder"
env -u LD_LIBRARY_PATH -u FLOWSURF_READER PATH="$TREE/bin:$PATH" flowsurf info quad.obj > info.txt 2>&1 \
  && grep -q "4 points, 2 triangles" info.txt && ok "info through PATH (reader found from /proc/self/exe)" \
  || { bad "info through PATH"; cat info.txt; }

# The tarball itself, when given.
if [ -n "${FLOWSURF_TARBALL:-}" ]; then
  mkdir "$WORK/tarball"
  tar -C "$WORK/tarball" -xf "$FLOWSURF_TARBALL"
  if python3 "$TOOL" check "$WORK"/tarball/flowsurf-* > "$WORK/tarball.log" 2>&1; then ok "tarball: $(tail -1 "$WORK/tarball.log")"
  else bad "tarball check"; cat "$WORK/tarball.log"; fi
fi
echo "portable tree: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
