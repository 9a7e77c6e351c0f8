#!/usr/bin/env python3
"""The comparison behind scripts/bench-check.sh: `flowsurf bench --csv` rows against a
committed baseline of the same rows.

    compare.py BASELINE CURRENT [CURRENT ...] [--threshold 2.0] [--failing-methods]

A row is (method, case, triangles, width, height, param, gl_path); its time is frame_ms.
Where several CURRENT files hold a row (repeats), its time is their median. Prints one
line per row: baseline ms, current ms, how many measurements, ratio = current / baseline,
and the verdict. A row fails when its ratio exceeds the threshold, when the baseline has
it and no CURRENT file does (a row the check stopped measuring), or when a CURRENT file
has it and the baseline does not (the baseline is out of date). Lines starting with '#'
(the baseline's machine and commit) are skipped.

Exit status: 0 all rows pass, 1 some row fails, 2 a file cannot be read or lacks a column.
--failing-methods prints only the methods with a failing row, comma-separated (for a retry).
"""
import argparse
import csv
import statistics
import sys

KEY = ("method", "case", "triangles", "width", "height", "param", "gl_path")


class InputError(Exception):
    pass


def read_rows(path):
    """{key: frame_ms} of one CSV file."""
    try:
        with open(path, newline="") as f:
            lines = [line for line in f if not line.startswith("#")]
    except OSError as e:
        raise InputError(f"{path}: cannot read ({e.strerror})")
    reader = csv.DictReader(lines)
    missing = [c for c in KEY + ("frame_ms",) if c not in (reader.fieldnames or [])]
    if missing:
        raise InputError(f"{path}: no column {', '.join(missing)} (not a `flowsurf bench --csv` file?)")
    rows = {}
    for n, r in enumerate(reader, start=2):
        try:
            ms = float(r["frame_ms"])
        except (TypeError, ValueError):
            raise InputError(f"{path}: data row {n - 1}: frame_ms '{r['frame_ms']}' is not a number")
        if ms <= 0:
            raise InputError(f"{path}: data row {n - 1}: frame_ms {ms} is not positive")
        rows[tuple(r[c] for c in KEY)] = ms
    return rows


def compare(baseline, currents, threshold):
    """[(key, baseline_ms or None, current_ms or None, repeats, ratio or None, verdict)]."""
    measured = {}
    for rows in currents:
        for key, ms in rows.items():
            measured.setdefault(key, []).append(ms)
    result = []
    for key in list(baseline) + [k for k in measured if k not in baseline]:
        base = baseline.get(key)
        times = measured.get(key, [])
        now = statistics.median(times) if times else None
        if base is None:
            result.append((key, None, now, len(times), None, "FAIL: not in the baseline"))
        elif now is None:
            result.append((key, base, None, 0, None, "FAIL: not measured"))
        else:
            ratio = now / base
            verdict = f"FAIL: more than {threshold:g}x slower" if ratio > threshold else "ok"
            result.append((key, base, now, len(times), ratio, verdict))
    return result


def print_table(result, threshold):
    print(f"{'method':6} {'case':7} {'triangles':>9} {'image':>9} {'param':>6} {'gl_path':8} "
          f"{'base ms':>8} {'now ms':>8} {'n':>2} {'ratio':>6}  verdict (fails above {threshold:g}x)")
    for (method, case, tris, w, h, param, path), base, now, n, ratio, verdict in result:
        fmt = lambda v, spec: format(v, spec) if v is not None else "-"
        print(f"{method:6} {case:7} {tris:>9} {w + 'x' + h:>9} {param:>6} {path:8} "
              f"{fmt(base, '8.2f'):>8} {fmt(now, '8.2f'):>8} {n:>2} {fmt(ratio, '6.2f'):>6}  {verdict}")


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("baseline")
    p.add_argument("current", nargs="+")
    p.add_argument("--threshold", type=float, default=2.0, help="fail above this ratio (default 2.0)")
    p.add_argument("--failing-methods", action="store_true", help="print only the failing rows' methods")
    a = p.parse_args(argv)
    try:
        result = compare(read_rows(a.baseline), [read_rows(c) for c in a.current], a.threshold)
    except InputError as e:
        print(f"compare.py: {e}", file=sys.stderr)
        return 2
    failing = [r for r in result if r[5] != "ok"]
    if a.failing_methods:
        print(",".join(dict.fromkeys(r[0][0] for r in failing)))
    else:
        print_table(result, a.threshold)
        ratios = [r[4] for r in result if r[4] is not None]
        if ratios:
            print(f"ratios: min {min(ratios):.2f}, median {statistics.median(ratios):.2f}, max {max(ratios):.2f}; "
                  f"{len(failing)} of {len(result)} rows fail")
    return 1 if failing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
