#!/usr/bin/env python3
"""Tables for scripts/bench-tables.sh.

    tables.py isa-ibfvs CSV              the manual's ISA/IBFVS table (Markdown) of a
                                         `flowsurf bench --methods isa,ibfvs --csv` file
    tables.py paraview-summary MD        one sentence on a bench/paraview/compare.sh table
    tables.py replace README NAME FILE   puts FILE between README's markers
                                         <!-- bench-tables NAME --> and <!-- /bench-tables NAME -->
"""
import csv
import os
import statistics
import sys


def isa_ibfvs(path):
    """Per mesh and image: IBFVS static / dynamic, then ISA static / dynamic per R."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    ms = {(r["method"], r["case"], int(r["triangles"]), f"{r['width']}x{r['height']}", r["param"]): float(r["frame_ms"])
          for r in rows}
    grids = list(dict.fromkeys(r["param"] for r in rows if r["method"] == "isa"))
    scenes = list(dict.fromkeys((int(r["triangles"]), f"{r['width']}x{r['height']}") for r in rows))
    cols = ["IBFVS static / dynamic"] + [f"ISA {g} static / dynamic" if k == 0 else f"ISA {g}" for k, g in enumerate(grids)]
    out = ["| triangles | image | " + " | ".join(cols) + " |", "|---:|---|" + "---:|" * len(cols)]
    for tris, image in scenes:
        cells = [pair(ms, "ibfvs", tris, image, "-")] + [pair(ms, "isa", tris, image, g) for g in grids]
        out.append(f"| {tris:,} | {image} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def pair(ms, method, tris, image, param):
    s, d = ms.get((method, "static", tris, image, param)), ms.get((method, "dynamic", tris, image, param))
    return " / ".join("-" if v is None else f"{v:.0f}" for v in (s, d))


def paraview_summary(path):
    """How much faster flowsurf's hybrid is on the rows of a compare.sh table (last column)."""
    ratios = []
    with open(path) as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if line.startswith("|") and len(cells) == 7:
                try:
                    ratios.append(float(cells[6]))
                except ValueError:
                    pass  # the header and the alignment row
    if not ratios:
        sys.exit(f"tables.py: {path}: no table rows")
    faster = sum(r > 1 for r in ratios)
    return (f"flowsurf's hybrid is faster per frame on {faster} of {len(ratios)} rows "
            f"({min(ratios):.1f}x to {max(ratios):.1f}x, median {statistics.median(ratios):.1f}x).")


def replace(readme, name, path):
    begin, end = f"<!-- bench-tables {name} -->", f"<!-- /bench-tables {name} -->"
    with open(readme) as f:
        text = f.read()
    if text.count(begin) != 1 or text.count(end) != 1 or text.index(begin) > text.index(end):
        sys.exit(f"tables.py: {readme}: expected one '{begin}' ... '{end}' block")
    with open(path) as f:
        block = f.read().strip("\n")
    head, rest = text.split(begin)
    tail = rest.split(end)[1]
    with open(readme + ".tmp", "w") as f:
        f.write(f"{head}{begin}\n{block}\n{end}{tail}")
    os.replace(readme + ".tmp", readme)


def main(argv):
    if len(argv) == 2 and argv[0] == "isa-ibfvs":
        print(isa_ibfvs(argv[1]))
    elif len(argv) == 2 and argv[0] == "paraview-summary":
        print(paraview_summary(argv[1]))
    elif len(argv) == 4 and argv[0] == "replace":
        replace(*argv[1:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
