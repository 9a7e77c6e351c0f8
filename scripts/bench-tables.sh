#!/usr/bin/env bash
# Regenerates the published benchmark tables, each with the machine (CPU model, cores, GL
# renderer) and commit it was measured on: the files in doc/bench/ and, on llvmpipe, the
# manual's blocks (docs/performance.md) between <!-- bench-tables NAME --> and <!-- /bench-tables NAME -->.
#
#   scripts/bench-tables.sh [TABLE ...]      default: all of them, in this order
#
#   isa_ibfvs  doc/bench/isa_ibfvs_R.txt + docs block     flowsurf bench, ISA and IBFVS grid   ~8 min
#   hybrid     doc/bench/hybrid_R.txt                      hybrid, ParaView's framing, dynamic   ~2 min
#   gl_paths   doc/bench/gl_paths_R.txt                    fragment vs compute per stage         ~3 min
#   surface_raster doc/bench/surface_raster_R.txt          GL vs compute rasteriser, dynamic     ~4 min
#   paraview   doc/bench/hybrid_vs_paraview_R.md + docs    bench/paraview/compare.sh             ~25 min
#   viewer     doc/bench/viewer_R.txt                      bench/viewer/run.sh                   ~4 min
#
# R is the renderer: "llvmpipe", or a name made from GL_RENDERER elsewhere (a GPU's tables
# go beside llvmpipe's, and only llvmpipe's go into docs/performance.md). Times are those of the
# 2-core llvmpipe machine. Needs build/apps/flowsurf (scripts/build.sh; FLOWSURF overrides).
# paraview is skipped, with a message, when ParaView is not installed (bench/paraview/setup.sh);
# viewer when the wind-around-buildings surface (VIEWER_INPUT, default
# ../shared/data/windAroundBuildings_wss.vtp beside the checkout) or xvfb-run is missing.
# A skipped table keeps its last measurement, which names its own machine and commit.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
F=${FLOWSURF:-build/apps/flowsurf}
[ -x "$F" ] || { echo "bench-tables: $F not found: build first (scripts/build.sh)" >&2; exit 2; }
. bench/machine.sh
TABLES=("$@")
ALL=(isa_ibfvs hybrid gl_paths surface_raster paraview viewer)
[ ${#TABLES[@]} -gt 0 ] || TABLES=("${ALL[@]}")
for t in "${TABLES[@]}"; do
    case " ${ALL[*]} " in *" $t "*) ;;
        *) echo "bench-tables: unknown table '$t' (${ALL[*]})" >&2; exit 2 ;;
    esac
done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

RENDERER=$(bench_renderer "$F")
MACHINE=$(bench_machine "$RENDERER")
COMMIT=$(bench_commit)
case "$RENDERER" in
    *llvmpipe*) R=llvmpipe ;;
    *) R=$(echo "${RENDERER##*, GL [0-9].[0-9], }" | cut -d/ -f1 | tr 'A-Z' 'a-z' | tr -cs 'a-z0-9' '_' | sed 's/_$//') ;;
esac
echo "bench-tables: $MACHINE, commit $COMMIT; tables: ${TABLES[*]}"

load() { cut -d' ' -f1-3 /proc/loadavg; }
# The lines above every generated text table: how it was made, on what, from which commit.
header() {
    echo "# scripts/bench-tables.sh: $1"
    echo "# machine: $MACHINE"
    echo "# commit: $COMMIT, $(date -u +%Y-%m-%d), load average at the start: $(load)"
}
# The line above a table of docs/performance.md.
note() {
    echo "*Measured by \`scripts/bench-tables.sh $1\` on $MACHINE; commit $COMMIT, $(date -u +%Y-%m-%d);" \
         "load average $(load) at the end (other jobs on the same cores slow every row).*"
}
# Writes stdin to FILE only when it is complete (no partial table on failure).
publish() {
    cat > "$WORK/publish"
    mv "$WORK/publish" "$1"
    echo "bench-tables: wrote $1"
}
readme_block() {  # NAME FILE
    if [ "$R" = llvmpipe ]; then python3 bench/tables.py replace docs/performance.md "$1" "$2"; echo "bench-tables: docs/performance.md block $1"; fi
}
bench_table() {  # NAME ARGS...: doc/bench/NAME_R.txt from one `flowsurf bench` run
    local name=$1
    shift
    { header "flowsurf bench $*"; "$F" bench "$@" --csv "$WORK/$name.csv"; echo "# load average at the end: $(load)"; } \
        > "$WORK/$name.txt"
    publish "doc/bench/${name}_$R.txt" < "$WORK/$name.txt"
}

