#!/usr/bin/env bash
# FlowSurf's strong scaling on ParaView's engine: ms per render at 1 and 2 ranks,
# FlowSurfParallel tiles against replicate in the same rounds, one llvmpipe thread per rank,
# each rank bound to its own core; the machine's own two-process speedup first.
#
#   bench/paraview/scaling.sh [--triangles 1000000] [--size 1024x1024] [--rounds 5]
#       [--frames 9] [--methods hybrid,isa,ibfvs] [--out DIR] [--ranks-stats 4,8] [--stats-rounds 3]
#       [--fxaa default|on|off]
#
# Per round: 1 rank, 2 ranks tiles, 1 rank with llvmpipe's own 2 threads (LP_NUM_THREADS=2,
# not bound: what the 2 ranks are compared with, right after them), 2 ranks replicate
# (interleaved, so that a drift of the machine's speed touches all alike); after the rounds,
# per --ranks-stats count, oversubscribed runs (the ranks bound round-robin to the cores) with
# FLOWSURF_RANK_STATS (per-rank CPU time and bytes per render; wall time says nothing there),
# after measuring what that oversubscription costs the same work on this machine (I_N): in
# --stats-rounds rounds of 1 rank then N ranks tiles per count (interleaved: each round's sums
# are divided by the same round's 1-rank run; this machine's speed drifts by up to a quarter
# between runs minutes apart), N ranks replicate in the first round only.
# Writes OUT/calibration.txt, OUT/rounds.txt (S_hw before and after each round's 2-rank runs),
# OUT/r<round>/<run>/{timings.json,*.png,pvbatch.log},
# OUT/stats/r<round>/np<N>_<mode>/rank<r>.jsonl and OUT/results.md (scaling_report.py).
# A run is tried up to 3 times; BENCH_TIMEOUT (900 s) bounds one, BENCH_START_TIMEOUT (300 s)
# its wait for the first render (ParaView's start-up hang).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TRIANGLES=1000000
SIZE=1024x1024
ROUNDS=5
FRAMES=9
METHODS=hybrid,isa,ibfvs
OUT="$ROOT/out/paraview_scaling"
STATS_RANKS=""
STATS_ROUNDS=3
FXAA=default
while [ $# -gt 0 ]; do
  case "$1" in
    --triangles) TRIANGLES=$2; shift 2 ;;
    --size) SIZE=$2; shift 2 ;;
    --rounds) ROUNDS=$2; shift 2 ;;
    --frames) FRAMES=$2; shift 2 ;;
    --methods) METHODS=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --ranks-stats) STATS_RANKS=$2; shift 2 ;;
    --stats-rounds) STATS_ROUNDS=$2; shift 2 ;;
    --fxaa) FXAA=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
