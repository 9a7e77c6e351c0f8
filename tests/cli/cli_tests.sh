#!/usr/bin/env bash
# Command-line tests: the documented commands work, bad input gets a one-line message
# naming the file and the problem, a distinct non-zero exit code, and no partial output.
set -u
FLOWSURF=${1:?usage: cli_tests.sh path/to/flowsurf [path/to/flowsurf_make_cgns_cases]}
MAKE_CGNS=${2:-}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
pass=0
fail=0

ok()   { pass=$((pass + 1)); echo "ok   - $1"; }
bad()  { fail=$((fail + 1)); echo "FAIL - $1"; }

# expect_fail NAME CODE PATTERN OUTPUT -- ARGS...: exit code CODE, stderr matches PATTERN,
# OUTPUT (a file) does not exist afterwards.
expect_fail() {
    local name=$1 code=$2 pattern=$3 out=$4
    shift 5
    local err rc
    err=$("$FLOWSURF" "$@" 2>&1 >/dev/null)
    rc=$?
    if [ "$rc" -ne "$code" ]; then bad "$name: exit $rc, expected $code ($err)"; return; fi
    if ! grep -qE -- "$pattern" <<<"$err"; then bad "$name: message '$err' lacks /$pattern/"; return; fi
    if [ "$(wc -l <<<"$err")" -gt 2 ]; then bad "$name: message longer than expected: $err"; return; fi
    if [ -n "$out" ] && ls "$out"* >/dev/null 2>&1; then bad "$name: left output $(ls "$out"*)"; return; fi
    ok "$name"
}

# --- files that go wrong --------------------------------------------------------
: > "$WORK/empty.vtp"
printf '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1">\n<PolyData><Piece NumberOfPoints="4"' > "$WORK/truncated.vtp"
head -c 3000 /dev/urandom > "$WORK/garbage.vtp"
printf 'solid x\nendsolid x\n' > "$WORK/nogeometry.stl"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' > "$WORK/badindex.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$WORK/plain.obj"
echo "1 2 3" > "$WORK/a.xyz"

