#!/usr/bin/env bash
# A reference image set for changes that must not change a pixel (a restructuring): renders
# every method with the built flowsurf program over the cases users see (still and orbiting
# camera, colour by an array with its legend, dye, contrast enhancement, a time series, the
# topology overlay, each GL path), then compares a later build's images byte for byte.
#
#   scripts/pixel-reference.sh make DIR      render the set into DIR (outside the repository)
#   scripts/pixel-reference.sh compare DIR   render again into a temporary folder, cmp each
#                                            image with DIR's; exit 1 naming those that differ
# FLOWSURF: the program (default build/apps/flowsurf).
set -euo pipefail -o noglob
cd "$(dirname "$0")/.."
mode=${1:?usage: $0 make|compare DIR}
ref=${2:?usage: $0 make|compare DIR}
flowsurf=${FLOWSURF:-build/apps/flowsurf}
[ -x "$flowsurf" ] || { echo "pixel-reference: no program at $flowsurf" >&2; exit 2; }

case "$mode" in
make) out=$ref; mkdir -p "$out" ;;
compare) out=$(mktemp -d); trap 'rm -rf "$out"' EXIT ;;
*) echo "usage: $0 make|compare DIR" >&2; exit 2 ;;
esac

# One case a line: name, then the render arguments (the output is added).
cases() {
    local m
    for m in isa ibfvs hybrid; do
        echo "$m-still builtin:tori --method $m --size 160x112 --frames 12"
        echo "$m-orbit builtin:tori --method $m --size 160x112 --frames 12 --orbit 1"
        echo "$m-colour builtin:sphere --method $m --size 160x112 --frames 8 --color-by velocity:x --legend"
        echo "$m-dye builtin:sphere --method $m --size 128x128 --frames 16 --dye 0,0,1 --dye 0.6,0.6,0.5:0.15"
        echo "$m-contrast builtin:tori --method $m --size 160x112 --frames 10 --enhance-contrast both"
        echo "$m-series builtin:double-gyre --method $m --size 160x96 --frames 10 --frames-per-step 2"
        echo "$m-topology builtin:sphere --method $m --size 128x128 --frames 6 --topology on"
        echo "$m-compute builtin:tori --method $m --size 128x96 --frames 8 --orbit 1 --gl-path compute --surface-raster compute"
        echo "$m-fragment builtin:tori --method $m --size 128x96 --frames 8 --orbit 1 --gl-path fragment --surface-raster gl"
    done
    echo "isa-wss /work/shared/data/windAroundBuildings_wss.vtp --method isa --size 160x112 --frames 6 --legend"
    echo "hybrid-vortex /work/shared/data/vortexShed/*.vtp --method hybrid --size 160x112 --frames 6"
}

status=0
while read -r name args; do
    case "$args" in /work/shared/*) first=${args%% *}; [ -d "${first%/*}" ] || continue ;; esac  # not on every machine
    # shellcheck disable=SC2086  # the arguments are words (noglob: a series' pattern is flowsurf's)
    if ! "$flowsurf" render $args -q -o "$out/$name.png" 2>"$out/$name.err"; then
        echo "pixel-reference: $name failed: $(tail -1 "$out/$name.err")" >&2; status=1; continue
    fi
    rm -f "$out/$name.err"
    if [ "$mode" = compare ]; then
        if [ ! -f "$ref/$name.png" ]; then echo "new   $name"; status=1
        elif cmp -s "$ref/$name.png" "$out/$name.png"; then echo "same  $name"
        else echo "DIFF  $name"; status=1; fi
    fi
done < <(cases)
[ "$mode" = make ] && (cd "$out" && set +f && sha256sum ./*.png > SHA256SUMS && echo "pixel-reference: $(wc -l < SHA256SUMS) images in $out")
exit $status
