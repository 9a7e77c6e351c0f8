#!/usr/bin/env python3
"""Markdown tables from `flowsurf bench` output of GPU machines (doc/bench/gpu_hopper.md).

    bench/gpu/summarize.py DIR LABEL [LABEL ...]

reads DIR/LABEL_grid.txt, DIR/LABEL_rasters.txt (bench/gpu/lease.sh's grid and the
--surface-rasters gl,compute run) for each machine LABEL and prints the tables, one column
per machine. Rows are parsed from the table `flowsurf bench` prints (bench/bench.cpp).
"""
import sys
from pathlib import Path

def rows(path):
    """The rows of a `flowsurf bench` table; the stage columns named by its header line."""
    out, stages = [], []
    for line in Path(path).read_text().splitlines():
        f = line.split()
        if f[:2] == ["method", "case"]:
            stages = line.split("|")[2].split()
            continue
        if len(f) < 12 or f[0] not in ("isa", "ibfvs", "hybrid") or "|" not in f:
            continue
        bar = f.index("|")
        method, case, tris, image, param, path, raster = f[:7]
        ms = float(f[bar + 1])
        times = dict(zip(stages, map(float, f[bar + 4:bar + 4 + len(stages)])))
        out.append(dict(method=method, case=case, tris=int(tris), image=image, param=param, path=path,
                        raster=raster, ms=ms, stages=times))
    return out


def find(rs, **key):
    for r in rs:
        if all(r[k] == v for k, v in key.items()):
            return r
    return None


def mega(t):
    return f"{t / 1e6:.0f}M" if t >= 1e6 else f"{t / 1e3:.0f}k"


def table(header, lines):
    print("| " + " | ".join(header) + " |")
    print("|" + "|".join("---" if i == 0 else "---:" for i in range(len(header))) + "|")
    for line in lines:
        print("| " + " | ".join(line) + " |")
    print()


def main():
    folder, labels = Path(sys.argv[1]), sys.argv[2:]
    grid = {m: rows(folder / f"{m}_grid.txt") for m in labels}
    rast = {m: rows(folder / f"{m}_rasters.txt") for m in labels}
    params = {"isa": "R=256", "ibfvs": "-", "hybrid": "L=31"}

    print("**Surface raster, GL vs compute** (dynamic ms per frame, compute per-pixel path; "
          "ISA R = 256, hybrid L = 31; IBFVS drew its polygons with GL either way in this run, see above for its "
          "compute pass)\n")
    header = ["method, triangles, image"]
    for m in labels:
        header += [f"{m} GL", f"{m} compute"]
    lines = []
    for method in ("hybrid", "isa", "ibfvs"):
        for tris in (99224, 998000, 9991920):
            for image in ("1024x1024", "1920x1080", "3840x2160"):
                line = [f"{method} {mega(tris)} {image}"]
                for m in labels:
                    for raster in ("gl", "compute"):
                        r = find(rast[m], method=method, tris=tris, image=image, raster=raster)
                        line.append(f"{r['ms']:.2f}" if r else "-")
                lines.append(line)
    table(header, lines)

    print("**Per-pixel passes, fragment vs compute shaders** (1M triangles, GL raster; "
          "ms per frame, static / dynamic)\n")
    header = ["method, image"] + [f"{m} {p}" for m in labels for p in ("fragment", "compute")]
    lines = []
    for method, param in (("hybrid", "L=101"), ("hybrid", "L=21"), ("isa", "R=1024"), ("ibfvs", "-")):
        for image in ("512x512", "1920x1080", "3840x2160"):
            line = [" ".join(x for x in (method, param, image) if x != "-")]
            for m in labels:
                for path in ("fragment", "compute"):
                    s = find(grid[m], method=method, tris=998000, image=image, param=param, path=path, case="static")
                    d = find(grid[m], method=method, tris=998000, image=image, param=param, path=path, case="dynamic")
                    line.append(f"{s['ms']:.2f} / {d['ms']:.2f}" if s and d else "-")
            lines.append(line)
    table(header, lines)

    print("**Mesh size** (1920x1080, dynamic ms per frame, compute per-pixel path, GL raster, "
          "ISA R = 256, hybrid L = 21; surface = the surface pass)\n")
    header = ["triangles"] + [f"{m} {meth}" for m in labels for meth in ("hybrid", "ISA", "IBFVS")]
    lines = []
    for tris in (9800, 99224, 998000, 9991920):
        line = [mega(tris)]
        for m in labels:
            for method, param in (("hybrid", "L=21"), ("isa", "R=256"), ("ibfvs", "-")):
                r = find(grid[m], method=method, tris=tris, image="1920x1080", param=param, path="compute",
                         case="dynamic")
                line.append(f"{r['ms']:.2f}" if r else "-")
        lines.append(line)
    table(header, lines)


if __name__ == "__main__":
    main()