expect_fail "missing file"        3 "nosuch.vtp"           "$WORK/o1.png" -- render "$WORK/nosuch.vtp" -o "$WORK/o1.png" -q
expect_fail "empty file"          4 "empty.vtp"            "$WORK/o2.png" -- render "$WORK/empty.vtp" -o "$WORK/o2.png" -q
expect_fail "truncated file"      4 "truncated.vtp"        "$WORK/o3.png" -- render "$WORK/truncated.vtp" -o "$WORK/o3.png" -q
expect_fail "garbage file"        4 "garbage.vtp"          "$WORK/o4.png" -- render "$WORK/garbage.vtp" -o "$WORK/o4.png" -q
# An EnSight count beyond the file: VTK's reader loops until the reader's CPU limit stops it.
mkdir -p "$WORK/ens"
printf 'FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: m.geo\n' > "$WORK/ens/t.case"
printf 'x\ny\nnode id off\nelement id off\npart\n1\ns\ncoordinates\n4\n0\n1\n1\n0\n0\n0\n1\n1\n0\n0\n0\n0\nnsided\n2\n4\n4\n1 2 3 4\n#\n' > "$WORK/ens/m.geo"
expect_fail "reader out of CPU"   4 "t.case: the reader used more than 1 s of CPU" "$WORK/o4b.png" -- render "$WORK/ens/t.case" -o "$WORK/o4b.png" -q
expect_fail "no triangles"        4 "nogeometry.stl"       "$WORK/o5.png" -- render "$WORK/nogeometry.stl" -o "$WORK/o5.png" -q
expect_fail "index out of range"  4 "badindex.obj"         "$WORK/o6.png" -- render "$WORK/badindex.obj" -o "$WORK/o6.png" -q
expect_fail "geometry only"       5 "vector"               "$WORK/o7.png" -- render "$WORK/plain.obj" -o "$WORK/o7.png" -q
expect_fail "unknown extension"   4 "\.xyz"                "$WORK/o8.png" -- render "$WORK/a.xyz" -o "$WORK/o8.png" -q
expect_fail "missing field"       5 "no vector field 'p'"  "$WORK/o9.png" -- render builtin:sphere --field p -o "$WORK/o9.png" -q
expect_fail "missing colour array" 5 "--color-by epsilon: .*no point array 'epsilon' \(available: .*velocity\)" "$WORK/o9b.png" -- render builtin:sphere --color-by epsilon -o "$WORK/o9b.png" -q
expect_fail "missing mask array"  5 "--mask-by k:x: .*no point array 'k'" "$WORK/o9c.png" -- render builtin:sphere --mask-by k:x -o "$WORK/o9c.png" -q
expect_fail "unknown builtin"     2 "unknown built-in"     "$WORK/oa.png" -- render builtin:nosuch -o "$WORK/oa.png" -q
expect_fail "zero-size image"     2 "--size"               "$WORK/ob.png" -- render builtin:sphere --size 0x100 -o "$WORK/ob.png" -q
expect_fail "absurd image size"   2 "out of range"         "$WORK/oc.png" -- render builtin:sphere --size 100000x100000 -o "$WORK/oc.png" -q
expect_fail "unknown method"      2 "method"               "$WORK/od.png" -- render builtin:sphere --method lic -o "$WORK/od.png" -q
expect_fail "bad output kind"     2 "\.gif"                "$WORK/oe.gif" -- render builtin:sphere -o "$WORK/oe.gif" -q
expect_fail "unwritable output"   3 "nodir"                "$WORK/nodir/of.png" -- render builtin:sphere --size 64x64 --frames 2 -o "$WORK/nodir/of.png" -q
expect_fail "bad dye point"       2 "--dye"                "$WORK/og.png" -- render builtin:sphere --dye 1,2 -o "$WORK/og.png" -q
expect_fail "negative dye radius" 2 "--dye.*radius"        "$WORK/oh.png" -- render builtin:sphere --dye 0,0,1:-1 -o "$WORK/oh.png" -q
expect_fail "bad dye release"     2 "--dye-release"        "$WORK/oi.png" -- render builtin:sphere --dye-release=-3 -o "$WORK/oi.png" -q
expect_fail "missing dye file"    3 "nosuch.json"          "$WORK/oj.png" -- render builtin:sphere --dye-file "$WORK/nosuch.json" -o "$WORK/oj.png" -q
echo '{"keyframes": [{"frame": 0}]}' > "$WORK/noeye.json"
echo '{"keyframes": [' > "$WORK/broken.json"
expect_fail "camera path no eye"  4 "noeye.json: keyframe 0" "$WORK/og.png" -- render builtin:sphere --camera-path "$WORK/noeye.json" -o "$WORK/og.png" -q
expect_fail "camera path broken"  4 "broken.json"          "$WORK/oh.png" -- render builtin:sphere --camera-path "$WORK/broken.json" -o "$WORK/oh.png" -q
expect_fail "time-step with time"  2 "time-step"            "$WORK/oi.png" -- render builtin:double-gyre --time-step 2 --time 0:5 -o "$WORK/oi.png" -q
expect_fail "time-step too big"   2 "time step"            "$WORK/oj.png" -- render builtin:double-gyre --time-step 99 -o "$WORK/oj.png" -q
expect_fail "bad time range"      2 "START:END"            "$WORK/ok.png" -- render builtin:double-gyre --time 5 -o "$WORK/ok.png" -q
expect_fail "info missing file"   3 "nosuch.vtu"           "" -- info "$WORK/nosuch.vtu"

