#!/usr/bin/env python3
"""Per-frame timing of flowsurf's hybrid LIC on a surface file while animating (the
flowsurf half of hybrid_vs_lic_file.sh; timed like surface_lic_bench.py times ParaView's
Surface LIC): one warm-up frame, then K frames with the camera orbiting `--orbit` degrees
per frame, each timed as advance() plus the read-back of the RGB image. Prints one CSV
line `L,ms_per_frame,min_ms,tracing_ms,cpu_ms_per_frame` (tracing_ms: the median
particle-tracing stage; cpu_ms_per_frame: CPU time of all threads, llvmpipe's included) and writes the first frame's camera (JSON: eye, target, up, fov) for the LIC half.

Needs the Python module: PYTHONPATH=build/python /usr/bin/python3 hybrid_file_bench.py ...
"""

import argparse
import json
import statistics
import time

import flowsurf


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mesh")
    ap.add_argument("--field", required=True)
    ap.add_argument("--size", default="512x512")
    ap.add_argument("--length", type=int, default=81, help="filter length L (ParaView: 2 S + 1)")
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--orbit", type=float, default=0.5)
    ap.add_argument("--gl-path", default="auto")
    ap.add_argument("--camera-json", default=None, help="write the first frame's camera here")
    args = ap.parse_args()
    w, h = (int(v) for v in args.size.split("x"))
    surface = flowsurf.read(args.mesh, field=args.field)
    r = flowsurf.Renderer(method="hybrid", size=(w, h), filter_length=args.length, lic_step_px=2.0,
                          orbit=args.orbit, gl_path=args.gl_path)
    frames = r.frames(surface, n=args.frames + 1)
    next(frames)  # warm-up: shaders, textures
    if args.camera_json:
        with open(args.camera_json, "w") as f:
            json.dump(r.camera, f)
    times, tracing = [], []
    cpu0 = time.process_time()
    for _ in range(args.frames):
        t0 = time.perf_counter()
        next(frames)
        times.append(1000.0 * (time.perf_counter() - t0))
        tracing.append(r.stage_ms.get("particle tracing", float("nan")))
    cpu_ms = 1000.0 * (time.process_time() - cpu0) / args.frames
    print("%d,%.2f,%.2f,%.2f,%.2f" % (args.length, statistics.mean(times), min(times), statistics.median(tracing), cpu_ms))


if __name__ == "__main__":
    main()
