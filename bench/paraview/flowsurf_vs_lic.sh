#!/usr/bin/env bash
# FlowSurf (hybrid) against ParaView's Surface LIC inside ParaView, at 1, 2, ... MPI ranks:
# ms per render and the seam difference of the N-rank image against the 1-rank image
# (flowsurf_vs_lic.py renders, compare_ranks.py compares; see bench/paraview/README.md).
#
#   bench/paraview/flowsurf_vs_lic.sh [--ranks 1,2,4] [--meshes sphere:37056,sphere1m:1000000]
#       [--size 400x400] [--steps 15] [--frames 9] [--out DIR] [--csv FILE]
#
# --out (default out/paraview_ranks) gets np{N}/ (PNGs, timings.json, the pvbatch log), diff/
# (|N-rank - 1-rank| x 8 per mesh and method), results.csv and results.md; --csv also copies
# the CSV there. The plugin (FLOWSURF_PLUGIN, default the one under build-paraview/) is copied
# into OUT first, so a rebuild during the run does not change it mid-way.
# Environment: FLOWSURF_PLUGIN, PVPYTHON_PREFIX (see setup.sh), XVFB_SCREEN (1280x1024x24),
# BENCH_NICE (e.g. -10, root only), BENCH_TIMEOUT (seconds per rank count, default 900) and
# BENCH_RETRIES (default 1): a run that fails or hangs is killed and tried again; one that never
# finishes leaves out its rows and the script exits 1. ParaView 5.11 itself hangs now and then in
# the first render at 4 ranks on 2 cores, with or without the plugin loaded (README).
# xvfb-run starts its search for a free display at a random number from 200 (two xvfb-run -a
# starting at 99 at once on a shared machine collided here).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
RANKS=1,2,4
MESHES=sphere:37056,sphere1m:1000000
SIZE=400x400
STEPS=15
FRAMES=9
OUT="$ROOT/out/paraview_ranks"
CSV=""
while [ $# -gt 0 ]; do
  case "$1" in
    --ranks) RANKS=$2; shift 2 ;;
    --meshes) MESHES=$2; shift 2 ;;
    --size) SIZE=$2; shift 2 ;;
    --steps) STEPS=$2; shift 2 ;;
    --frames) FRAMES=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --csv) CSV=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
case ",$RANKS," in *,1,*) ;; *) echo "--ranks must include 1 (the reference image)" >&2; exit 2 ;; esac

eval "$("$HERE/setup.sh")"
. "$HERE/../../scripts/xvfb-args.sh"
"$ROOT/scripts/apt-install.sh" openmpi-bin python3-pil
PLUGIN="${FLOWSURF_PLUGIN:-$(find "$ROOT/build-paraview" -name FlowSurf.so 2>/dev/null | head -n1 || true)}"
[ -f "$PLUGIN" ] || { echo "FlowSurf.so not found: scripts/build-paraview-plugin.sh, or set FLOWSURF_PLUGIN" >&2; exit 1; }
mkdir -p "$OUT/plugin"
cp "$PLUGIN" "$OUT/plugin/FlowSurf.so"
{
  echo "plugin: $PLUGIN"
  stat -c 'modified: %y  size: %s' "$PLUGIN"
  sha256sum "$OUT/plugin/FlowSurf.so"
  git -C "$ROOT" log -1 --format='bench commit: %h %s' 2>/dev/null || true
  # the checkout the plugin was built in, as it is now (the build may be older, or dirty)
  git -C "$(dirname "$PLUGIN")" log -1 --format='plugin checkout HEAD now: %h %ci %s' 2>/dev/null || true
  echo "cores: $(nproc)  load at start: $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$OUT/plugin/info.txt" >&2

# --bind-to none: Open MPI pins each rank to one core by default when ranks <= cores, which
# would leave llvmpipe's threads one core. --oversubscribe: more ranks than cores (-np 4 here).
MPI=(mpiexec --bind-to none --oversubscribe)
[ "$(id -u)" -eq 0 ] && MPI+=(--allow-run-as-root)
NICE=()
[ -n "${BENCH_NICE:-}" ] && NICE=(nice -n "$BENCH_NICE")
failed=0
for n in ${RANKS//,/ }; do
  mkdir -p "$OUT/np$n"
  for attempt in $(seq 0 "${BENCH_RETRIES:-1}"); do
    [ "$attempt" -eq 0 ] || echo "# $n rank(s) hung or failed: attempt $((attempt + 1))" >&2
    echo "# $n rank(s): ${MPI[*]} -np $n pvbatch flowsurf_vs_lic.py --meshes $MESHES ..." >&2
    # /usr/bin/time per rank: each rank's peak memory ("maxrss_kb") lands in the log.
    "${NICE[@]}" xvfb-run -a -n "$((200 + RANDOM % 600))" -s "$FLOWSURF_XVFB_ARGS" \
      timeout -k 10 "${BENCH_TIMEOUT:-900}" "${MPI[@]}" -np "$n" -x PYTHONPATH \
      /usr/bin/time -f 'rank maxrss_kb %M wall_s %e' \
      pvbatch "$HERE/flowsurf_vs_lic.py" --plugin "$OUT/plugin/FlowSurf.so" --out "$OUT/np$n" \
      --meshes "$MESHES" --size "$SIZE" --steps "$STEPS" --frames "$FRAMES" \
      2>&1 | tee "$OUT/np$n/pvbatch.log" | grep -E '^(  |[a-z0-9]+: |rank maxrss|DONE)' >&2 || true
    grep -q '^DONE' "$OUT/np$n/pvbatch.log" && break
    cp "$OUT/np$n/pvbatch.log" "$OUT/np$n/pvbatch.failed$attempt.log"
  done
  if ! grep -q '^DONE' "$OUT/np$n/pvbatch.log"; then
    # A failed or hung rank count (killed after BENCH_TIMEOUT s) leaves out its rows; the
    # 1-rank run is the reference, so without it there is nothing to compare.
    echo "pvbatch at $n ranks failed or hung (see $OUT/np$n/pvbatch.log)" | tee -a "$OUT/plugin/info.txt" >&2
    [ "$n" -ne 1 ] || exit 1
    rm -f "$OUT/np$n/timings.json"
    failed=1
  fi
done
echo "load at end: $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/plugin/info.txt" >&2
/usr/bin/python3 "$HERE/compare_ranks.py" "$OUT" "$OUT/results.csv" "$OUT/diff" >&2
/usr/bin/python3 "$HERE/compare_ranks.py" --markdown "$OUT/results.csv" | tee "$OUT/results.md"
[ -z "$CSV" ] || cp "$OUT/results.csv" "$CSV"
exit "$failed"