# A numbered series whose middle step is corrupt: stops naming that step; the frames
# written before it are complete files.
plane_vtp() {  # $1: file, $2: x velocity
    cat > "$1" <<VTP
<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
<PolyData><Piece NumberOfPoints="4" NumberOfPolys="2">
<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 1 1 0 0 1 0</DataArray></Points>
<PointData><DataArray type="Float32" Name="U" NumberOfComponents="3" format="ascii">$2 0 0 $2 0 0 $2 0 0 $2 0 0</DataArray></PointData>
<Polys><DataArray type="Int32" Name="connectivity" format="ascii">0 1 2 0 2 3</DataArray>
<DataArray type="Int32" Name="offsets" format="ascii">3 6</DataArray></Polys>
</Piece></PolyData></VTKFile>
VTP
}
mkdir -p "$WORK/series" "$WORK/seqout"
for i in 1 2 3 4 5; do plane_vtp "$WORK/series/s_$i.vtp" "$i"; done
head -c 200 "$WORK/series/s_1.vtp" > "$WORK/series/s_3.vtp"
err=$("$FLOWSURF" render "$WORK/series/s_%d.vtp" --frames-per-step 2 --frames 8 --size 32x32 -q -o "$WORK/seqout/f_%02d.png" 2>&1)
rc=$?
if [ "$rc" -eq 4 ] && grep -q "s_3.vtp" <<<"$err" && [ -s "$WORK/seqout/f_00.png" ] \
   && ! ls "$WORK/seqout"/*.tmp* >/dev/null 2>&1; then
    ok "corrupt step in a series is named; earlier frames complete"
else
    bad "corrupt step in a series (rc $rc: $err)"
fi
# The hybrid reads steps ahead of the frame (its pathline window): the same error, no output.
err=$("$FLOWSURF" render "$WORK/series/s_%d.vtp" --method hybrid --frames-per-step 2 --frames 8 --size 32x32 -q \
      -o "$WORK/hyb_corrupt.png" 2>&1)
rc=$?
if [ "$rc" -eq 4 ] && grep -q "s_3.vtp" <<<"$err" && [ ! -e "$WORK/hyb_corrupt.png" ]; then
    ok "hybrid pathlines: corrupt step ahead is named, no output"
else
    bad "hybrid pathlines over a corrupt step (rc $rc: $err)"
fi
plane_vtp "$WORK/series/s_3.vtp" 3
if "$FLOWSURF" render "$WORK/series/s_*.vtp" --method hybrid --frames-per-step 2 --frames 8 --size 32x32 -q \
   -o "$WORK/hyb_series.png" && [ -s "$WORK/hyb_series.png" ]; then
    ok "hybrid pathlines over a file series"
else
    bad "hybrid pathlines over a file series"
fi
expect_fail "negative trace dt"   2 "trace-dt"             "$WORK/ol.png" -- render builtin:double-gyre --method hybrid --trace-dt -1 -o "$WORK/ol.png" -q
if "$FLOWSURF" render "$WORK/series/s_*.vtp" --frames 8 --size 32x32 -q -o "$WORK/series.png" && [ -s "$WORK/series.png" ]; then
    ok "render a numbered file series (glob)"
else
    bad "render a numbered file series (glob)"
fi

# --- commands that must work ------------------------------------------------------
if "$FLOWSURF" render --list-builtins | grep -q sphere; then ok "list builtins"; else bad "list builtins"; fi
if "$FLOWSURF" render --help | grep -q -- "--grid-res"; then ok "help lists options"; else bad "help lists options"; fi
if "$FLOWSURF" info builtin:tori | grep -q triangles; then ok "info builtin"; else bad "info builtin"; fi
# The table's read options of kind flag are flags for info too, as for render.
if "$FLOWSURF" info builtin:tori --foam-zero-time | grep -q triangles; then ok "info read flag"; else bad "info read flag"; fi
if "$FLOWSURF" render builtin:sphere --size 96x64 --frames 3 -q -o "$WORK/s.png" --flow-texture "$WORK/f.png" \
   && [ -s "$WORK/s.png" ] && [ -s "$WORK/f.png" ] && ! ls "$WORK"/*.tmp* >/dev/null 2>&1; then
    ok "render png + flow texture"
else
    bad "render png + flow texture"
fi
# --frames N writes N frames: seq_000 .. seq_002, no seq_003.
if "$FLOWSURF" render builtin:sphere --size 64x64 --frames 3 -q -o "$WORK/seq_%03d.png" && [ -s "$WORK/seq_002.png" ] \
   && [ "$(ls "$WORK"/seq_*.png | wc -l)" -eq 3 ]; then
    ok "render png sequence: --frames 3 writes 3 files"
else
    bad "render png sequence: --frames 3 wrote $(ls "$WORK"/seq_*.png 2>/dev/null | wc -l) files"
fi
expect_fail "log scale, range not positive" 2 "color-scale log: --color-range -1:5" "$WORK/lg.png" -- render builtin:sphere --color-scale log --color-range=-1:5 -o "$WORK/lg.png" -q
expect_fail "movie of no frames"  2 "frames 0"             "$WORK/none.mp4" -- render builtin:sphere --frames 0 -o "$WORK/none.mp4" -q
echo '{"keyframes": [{"frame": 0, "eye": [0,0,4]}, {"frame": 3, "eye": [3,1,2.5], "fov": 25}]}' > "$WORK/path.json"
if "$FLOWSURF" render builtin:sphere --camera-path "$WORK/path.json" --size 64x64 --frames 3 -q -o "$WORK/p.png" && [ -s "$WORK/p.png" ]; then
    ok "render along a camera path"
else
    bad "render along a camera path"
fi
if "$FLOWSURF" compare builtin:sphere --methods isa,ibfvs --size 64x64 --frames 3 -q -o "$WORK/c.png" && [ -s "$WORK/c.png" ]; then
    ok "compare sheet"
else
    bad "compare sheet"
fi
if "$FLOWSURF" render builtin:piston --frames-per-step 2 --frames 12 --size 64x64 -q -o "$WORK/pist_%02d.png" \
   && [ -s "$WORK/pist_11.png" ] && [ ! -e "$WORK/pist_12.png" ]; then
    ok "render a series with changing topology"
else
    bad "render a series with changing topology"
fi
if "$FLOWSURF" render builtin:double-gyre --method hybrid --time 2:4 --frames 3 --size 64x64 -q -o "$WORK/dg.png" && [ -s "$WORK/dg.png" ]; then
    ok "hybrid over a time range"
else
    bad "hybrid over a time range"
fi
# bench: one row per GL path asked for (auto is the renderer's, run once), the calibration
# row, and the speed check's hidden slowdown refused when malformed.
expect_fail "bench unknown gl path" 2 "gl-paths"            "$WORK/b1.csv" -- bench --gl-paths vulkan --csv "$WORK/b1.csv"
expect_fail "bench bad slowdown"    2 "slowdown: 'hybrid:0'" "$WORK/b2.csv" -- bench --slowdown hybrid:0 --csv "$WORK/b2.csv"
if "$FLOWSURF" bench --methods ibfvs --triangles 8 --sizes 64x64 --frames 1 --gl-paths fragment,compute,auto \
       --calibration --no-stage-times --csv "$WORK/b.csv" >/dev/null &&
   [ "$(cut -d, -f1,7 "$WORK/b.csv" | sort | tr '\n' ' ')" = "calib,- ibfvs,compute ibfvs,compute ibfvs,fragment ibfvs,fragment method,gl_path " ]; then
    ok "bench gl_path column and calibration row"
else
    bad "bench gl_path column and calibration row: $(cut -d, -f1,7 "$WORK/b.csv" 2>&1 | tr '\n' ' ')"
fi
# bench --ranks: a row per rank count and (above one rank) per parallel mode, as threads.
expect_fail "bench unknown parallel mode" 2 "parallel" "$WORK/b3.csv" -- bench --parallel mpi --csv "$WORK/b3.csv"
if "$FLOWSURF" bench --methods isa --grids 128 --triangles 2000 --sizes 64x64 --frames 1 --dynamic-only --no-stage-times \
       --ranks 1,2 --parallel tiles,replicate --csv "$WORK/r.csv" >/dev/null &&
   [ "$(awk -F, '{print $1 "," $(NF-1) "," $NF}' "$WORK/r.csv" | tr '\n' ' ')" = "method,ranks,parallel isa,1,- isa,2,tiles isa,2,replicate " ]; then
    ok "bench --ranks rows"
else
    bad "bench --ranks rows: $(awk -F, '{print $1 "," $(NF-1) "," $NF}' "$WORK/r.csv" 2>&1 | tr '\n' ' ')"
fi
if "$FLOWSURF" info builtin:double-gyre | grep -q "time values: 0 1 2"; then ok "info lists time values"; else bad "info lists time values"; fi
if command -v ffmpeg >/dev/null; then
    if "$FLOWSURF" render builtin:sphere --size 64x64 --frames 4 --orbit 2 -q -o "$WORK/a.mp4" && [ -s "$WORK/a.mp4" ]; then
        ok "render mp4"
    else
        bad "render mp4"
    fi
    # --frames 12 writes 12 frames, not 13.
    if command -v ffprobe >/dev/null; then
        n=$("$FLOWSURF" render builtin:sphere --size 64x64 --frames 12 -q -o "$WORK/twelve.mp4" && \
            ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$WORK/twelve.mp4")
        if [ "$n" = "12" ]; then ok "mp4: --frames 12 writes 12 frames"; else bad "mp4: --frames 12 wrote '$n' frames"; fi
    fi
fi

# quality: one row per method on stdout; --quality FILE.json on quality, render, compare
# carries the options, the renderer and per method median, worst and frames.
qout=$("$FLOWSURF" quality builtin:sphere --size 96x96 --frames 4 --quality-every 2 -q --quality "$WORK/q.json")
if [ "$(grep -cE '^(isa|ibfvs|hybrid) +2 +[0-9.]+' <<<"$qout")" = 3 ] && grep -q '^method .*orient_err' <<<"$qout" &&
   python3 -c "
import json, sys; d = json.load(open(sys.argv[1]))
assert d['gl_renderer'] and d['options']['size'] == '96x96' and d['command'] == 'quality'
assert [m['method'] for m in d['methods']] == ['isa', 'ibfvs', 'hybrid']
assert all(m['frames_measured'] == 2 and len(m['frames']) == 2 and m['median']['orientation_error_deg'] < 30 for m in d['methods'])
" "$WORK/q.json"; then
    ok "quality table and JSON"
else
    bad "quality table and JSON: $qout"
fi
if "$FLOWSURF" render builtin:vortex-plane --size 96x96 --frames 30 -q -o "$WORK/r.png" --quality "$WORK/r.json" &&
   [ -s "$WORK/r.png" ] && python3 -c "
import json, sys; d = json.load(open(sys.argv[1]))
m = d['methods'][0]; assert m['method'] == 'isa' and m['frames_measured'] == 1 and m['frames'][0]['frame'] == 30
assert 0.5 < m['median']['frame_correlation'] <= 1
" "$WORK/r.json"; then
    ok "render --quality"
else
    bad "render --quality"
fi
if "$FLOWSURF" compare builtin:sphere --methods isa,hybrid --size 64x64 --frames 3 -q -o "$WORK/c2.png" \
       --quality "$WORK/c2.json" && [ -s "$WORK/c2.png" ] &&
   python3 -c "
import json, sys; d = json.load(open(sys.argv[1])); assert [m['method'] for m in d['methods']] == ['isa', 'hybrid']
assert all(m['frames_measured'] == 4 and m['ms_per_frame'] > 0 for m in d['methods'])
" "$WORK/c2.json"; then
    ok "compare --quality"
else
    bad "compare --quality"
fi
if "$FLOWSURF" quality builtin:sphere --size 64x64 --frames 2 --quality-every 1 --methods hybrid --auto-tune -q |
   grep -qE '^best trade for hybrid: --filter-length [0-9]+ --lic-step-px [0-9]+ --noise-scale [0-9]+'; then
    ok "quality --auto-tune names the best trade"
else
    bad "quality --auto-tune names the best trade"
fi
expect_fail "auto-tune with --quality" 2 "auto-tune"         "$WORK/q0.json" -- quality builtin:sphere --auto-tune --quality "$WORK/q0.json" -q
expect_fail "quality unknown method" 2 "'lic' is not one of" "$WORK/q1.json" -- quality builtin:sphere --methods isa,lic --quality "$WORK/q1.json" -q
expect_fail "quality not json"       2 "q2.txt' must be a .json" "$WORK/q2.txt" -- quality builtin:sphere --quality "$WORK/q2.txt" -q
expect_fail "quality missing input"  3 "nosuch.vtp"          "$WORK/q3.json" -- quality "$WORK/nosuch.vtp" --quality "$WORK/q3.json" -q
expect_fail "quality every 0"        2 "quality-every"       "$WORK/q4.json" -- quality builtin:sphere --quality-every 0 --quality "$WORK/q4.json" -q
expect_fail "render quality no dir"  3 "nodir"               "$WORK/q5.png" -- render builtin:sphere --size 64x64 --frames 2 -o "$WORK/q5.png" --quality "$WORK/nodir/q5.json" -q

# --- flow topology -----------------------------------------------------------------
if "$FLOWSURF" topology builtin:sphere -q -o "$WORK/t1.json" && python3 -c "
import json, sys; d = json.load(open(sys.argv[1]))
assert d['euler_characteristic'] == 2 and d['index_sum'] == 2 and d['closed'], d
assert sorted(p['type'] for p in d['critical_points']) == ['center', 'center'], d['critical_points']
assert all(len(p['position']) == 3 and p['index'] == 1 for p in d['critical_points'])
assert isinstance(d['lines'], list)
" "$WORK/t1.json"; then
    ok "topology: a rotating sphere has two centres, chi 2"
else
    bad "topology: a rotating sphere has two centres, chi 2"
fi
# The tangential part of a vertical field on two tori: sources where it leaves, sinks where
# it arrives; reversed, the two swap.
count_types() { python3 -c "
import json, sys, collections; c = collections.Counter(p['type'] for p in json.load(open(sys.argv[1]))['critical_points'])
print(c['source'], c['sink'], c['saddle'])" "$1"; }
if "$FLOWSURF" topology builtin:tori -q -o "$WORK/t2.json" &&
   "$FLOWSURF" topology builtin:tori --reverse-field on -q -o "$WORK/t3.json" &&
   read -r so si sa < <(count_types "$WORK/t2.json") && read -r so2 si2 sa2 < <(count_types "$WORK/t3.json") &&
   [ "$so" -gt 0 ] && [ "$si" -gt 0 ] && [ "$sa" -gt 0 ] && [ "$so" = "$si2" ] && [ "$si" = "$so2" ] && [ "$sa" = "$sa2" ]; then
    ok "topology: --reverse-field swaps sources and sinks"
else
    bad "topology: --reverse-field swaps sources and sinks"
fi
if "$FLOWSURF" topology builtin:tori -q -o "$WORK/t4.csv" && head -1 "$WORK/t4.csv" | grep -q '^record,id,type,index,x,y,z,strength$' &&
   grep -q '^point,0,' "$WORK/t4.csv" &&
   "$FLOWSURF" topology builtin:tori -q -o "$WORK/t5.vtp" && grep -q '<VTKFile type="PolyData"' "$WORK/t5.vtp"; then
    ok "topology: CSV and VTP"
else
    bad "topology: CSV and VTP"
fi
if "$FLOWSURF" topology builtin:double-gyre -q -o "$WORK/dg_%02d.json" && [ "$(ls "$WORK"/dg_*.json | wc -l)" -eq 11 ]; then
    ok "topology: one file per time step with a pattern"
else
    bad "topology: one file per time step with a pattern"
fi
if "$FLOWSURF" info builtin:sphere | grep -q "Derived scalars .*normalized-divergence"; then
    ok "info lists the derived fields and scalars"
else
    bad "info lists the derived fields and scalars"
fi
expect_fail "topology without -o"     2 "-o OUT.json"          ""               -- topology builtin:sphere -q
expect_fail "topology image output"   2 "\.json, \.csv or \.vtp" "$WORK/t6.png" -- topology builtin:sphere -o "$WORK/t6.png" -q
expect_fail "topology zero field"     5 "zero everywhere"      "$WORK/t7.json"  -- topology builtin:uniform-plane --field down:0,0,1 -o "$WORK/t7.json" -q
expect_fail "topology no triangles"   4 "nogeometry.stl"       "$WORK/t8.json"  -- topology "$WORK/nogeometry.stl" -o "$WORK/t8.json" -q
expect_fail "topology missing field"  5 "no vector field 'p'"  "$WORK/t9.json"  -- topology builtin:sphere --field p -o "$WORK/t9.json" -q
expect_fail "topology bad threshold"  2 "topology-cancel-speed" "$WORK/ta.json" -- topology builtin:sphere --topology-cancel-speed 2 -o "$WORK/ta.json" -q
if "$FLOWSURF" render builtin:tori --method isa --topology on --size 96x72 --frames 2 -q -o "$WORK/t10.png" && [ -s "$WORK/t10.png" ] &&
   "$FLOWSURF" render builtin:vortex-plane --color-by normalized-divergence --size 96x72 --frames 2 -q -o "$WORK/t11.png" && [ -s "$WORK/t11.png" ]; then
    ok "render --topology on, --color-by normalized-divergence"
else
    bad "render --topology on, --color-by normalized-divergence"
fi

# --- CGNS: the walls of generated cases, the same image as the same surface as a VTK file ---
if [ -n "$MAKE_CGNS" ]; then
    mkdir -p "$WORK/cgns"
    "$MAKE_CGNS" "$WORK/cgns"
    for c in box blocks nobc; do
        args=(--field Velocity --view iso --size 160x120 --frames 4 -q)
        [ "$c" = box ] && args+=(--color-by Temperature --legend)
        if "$FLOWSURF" render "$WORK/cgns/$c.cgns" "${args[@]}" -o "$WORK/cgns/$c.png" &&
           "$FLOWSURF" render "$WORK/cgns/$c.expected.vtk" "${args[@]}" -o "$WORK/cgns/$c.vtk.png" &&
           cmp -s "$WORK/cgns/$c.png" "$WORK/cgns/$c.vtk.png"; then
            ok "cgns $c: the same image as its VTK surface"
        else
            bad "cgns $c: the same image as its VTK surface"
        fi
    done
    if "$FLOWSURF" render "$WORK/cgns/series.cgns" --field Velocity --size 96x72 --frames 3 -q -o "$WORK/cgns/s_%02d.png" &&
       "$FLOWSURF" render "$WORK/cgns/series.expected_%d.vtk" --field Velocity --size 96x72 --frames 3 -q -o "$WORK/cgns/v_%02d.png" &&
       cmp -s "$WORK/cgns/s_02.png" "$WORK/cgns/v_02.png"; then
        ok "cgns series: the same frames as its VTK series"
    else
        bad "cgns series: the same frames as its VTK series"
    fi
    info=$("$FLOWSURF" info "$WORK/cgns/box_adf.cgns")
    if grep -q "CGNS (ADF" <<<"$info" && grep -qE "roof +BCWallViscous +Walls +8 faces  read" <<<"$info" &&
       grep -qE "inlet +BCInflow +- +4 faces$" <<<"$info"; then
        ok "cgns info: every BC with its type and family"
    else
        bad "cgns info: every BC with its type and family ($info)"
    fi
    expect_fail "cgns --patches matching nothing" 2 "box.cgns: --patches 'wing' matches no .*inlet \(BCInflow\)" "$WORK/cg1.png" \
        -- render "$WORK/cgns/box.cgns" --patches wing -o "$WORK/cg1.png" -q
    head -c 5000 "$WORK/cgns/box.cgns" > "$WORK/cgns/cut.cgns"
    expect_fail "cgns truncated"      4 "cut.cgns"             "$WORK/cg2.png" -- render "$WORK/cgns/cut.cgns" -o "$WORK/cg2.png" -q
    printf 'not cgns' > "$WORK/cgns/text.cgns"
    expect_fail "cgns not cgns"       4 "text.cgns: not a CGNS file" "$WORK/cg3.png" -- render "$WORK/cgns/text.cgns" -o "$WORK/cg3.png" -q
    # skin-friction of a CGNS volume: said by info, rendered, refused without a velocity
    if "$FLOWSURF" info "$WORK/cgns/couette.cgns" | grep -q "Wall stress.*skin-friction: from Velocity (at the vertices).*wall BCs floor, roof"; then
        ok "cgns info: skin-friction"
    else
        bad "cgns info: skin-friction"
    fi
    if "$FLOWSURF" render "$WORK/cgns/couette.cgns" --field skin-friction --viscosity 1e-5 --legend --size 96x72 --frames 2 -q \
           -o "$WORK/cgns/sf.png" && [ -s "$WORK/cgns/sf.png" ]; then
        ok "cgns render --field skin-friction"
    else
        bad "cgns render --field skin-friction"
    fi
    expect_fail "cgns skin-friction without velocity" 5 "couette_novelocity.cgns.*skin-friction.*no velocity" "$WORK/cg4.png" \
        -- render "$WORK/cgns/couette_novelocity.cgns" --field skin-friction -o "$WORK/cg4.png" -q
fi
# --- skin-friction: the wall stress derived from the volume's velocity -------------------
CAVITY=$(cd "$(dirname "$0")/../unit/data/openfoam_cavity_laminar" && pwd)/case.foam
if "$FLOWSURF" info "$CAVITY" | grep -q "Wall stress.*skin-friction.*nu = 0.01"; then ok "info: skin-friction"; else bad "info: skin-friction"; fi
# OpenFOAM's default for a 2-D case (the cavity): its empty patches, the plane of the flow,
# marked read by info; --patches picks the walls; '.*' all
info=$("$FLOWSURF" info "$CAVITY")
if grep -q "(2-D: the empty patches" <<<"$info" && grep -qE "frontAndBack +empty +- +800 faces  read" <<<"$info" &&
   grep -qE "movingWall +wall +- +20 faces$" <<<"$info" &&
   "$FLOWSURF" info "$CAVITY" --patches 'movingWall|fixedWalls' | grep -qE "movingWall +wall +- +20 faces  read" &&
   "$FLOWSURF" info "$CAVITY" --patches '.*' | grep -qE "frontAndBack +empty +- +800 faces  read"; then
    ok "foam info: a 2-D case's plane by default"
else
    bad "foam info: a 2-D case's plane by default ($info)"
fi
# wallShearStress is a point and a cell array: said once to be shown reversed
if [ "$(grep -c "^Shown reversed   wallShearStress" <<<"$info")" -eq 1 ]; then
    ok "info: reversed field said once"
else
    bad "info: reversed field said once ($info)"
fi
if "$FLOWSURF" render "$CAVITY" --field skin-friction --viscosity 0.02 --size 96x72 --frames 2 -q -o "$WORK/sf.png" &&
   [ -s "$WORK/sf.png" ]; then ok "render --field skin-friction"; else bad "render --field skin-friction"; fi
expect_fail "skin-friction of a surface" 4 "plain.obj.*volume" "$WORK/sf2.png" -- render "$WORK/plain.obj" --field skin-friction -o "$WORK/sf2.png" -q
expect_fail "negative viscosity"         2 "viscosity"         "$WORK/sf3.png" -- render "$CAVITY" --field skin-friction --viscosity -1 -o "$WORK/sf3.png" -q

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
