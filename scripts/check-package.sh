#!/usr/bin/env bash
# Proves the packages on a Linux with nothing but a GL driver: a clean Debian 12 root
# (debootstrap --variant=minbase) plus only glvnd's loaders and Mesa (libegl1 libgl1
# libopengl0 libgl1-mesa-dri libegl-mesa0), entered with chroot. Root only; needs network
# the first time (the root is cached in $FLOWSURF_ROOT_CACHE, default /var/cache/flowsurf-root,
# and the .deb's dependencies in its apt archive, so reruns take about a minute).
#   scripts/check-package.sh [TARBALL [DEB]]    defaults: the newest in dist/ (scripts/package.sh)
# Tarball, from a random folder: render builtin:tori, a .vtp through the reader process, a
# legend (the bundled font), bin/ on PATH, MP4 (must fail with the ffmpeg message, no file),
# view --headless, bench/gpu/run.sh on a quick grid. Then, on a fresh copy of the root:
# apt-get install ./flowsurf_*.deb, the same renders, an MP4 (ffmpeg comes as a Recommends)
# and `import flowsurf` in python3. FLOWSURF_CHECK_ONLY=tar or deb runs one half.
# The PNGs land in out/check-package/ to be looked at. Exit status: the number of failures.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
TARBALL=${1:-$(ls -t dist/flowsurf-*-linux-x86_64.tar.xz 2>/dev/null | head -1)}
DEB=${2:-$(ls -t dist/flowsurf_*_amd64.deb 2>/dev/null | head -1)}
[ -f "$TARBALL" ] || { echo "check-package: no tarball (run scripts/package.sh)" >&2; exit 2; }
[ -f "$DEB" ] || { echo "check-package: no .deb (run scripts/package.sh)" >&2; exit 2; }
[ "$(id -u)" -eq 0 ] || { echo "check-package: needs root (debootstrap, chroot)" >&2; exit 2; }
CACHE=${FLOWSURF_ROOT_CACHE:-/var/cache/flowsurf-root}
MIRROR=${FLOWSURF_DEBIAN_MIRROR:-http://deb.debian.org/debian}
# The .vtp read through the reader: OpenFOAM's windAroundBuildings wall shear stress when the
# shared data is at hand, else a generated wavy sheet with a vortex (ASCII VTK XML).
DATA=${FLOWSURF_CHECK_VTP:-}
for d in "$ROOT/../shared/data" "$ROOT/../../shared/data"; do
  [ -z "$DATA" ] && [ -f "$d/windAroundBuildings_wss.vtp" ] && DATA=$d/windAroundBuildings_wss.vtp
done
OUT=$ROOT/out/check-package
GL_PACKAGES=(libegl1 libgl1 libopengl0 libgl1-mesa-dri libegl-mesa0)
scripts/apt-install.sh debootstrap

# 1. The cached root: minbase + the GL driver packages, nothing else.
BASE=$CACHE/bookworm-gl
if [ ! -f "$BASE/.flowsurf-root-done" ]; then
  rm -rf "$BASE"
  echo "check-package: debootstrap --variant=minbase bookworm (first run only)" >&2
  debootstrap --variant=minbase bookworm "$BASE" "$MIRROR" >"$CACHE/debootstrap.log" 2>&1 \
    || { tail -20 "$CACHE/debootstrap.log" >&2; exit 2; }
  cat >"$BASE/etc/apt/sources.list" <<EOF
deb $MIRROR bookworm main
deb $MIRROR bookworm-updates main
deb http://security.debian.org/debian-security bookworm-security main
EOF
  cp /etc/resolv.conf "$BASE/etc/resolv.conf"
  chroot "$BASE" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive chroot "$BASE" apt-get install -y -qq --no-install-recommends "${GL_PACKAGES[@]}" >/dev/null
  chroot "$BASE" apt-get clean
  touch "$BASE/.flowsurf-root-done"
fi
mkdir -p "$CACHE/archives/partial"

# A fresh copy of the cached root per stage, with /proc, /dev and the apt archive mounted.
WORK=$(mktemp -d /var/tmp/flowsurf-check.XXXXXX)
MOUNTS=()
cleanup() {
  for ((i = ${#MOUNTS[@]} - 1; i >= 0; i--)); do umount -l "${MOUNTS[i]}" 2>/dev/null || true; done
  rm -rf "$WORK"
}
trap cleanup EXIT
new_root() {  # new_root NAME -> path in $R
  R=$WORK/$1
  cp -a "$BASE" "$R"
  mount -t proc proc "$R/proc" && MOUNTS+=("$R/proc")
  mount --bind /dev "$R/dev" && MOUNTS+=("$R/dev")
  mount --bind "$CACHE/archives" "$R/var/cache/apt/archives" && MOUNTS+=("$R/var/cache/apt/archives")
  cp /etc/resolv.conf "$R/etc/resolv.conf"
  mkdir -p "$R/data"
  if [ -n "$DATA" ]; then cp "$DATA" "$R/data/case.vtp"; else make_vtp >"$R/data/case.vtp"; fi
  printf '# flowsurf events 1\nat 0 set method hybrid\nat 20 screenshot view.png\n' >"$R/data/events.txt"
}
make_vtp() {  # a 60x60 wavy sheet, point vectors "wallShearStress" circling its centre
  python3 - <<'PY'
import math
n = 60
pts, vec, tri = [], [], []
for j in range(n):
    for i in range(n):
        x, y = i / (n - 1) - 0.5, j / (n - 1) - 0.5
        pts.append((x, y, 0.08 * math.sin(6 * x) * math.cos(5 * y)))
        vec.append((-y + 0.2 * x, x + 0.2 * y, 0.0))
for j in range(n - 1):
    for i in range(n - 1):
        a = j * n + i
        tri += [(a, a + 1, a + n + 1), (a, a + n + 1, a + n)]
f = lambda rows: " ".join("%g" % v for r in rows for v in r)
print('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">'
      '<PolyData><Piece NumberOfPoints="%d" NumberOfPolys="%d">' % (len(pts), len(tri)))
print('<PointData><DataArray type="Float32" Name="wallShearStress" NumberOfComponents="3" format="ascii">%s'
      '</DataArray></PointData>' % f(vec))
print('<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">%s</DataArray></Points>' % f(pts))
print('<Polys><DataArray type="Int32" Name="connectivity" format="ascii">%s</DataArray>' % f(tri))
print('<DataArray type="Int32" Name="offsets" format="ascii">%s</DataArray></Polys>'
      % " ".join(str(3 * (k + 1)) for k in range(len(tri))))
print('</Piece></PolyData></VTKFile>')
PY
}
rm -rf "$OUT"
mkdir -p "$OUT"
failures=0
# check NAME COMMAND...: runs COMMAND in the chroot ($R) from a new random folder; the
# folder's files are copied to out/check-package/NAME-*.
check() {
  local name=$1
  shift
  local log=$OUT/$name.log
  if chroot "$R" /bin/bash -c 'cd "$(mktemp -d /tmp/anywhere.XXXXXX)" && '"$*"' && cp -r . /tmp/result' >"$log" 2>&1; then
    echo "PASS  $name: $*"
  else
    echo "FAIL  $name: $* (log: $log)"
    tail -5 "$log" | sed 's/^/      /'
    failures=$((failures + 1))
  fi
  if [ -d "$R/tmp/result" ]; then
    for f in "$R"/tmp/result/*; do [ -f "$f" ] && cp "$f" "$OUT/$name-$(basename "$f")"; done
    rm -rf "$R/tmp/result"
  fi
}
png_size() { od -An -tu4 --endian=big -j16 -N8 "$1" | tr -s ' ' | sed 's/^ //'; }
expect_png() {  # expect_png FILE "W H"
  if [ -f "$1" ] && [ "$(png_size "$1")" = "$2" ] && [ "$(stat -c %s "$1")" -gt 10000 ]; then
    echo "PASS  $(basename "$1"): a ${2/ /x} PNG, $(stat -c %s "$1") bytes"
  else
    echo "FAIL  $(basename "$1"): not a ${2/ /x} PNG with content"
    failures=$((failures + 1))
  fi
}

# 2. The tarball, unpacked in /opt, nothing else installed.
check_tarball() {
  echo "== tarball $(basename "$TARBALL") ($(($(stat -c %s "$TARBALL") / 1024 / 1024)) MiB) in a root with only: ${GL_PACKAGES[*]}"
  new_root tar
  tar -C "$R/opt" -xf "$TARBALL"   # here: minbase has no xz
  F=$(cd "$R/opt" && ls -d flowsurf-*)
  F=/opt/$F/bin/flowsurf
  check tar-tori "$F render builtin:tori --size 512x384 -o tori.png"
  check tar-vtp "$F render /data/case.vtp --field wallShearStress --size 512x384 --legend -o wind.png"
  check tar-path "PATH=$(dirname "$F"):\$PATH flowsurf info /data/case.vtp"
  check tar-mp4 "! $F render builtin:tori --size 128x128 --frames 4 -o tori.mp4 2>err.txt && grep -q 'ffmpeg not found' err.txt && ! ls *.mp4 && cat err.txt"
  check tar-view "$F view builtin:sphere --headless --size 320x240 --play /data/events.txt"
  cp bench/gpu/run.sh "$R/data/gpu-bench.sh"
  check tar-bench "FLOWSURF_BENCH_QUICK=1 FLOWSURF_BENCH_FRAMES=1 bash /data/gpu-bench.sh ${F%/bin/flowsurf} out \
    && grep -q '^GL driver: .*Mesa' out/bench.txt && test \$(wc -l < out/bench.csv) -eq 25"
  expect_png "$OUT/tar-tori-tori.png" "512 384"
  expect_png "$OUT/tar-vtp-wind.png" "512 384"
  expect_png "$OUT/tar-view-view.png" "320 240"
  grep -h "ffmpeg not found" "$OUT/tar-mp4.log" | sed 's/^/      message: /' || true
  umount -l "$R/proc" "$R/dev" "$R/var/cache/apt/archives" 2>/dev/null || true
}

# 3. The .deb on a fresh root: apt resolves its Depends (and Recommends) from Debian 12.
check_deb() {
  echo "== $(basename "$DEB"): apt-get install on a fresh copy of the root"
  new_root deb
  cp "$DEB" "$R/tmp/"
  if chroot "$R" /bin/bash -c "apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq /tmp/$(basename "$DEB")" \
      >"$OUT/deb-install.log" 2>&1; then
    echo "PASS  deb-install: apt-get install ./$(basename "$DEB") ($(grep -c '^Setting up' "$OUT/deb-install.log") packages set up)"
  else
    echo "FAIL  deb-install (log: $OUT/deb-install.log)"
    tail -5 "$OUT/deb-install.log" | sed 's/^/      /'
    failures=$((failures + 1))
  fi
  check deb-tori "flowsurf render builtin:tori --size 512x384 -o tori.png"
  check deb-vtp "flowsurf render /data/case.vtp --field wallShearStress --size 512x384 --legend -o wind.png"
  check deb-mp4 "flowsurf render builtin:tori --size 128x128 --frames 12 -o tori.mp4 && test -s tori.mp4"
  check deb-python "python3 -c 'import flowsurf; s = flowsurf.read(\"/data/case.vtp\", field=\"wallShearStress\"); \
  img = flowsurf.render(s, size=(320, 240), frames=8); open(\"py.png\", \"wb\").write(flowsurf.to_png(img)); print(img.shape)'"
  expect_png "$OUT/deb-tori-tori.png" "512 384"
  expect_png "$OUT/deb-vtp-wind.png" "512 384"
  expect_png "$OUT/deb-python-py.png" "320 240"
}

case "${FLOWSURF_CHECK_ONLY:-}" in
  tar) check_tarball ;;
  deb) check_deb ;;
  *) check_tarball; check_deb ;;
esac
echo "check-package: $failures failed; images in $OUT"
exit "$failures"
