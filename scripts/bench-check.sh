#!/usr/bin/env bash
# The speed check: a fixed set of `flowsurf bench` rows against a committed baseline taken
# on this kind of machine (bench/baseline/llvmpipe-FAMILY.csv for this CPU family, e.g.
# amd-epyc, else bench/baseline/llvmpipe.csv: bench/machine.sh's bench_baseline). Fails (exit 1) when a row is more
# than THRESHOLD (2) x slower than its baseline on an equally fast machine, or a method's rows
# are METHOD_THRESHOLD (1.5) x slower on their geometric mean: a method made 2x slower is
# slower in all its 8 rows, and their mean carries about a third of one row's noise.
#
#   scripts/bench-check.sh                     check (needs build/apps/flowsurf: scripts/build.sh)
#   scripts/bench-check.sh --update-baseline   measure and write this CPU family's baseline
#                                              (bench/baseline/llvmpipe-FAMILY.csv), on purpose
#
# Rows: ISA (R = 256), IBFVS and the hybrid (L = 31), static and dynamic case, 10k and 220k
# triangles, 512x512, every GL path (fragment, compute), whole frames (no per-stage pass).
# Noise: each row is the median of PASSES runs of the whole set (interleaved, so a burst of
# load hits different rows each time); the methods with a failing row run RETRY_PASSES more
# times and are judged again on the median of all their runs. Machine: every run also times
# a fixed GL frame no flowsurf change touches (`bench --calibration`); each row's ratio is
# divided by that frame's ratio (bench/check/compare.py), so a machine or a moment of load
# that is 2x slower than the baseline's is not a regression.
#
# Environment: FLOWSURF (default build/apps/flowsurf), BASELINE (this CPU family's, above),
# THRESHOLD (2), METHOD_THRESHOLD (1.5), PASSES (3), RETRY_PASSES (2), FRAMES (8 per row),
# BENCH_CHECK_SLOWDOWN=METHOD:K renders every frame of METHOD K times: proves the check fails.
set -euo pipefail
cd "$(dirname "$0")/.."
F=${FLOWSURF:-build/apps/flowsurf}
THRESHOLD=${THRESHOLD:-2}
METHOD_THRESHOLD=${METHOD_THRESHOLD:-1.5}
PASSES=${PASSES:-3}
RETRY_PASSES=${RETRY_PASSES:-2}
FRAMES=${FRAMES:-8}
COMPARE=bench/check/compare.py
. bench/machine.sh
ROWS=(--triangles 10000,220000 --sizes 512x512 --grids 256 --lengths 31 --gl-paths fragment,compute
      --no-stage-times --calibration --frames "$FRAMES")
update=0
case "${1:-}" in
    --update-baseline) update=1 ;;
    "") ;;
    *) echo "usage: scripts/bench-check.sh [--update-baseline]" >&2; exit 2 ;;
esac
if [ "$update" = 1 ]; then BASELINE=${BASELINE:-bench/baseline/llvmpipe-$(bench_family).csv}; fi
BASELINE=${BASELINE:-$(bench_baseline)}
[ -x "$F" ] || { echo "bench-check: $F not found: build first (scripts/build.sh)" >&2; exit 2; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
start=$(date +%s)
# Other jobs on the cores slow the rows unevenly (the calibration frame does not follow
# every method), so a busy machine is said out loud, above all when taking a baseline.
busy() {
    awk -v n="$(nproc)" '$1 > n { printf "bench-check: NOTE: load average %s on %d cores: other jobs share the CPU, ratios vary more than on a quiet machine%s\n", $1, n, extra }' \
        extra="$1" /proc/loadavg
}

# One run of the rows of METHODS (comma list) into $WORK/run<N>.csv; prints its table.
runs=0
run() {
    runs=$((runs + 1))
    local slow=()
    [ -z "${BENCH_CHECK_SLOWDOWN:-}" ] || slow=(--slowdown "$BENCH_CHECK_SLOWDOWN")
    echo "# run $runs: $F bench --methods $1 ${ROWS[*]} ${slow[*]}"
    "$F" bench --methods "$1" "${ROWS[@]}" "${slow[@]}" --csv "$WORK/run$runs.csv" | tee "$WORK/run$runs.txt"
}

for ((k = 0; k < PASSES; k++)); do run isa,ibfvs,hybrid; done
machine=$(bench_machine "$(sed -n '1s/^flowsurf bench on \(.*\) (ms per frame.*$/\1/p' "$WORK/run1.txt")")
commit=$(bench_commit)

if [ "$update" = 1 ]; then
    [ -z "${BENCH_CHECK_SLOWDOWN:-}" ] || { echo "bench-check: no baseline with BENCH_CHECK_SLOWDOWN set" >&2; exit 2; }
    mkdir -p "$(dirname "$BASELINE")"
    {
        echo "# flowsurf speed-check baseline: scripts/bench-check.sh --update-baseline, median of $PASSES runs per row"
        echo "# machine: $machine"
        echo "# commit: $commit, $(date -u +%Y-%m-%d), load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
        python3 "$COMPARE" --median "$WORK"/run*.csv
    } > "$WORK/baseline.csv"
    mv "$WORK/baseline.csv" "$BASELINE"
    echo "bench-check: wrote $BASELINE ($machine, commit $commit) in $(($(date +%s) - start)) s"
    busy "; take the baseline again on a quiet machine"
    exit 0
fi

[ -f "$BASELINE" ] || { echo "bench-check: no baseline $BASELINE (scripts/bench-check.sh --update-baseline)" >&2; exit 2; }
rc=0
failing=$(python3 "$COMPARE" "$BASELINE" "$WORK"/run*.csv --threshold "$THRESHOLD" \
    --method-threshold "$METHOD_THRESHOLD" --failing-methods) || rc=$?
[ "$rc" -le 1 ] || exit "$rc"
if [ "$rc" = 1 ] && [ -n "$failing" ] && [ "$RETRY_PASSES" -gt 0 ]; then
    echo "# $failing over the thresholds: $RETRY_PASSES more runs of those methods"
    for ((k = 0; k < RETRY_PASSES; k++)); do run "$failing"; done
fi
echo
echo "bench-check: $machine, commit $commit, load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "baseline $BASELINE: $(sed -n 's/^# machine: //p' "$BASELINE"); $(sed -n 's/^# commit: //p' "$BASELINE")"
rc=0
python3 "$COMPARE" "$BASELINE" "$WORK"/run*.csv --threshold "$THRESHOLD" --method-threshold "$METHOD_THRESHOLD" || rc=$?
busy ""
echo "bench-check: $runs runs in $(($(date +%s) - start)) s: $([ "$rc" = 0 ] && echo passed || echo FAILED)"
exit "$rc"
