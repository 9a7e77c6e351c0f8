# Sourced by scripts/bench-check.sh and scripts/bench-tables.sh: what a timing was taken on.
#   bench_renderer FLOWSURF    the GL renderer flowsurf gets here (from a tiny `bench` run)
#   bench_machine RENDERER     "CPU model, N cores, RENDERER"
#   bench_commit               "abc1234" or "abc1234 (with uncommitted changes)"
#   bench_family               the CPU's maker and family, e.g. "intel-xeon", "amd-epyc"
#   bench_baseline             the speed check's baseline for this CPU family
#                              (bench/baseline/llvmpipe-FAMILY.csv), else bench/baseline/llvmpipe.csv

bench_renderer() {
    "$1" bench --methods ibfvs --triangles 8 --sizes 64x64 --frames 1 --dynamic-only --no-stage-times |
        sed -n '1s/^flowsurf bench on \(.*\) (ms per frame.*$/\1/p'
}

bench_machine() {
    echo "$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores, $1"
}

bench_commit() {
    local c
    c=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
    git diff --quiet HEAD -- . ':!doc/bench' ':!README.md' ':!docs/performance.md' ':!bench/baseline' 2>/dev/null || c="$c (with uncommitted changes)"
    echo "$c"
}

# llvmpipe's methods do not keep their proportions across CPU families (ISA and IBFVS 1.3-1.7x
# slower on an AMD EPYC VM than on an Intel Xeon one against the same calibration frame, the
# hybrid 1.0-1.4x), so the speed check compares with a baseline of the same family.
bench_family() {
    grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/([^)]*)//g' | tr 'A-Z' 'a-z' |
        grep -oE '[a-z]+' | grep -vxE 'processor|cpu|core' | head -n2 | paste -sd-
}

bench_baseline() {
    local f
    f="bench/baseline/llvmpipe-$(bench_family).csv"
    if [ -f "$f" ]; then echo "$f"; else echo bench/baseline/llvmpipe.csv; fi
}
