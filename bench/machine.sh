# Sourced by scripts/bench-check.sh and scripts/bench-tables.sh: what a timing was taken on.
#   bench_renderer FLOWSURF    the GL renderer flowsurf gets here (from a tiny `bench` run)
#   bench_machine RENDERER     "CPU model, N cores, RENDERER"
#   bench_commit               "abc1234" or "abc1234 (with uncommitted changes)"

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
