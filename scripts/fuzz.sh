#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang with ASan + UBSan), writes their seed
# corpora (fuzz/make_seeds.py) and runs each target on one core.
#   scripts/fuzz.sh                      every target, seed 1, a fixed number of executions
#                                        (what CI runs: the same inputs on every machine, so a
#                                        run that passed here passes there)
#   scripts/fuzz.sh --runs 1000000       every target for 1M executions, random seed
#   scripts/fuzz.sh --time 3600 fuzz_ply one target for an hour, random seed (a long run:
#                                        add what it finds to fuzz/make_seeds.py as a regression)
# Corpora grow in build-fuzz/corpus/<target>/; crashes land in build-fuzz/crashes/.
# Exit status: non-zero if a target found a crash, leak or undefined behaviour.
set -euo pipefail
cd "$(dirname "$0")/.."
budget=(-runs=${FUZZ_RUNS:-300000} -seed=1)
# fuzz_reader reads every input in the reader process (a round trip, and a second or two
# of CPU for an input that spins a reader): fewer runs by default, and a wall-clock limit
# per input a loaded machine cannot reach (the reader's own CPU limit is what must stop an
# input; fuzz_reader.cpp fails on one stopped by the library's deadline instead).
reader_budget=(-runs=${FUZZ_READER_RUNS:-1000} -seed=1)
targets=()
while [ $# -gt 0 ]; do
    case "$1" in
        --runs) budget=(-runs="$2"); reader_budget=("${budget[@]}"); shift 2 ;;
        --time) budget=(-max_total_time="$2"); reader_budget=("${budget[@]}"); shift 2 ;;
        *) targets+=("$1"); shift ;;
    esac
done
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_ply fuzz_obj fuzz_reader fuzz_camera_path fuzz_dye_file fuzz_config fuzz_event_log fuzz_options)
B=build-fuzz
werror=OFF
[ "${CI:-}" = true ] && werror=ON  # CI builds warning-free (clang's warnings here)
CC=clang CXX=clang++ cmake -S fuzz -B $B -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFLOWSURF_WERROR=$werror > /dev/null
cmake --build $B -j"${JOBS:-2}" --target "${targets[@]}"
python3 fuzz/make_seeds.py $B/seeds
mkdir -p $B/crashes
for t in "${targets[@]}"; do
    mkdir -p $B/corpus/$t
    run=("${budget[@]}" -timeout=10)
    [ "$t" = fuzz_reader ] && run=("${reader_budget[@]}" -timeout=60)
    echo "== $t ${run[*]}"
    rc=0
    $B/$t "${run[@]}" -max_len=65536 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix=$B/crashes/$t- $B/corpus/$t $B/seeds/$t > $B/$t.log 2>&1 || rc=$?
    grep -E "^(#[0-9]+[[:space:]]+DONE|stat::number_of_executed_units|stat::peak_rss_mb|==[0-9]+==ERROR|SUMMARY)" $B/$t.log || true
    [ $rc -eq 0 ] || { echo "$t: FAILED (log $B/$t.log, input in $B/crashes/)"; exit 1; }
done
