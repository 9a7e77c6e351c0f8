#!/usr/bin/env python3
"""Joins `flowsurf bench --csv` (hybrid rows, dynamic case) with surface_lic_bench.py's CSV:
one Markdown row per (triangles, image, ParaView steps S <-> flowsurf L = 2S+1) with both
ms/frame and the ratio ParaView / flowsurf (> 1: flowsurf is faster)."""
import csv
import sys


def main(ours_csv, pv_csv):
    ours = {}
    with open(ours_csv) as f:
        for r in csv.DictReader(f):
            if r["method"] != "hybrid" or r["case"] != "dynamic":
                continue
            length = int(r["param"].split("=")[1])
            ours[(int(r["width"]), int(r["height"]), (length - 1) // 2, r["triangles"])] = float(r["frame_ms"])
    rows = []
    with open(pv_csv) as f:
        for r in csv.DictReader(f):
            key = (int(r["width"]), int(r["height"]), int(r["steps"]))
            # Triangle counts differ slightly between the two sphere generators: nearest.
            cands = [(abs(int(t) - int(r["triangles"])), t, ms) for (w, h, s, t), ms in ours.items() if (w, h, s) == key]
            if not cands:
                continue
            _, tris, ms = min(cands)
            pv = float(r["ms_per_frame"])
            rows.append((int(r["triangles"]), key, ms, pv))
    print("| triangles | image | ParaView steps S | flowsurf L | flowsurf ms/frame | ParaView ms/frame | ParaView / flowsurf |")
    print("|---:|---|---:|---:|---:|---:|---:|")
    for tris, (w, h, s), ms, pv in sorted(rows):
        print(f"| {tris:,} | {w}x{h} | {s} | {2 * s + 1} | {ms:.0f} | {pv:.0f} | {pv / ms:.2f} |")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: join_results.py flowsurf.csv paraview.csv")
    main(sys.argv[1], sys.argv[2])