for t in "${TABLES[@]}"; do
    echo "bench-tables: $t ..."
    case "$t" in
    isa_ibfvs)
        bench_table isa_ibfvs --methods isa,ibfvs --frames 8
        { note isa_ibfvs; echo; python3 bench/tables.py isa-ibfvs "$WORK/isa_ibfvs.csv"; } > "$WORK/block"
        readme_block isa_ibfvs "$WORK/block" ;;
    hybrid)
        bench_table hybrid --methods hybrid --lengths 21,51,101 --triangles 10000,1000000 \
            --sizes 512x512,1024x1024,1920x1080 --dynamic-only --camera paraview --frames 3 ;;
    gl_paths)
        bench_table gl_paths --gl-paths fragment,compute --triangles 10000,220000 --sizes 512x512,1024x1024 \
            --grids 256 --lengths 31 --frames 8 ;;
    surface_raster)
        bench_table surface_raster --methods isa,hybrid --surface-rasters gl,compute --triangles 60000,120000,220000,1000000 \
            --sizes 512x512,1024x1024 --grids 256 --lengths 31 --dynamic-only --frames 5 ;;
    paraview)
        if ! command -v pvbatch > /dev/null; then
            echo "bench-tables: paraview skipped: ParaView is not installed (bench/paraview/setup.sh installs it);" \
                 "doc/bench/hybrid_vs_paraview_$R.md keeps its last measurement" >&2
            continue
        fi
        args="--triangles 10000,1000000 --sizes 512x512,1024x1024,1920x1080 --steps 10,25,50 --frames 3"
        start_load=$(load)
        # shellcheck disable=SC2086
        OUT="$WORK/paraview" bench/paraview/compare.sh $args > "$WORK/ratio.md"
        {
            echo "<!-- scripts/bench-tables.sh: bench/paraview/compare.sh $args -->"
            echo "Machine: $MACHINE; commit $COMMIT, $(date -u +%Y-%m-%d); load average $start_load at the start," \
                 "$(load) at the end. ParaView (Debian package): $(dpkg-query -W -f='${Version}' paraview 2>/dev/null || echo unknown)."
            echo
            cat "$WORK/ratio.md"
        } | publish "doc/bench/hybrid_vs_paraview_$R.md"
        { note paraview; echo; cat "$WORK/ratio.md"; echo; python3 bench/tables.py paraview-summary "$WORK/ratio.md"; } \
            > "$WORK/block"
        readme_block paraview "$WORK/block" ;;
    viewer)
        input=${VIEWER_INPUT:-$ROOT/../shared/data/windAroundBuildings_wss.vtp}
        if [ ! -f "$input" ] || ! command -v xvfb-run > /dev/null; then
            echo "bench-tables: viewer skipped: needs xvfb-run and $input (VIEWER_INPUT);" \
                 "doc/bench/viewer_$R.txt keeps its last measurement" >&2
            continue
        fi
        { header "bench/viewer/run.sh $input"; FLOWSURF=$F bench/viewer/run.sh "$input"; echo "# load average at the end: $(load)"; } \
            > "$WORK/viewer.txt"
        publish "doc/bench/viewer_$R.txt" < "$WORK/viewer.txt" ;;
    esac
done