eval "$("$HERE/setup.sh")"
. "$ROOT/scripts/xvfb-args.sh"
"$ROOT/scripts/apt-install.sh" openmpi-bin bc
PLUGIN="${FLOWSURF_PLUGIN:-$(find "$ROOT/build-paraview" -name FlowSurf.so 2>/dev/null | head -n1 || true)}"
FLOWSURF="${FLOWSURF_BIN:-$ROOT/build/apps/flowsurf}"
[ -f "$PLUGIN" ] || { echo "FlowSurf.so not found: scripts/build-paraview-plugin.sh, or set FLOWSURF_PLUGIN" >&2; exit 1; }
[ -x "$FLOWSURF" ] || { echo "flowsurf not found: scripts/build.sh, or set FLOWSURF_BIN" >&2; exit 1; }
mkdir -p "$OUT/plugin"
cp "$PLUGIN" "$OUT/plugin/FlowSurf.so"
{
  git -C "$ROOT" log -1 --format='commit: %h %s' 2>/dev/null || true
  echo "cores: $(nproc)  $(grep -m1 'model name' /proc/cpuinfo)"
  echo "load at start: $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$OUT/plugin/info.txt" >&2

export LP_NUM_THREADS=1
# 1. The machine's own two-process speedup: one flowsurf render loop alone, then two at once,
# each on its own core. S_hw = 2 t(one) / t(two at once).
CAL=("$FLOWSURF" bench --methods hybrid --triangles 220000 --sizes 512x512 --lengths 31 --dynamic-only
     --frames 40 --no-stage-times)
one() { local t0; t0=$(date +%s.%N); taskset -c 0 "${CAL[@]}" >/dev/null 2>&1; echo "$(date +%s.%N) - $t0" | bc; }
two() {
  local t0; t0=$(date +%s.%N)
  taskset -c 0 "${CAL[@]}" >/dev/null 2>&1 & taskset -c 1 "${CAL[@]}" >/dev/null 2>&1 & wait
  echo "$(date +%s.%N) - $t0" | bc
}
one >/dev/null  # warm caches
t1a=$(one); t2a=$(two); t1b=$(one); t2b=$(two)
S_HW=$(echo "scale=3; 2 * ($t1a + $t1b) / ($t2a + $t2b)" | bc)
echo "calibration: one copy ${t1a}/${t1b} s, two at once ${t2a}/${t2b} s: two-process speedup S_hw = $S_HW" \
  | tee "$OUT/calibration.txt" >&2
# 2. For the oversubscribed runs (N ranks bound round-robin to these cores): a flowsurf loop the size
# of one rank's share (ISA, TRIANGLES / N at the benchmark's size), its CPU time per copy when
# N copies share the cores against one copy alone, I_N = Σ CPU(N copies) / (N CPU(one)):
# what sharing a core costs the same work here (switches, caches, memory), the scale of the
# ranks' Σ CPU / 1 rank. Each copy bound like the ranks (copy i to core i mod cores, the one
# alone to core 0). Twice each, the sums.
cpu_of() {  # N CORE: CPU seconds (user + system, all threads) of one run of the loop on CORE
  taskset -c "$2" /usr/bin/python3 -c 'import resource, subprocess, sys
subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
r = resource.getrusage(resource.RUSAGE_CHILDREN)
print(r.ru_utime + r.ru_stime)' "$FLOWSURF" bench --methods isa --triangles "$((TRIANGLES / $1))" --sizes "$SIZE" \
    --dynamic-only --frames 20 --no-stage-times
}
for n in ${STATS_RANKS//,/ }; do
  alone=0 shared=0
  for pass in 1 2; do
    alone=$(echo "$alone + $(cpu_of "$n" 0)" | bc)
    for i in $(seq 1 "$n"); do cpu_of "$n" "$((i % $(nproc)))" >"$OUT/plugin/cpu$i.txt" & done
    wait
    shared=$(echo "$shared + $(cat "$OUT"/plugin/cpu[0-9]*.txt | paste -sd+ | bc)" | bc)
    rm -f "$OUT"/plugin/cpu[0-9]*.txt
  done
  echo "oversubscription: $n copies on $(nproc) cores, CPU per copy against one alone: I_$n = $(echo "scale=3; $shared / ($n * $alone)" | bc)" \
    | tee -a "$OUT/calibration.txt" >&2
done

ROOTOK=()
[ "$(id -u)" -eq 0 ] && ROOTOK=(--allow-run-as-root)
BOUND=(mpiexec "${ROOTOK[@]}" --bind-to core --map-by core -x LP_NUM_THREADS -x PYTHONPATH)
FREE=(mpiexec "${ROOTOK[@]}" --bind-to none -x LP_NUM_THREADS -x PYTHONPATH -x FLOWSURF_RANK_STATS)
# The oversubscribed runs: ranks bound round-robin to the cores, several to a core, as the
# 1-rank run of their rounds is bound to one. Unbound, a rank's GL thread and llvmpipe's
# rasteriser thread run on two cores and hand work across them: measured, a 1-rank render
# costs 5-10 % more CPU so (and varies more), which made earlier ratios look lower.
SHARED=(mpiexec "${ROOTOK[@]}" --bind-to core:overload-allowed --map-by core -x LP_NUM_THREADS -x PYTHONPATH
        -x FLOWSURF_RANK_STATS)
run() {  # DIR NP PARALLEL MPIEXEC [ARGS...]
  local dir=$1 np=$2 mode=$3
  shift 3
  mkdir -p "$dir"
  local attempt pid waited
  for attempt in 1 2 3; do
    # In its own session, so that a hang is ended with everything it started.
    setsid xvfb-run -a -n "$((200 + RANDOM % 600))" -s "$FLOWSURF_XVFB_ARGS" \
      timeout -k 10 "${BENCH_TIMEOUT:-900}" "$@" -np "$np" \
      pvbatch --force-offscreen-rendering "$HERE/scaling.py" --plugin "$OUT/plugin/FlowSurf.so" --out "$dir" \
      --triangles "$TRIANGLES" --size "$SIZE" --methods "$METHODS" --parallel "$mode" --frames "$FRAMES" --fxaa "$FXAA" \
      >"$dir/pvbatch.log" 2>&1 &
    pid=$!
    # ParaView's own start-up hang (rank 0 in IceT's MPI_Comm_dup inside the first Render,
    # the others in ProcessRMIs; seen before -noreset, not in 50 runs of startup_hang.sh
    # since): no first render after BENCH_START_TIMEOUT seconds ends the run, which is tried again.
    # A rank that dies on a signal is ended at once too: VTK's handler, printing its stack
    # after a heap check failed, can wait forever on the allocator's lock.
    waited=0
    while kill -0 "$pid" 2>/dev/null; do
      if grep -q 'Loguru caught a signal' "$dir/pvbatch.log"; then
        echo "# $dir: a rank died on a signal" >&2
        pkill -KILL -s "$pid" 2>/dev/null  # the session: timeout keeps its own process group
        break
      fi
      if [ "$waited" -ge "${BENCH_START_TIMEOUT:-300}" ] && ! grep -q '^FIRST_RENDER' "$dir/pvbatch.log"; then
        echo "# $dir: no first render after $waited s (ParaView's start-up hang)" >&2
        pkill -KILL -s "$pid" 2>/dev/null
        break
      fi
      sleep 5
      waited=$((waited + 5))
    done
    wait "$pid" 2>/dev/null || true
    grep -q '^DONE' "$dir/pvbatch.log" && { grep -E 'median' "$dir/pvbatch.log" >&2; return 0; }
    cp "$dir/pvbatch.log" "$dir/pvbatch.failed$attempt.log"  # kept: the next attempt writes pvbatch.log
    echo "# $dir: failed or hung (attempt $attempt; its log: pvbatch.failed$attempt.log)" >&2
  done
  return 1
}
# The two-process speedup again around each round's 2-rank runs (before and after): a VM's
# second core can slow down for minutes (another guest), which only the 2-rank runs feel.
round_shw() {  # ROUND WHEN
  local a b
  a=$(one); b=$(two)
  echo "round $1 $2: S_hw = $(echo "scale=3; 2 * $a / $b" | bc)" | tee -a "$OUT/rounds.txt" >&2
}
rm -f "$OUT/rounds.txt"
for r in $(seq 1 "$ROUNDS"); do
  echo "== round $r ($(cut -d' ' -f1 /proc/loadavg))" >&2
  run "$OUT/r$r/np1" 1 tiles "${BOUND[@]}" || true
  round_shw "$r" before
  run "$OUT/r$r/np2_tiles" 2 tiles "${BOUND[@]}" || true
  LP_NUM_THREADS=2 run "$OUT/r$r/np1_lp2" 1 tiles "${FREE[@]}" || true
  run "$OUT/r$r/np2_replicate" 2 replicate "${BOUND[@]}" || true
  round_shw "$r" after
done
export FLOWSURF_RANK_STATS
if [ -n "$STATS_RANKS" ]; then rm -rf "$OUT/stats"; fi
stats_run() {  # ROUND NAME NP MODE: one run with FLOWSURF_RANK_STATS into OUT/stats/r<ROUND>/<NAME>
  local dir="$OUT/stats/r$1/$2" np=$3 mode=$4 extra=()
  mkdir -p "$dir"
  if [ "$np" -gt 1 ]; then extra=(--oversubscribe --mca mpi_yield_when_idle 1); fi
  FLOWSURF_RANK_STATS="$dir" run "$dir/run" "$np" "$mode" "${SHARED[@]}" "${extra[@]}" || true
}
for r in $(seq 1 "$STATS_ROUNDS"); do
  [ -n "$STATS_RANKS" ] || break
  echo "== stats round $r: 1 rank, then ${STATS_RANKS} ranks oversubscribed (FLOWSURF_RANK_STATS)" >&2
  stats_run "$r" np1 1 tiles
  for n in ${STATS_RANKS//,/ }; do
    stats_run "$r" "np${n}_tiles" "$n" tiles
    if [ "$r" -eq 1 ]; then stats_run "$r" "np${n}_replicate" "$n" replicate; fi
  done
done
echo "load at end: $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/plugin/info.txt" >&2
/usr/bin/python3 "$HERE/scaling_report.py" "$OUT" | tee "$OUT/results.md"
