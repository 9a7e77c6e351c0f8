#!/usr/bin/env python3
"""The comparison behind scripts/bench-check.sh: `flowsurf bench --csv` rows against a
committed baseline of the same rows.

    compare.py BASELINE CURRENT [CURRENT ...] [--threshold 2.0] [--method-threshold 1.5]
               [--failing-methods]
    compare.py --median CURRENT [CURRENT ...]      (the per-row median as CSV, a new baseline)

A row is (method, case, triangles, width, height, param, gl_path); its time is frame_ms.
Where several CURRENT files hold a row (repeats), its time is their median.

The machine's speed: the row of method "calib" (`flowsurf bench --calibration`, a fixed GL
frame no flowsurf change touches) gives machine = calib now / calib in the baseline, and
each row is judged by ratio / machine, its slowdown on equal machines: a machine (or a
moment of load) that is twice as slow makes every row twice as slow and is not a
regression. Without a calib row in both files, machine = 1.

Prints one line per row: baseline ms, current ms, how many measurements, ratio = current /
baseline, that ratio / machine, and the verdict. A row fails when ratio / machine exceeds
the threshold, when the baseline has it and no CURRENT file does (a row the check stopped
measuring), or when a CURRENT file has it and the baseline does not (the baseline is out of
date). A method fails when the geometric mean of its rows' ratio / machine exceeds the
method threshold: a method made 2x slower is 2x slower in every row, and the mean over its
rows has a fraction of one row's noise, so this catches it even where single rows land under
the row threshold (noise here is about +-30 % per row). Lines starting with '#' (the
baseline's machine and commit) are skipped.

Exit status: 0 all rows pass, 1 some row fails, 2 a file cannot be read or lacks a column.
--failing-methods prints only the methods with a failing row, comma-separated (for a retry).
"""
import argparse
import csv
import math
import statistics
import sys

KEY = ("method", "case", "triangles", "width", "height", "param", "gl_path")
CALIB = "calib"


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


def medians(currents):
    """{key: (median ms, number of measurements)} over the CURRENT files."""
    measured = {}
    for rows in currents:
        for key, ms in rows.items():
            measured.setdefault(key, []).append(ms)
    return {key: (statistics.median(times), len(times)) for key, times in measured.items()}


def machine_factor(baseline, now):
    """calib now / calib in the baseline, or 1 where either lacks the row."""
    base = [ms for key, ms in baseline.items() if key[0] == CALIB]
    cur = [ms for key, (ms, _) in now.items() if key[0] == CALIB]
    return cur[0] / base[0] if base and cur else 1.0


def compare(baseline, currents, threshold):
    """(machine, [(key, baseline_ms or None, current_ms or None, repeats, ratio or None, verdict)])."""
    now = medians(currents)
    machine = machine_factor(baseline, now)
    result = []
    for key in list(baseline) + [k for k in now if k not in baseline]:
        if key[0] == CALIB:
            continue
        base = baseline.get(key)
        ms, n = now.get(key, (None, 0))
        if base is None:
            result.append((key, None, ms, n, None, "FAIL: not in the baseline"))
        elif ms is None:
            result.append((key, base, None, 0, None, "FAIL: not measured"))
        else:
            ratio = ms / base
            slow = ratio / machine > threshold
            result.append((key, base, ms, n, ratio, f"FAIL: more than {threshold:g}x slower" if slow else "ok"))
    return machine, result


def method_means(machine, result):
    """{method: geometric mean of ratio / machine over its measured rows}."""
    logs = {}
    for key, _, _, _, ratio, _ in result:
        if ratio is not None:
            logs.setdefault(key[0], []).append(math.log(ratio / machine))
    return {m: math.exp(sum(v) / len(v)) for m, v in logs.items()}


def print_table(machine, result, threshold):
    print(f"machine: calib now / calib in the baseline = {machine:.2f} (each ratio is divided by it)")
    print(f"{'method':6} {'case':7} {'triangles':>9} {'image':>9} {'param':>6} {'gl_path':8} "
          f"{'base ms':>8} {'now ms':>8} {'n':>2} {'ratio':>6} {'/machine':>8}  verdict (fails above {threshold:g}x)")
    for (method, case, tris, w, h, param, path), base, now, n, ratio, verdict in result:
        fmt = lambda v, spec: format(v, spec) if v is not None else "-"
        norm = ratio / machine if ratio is not None else None
        print(f"{method:6} {case:7} {tris:>9} {w + 'x' + h:>9} {param:>6} {path:8} "
              f"{fmt(base, '8.2f'):>8} {fmt(now, '8.2f'):>8} {n:>2} {fmt(ratio, '6.2f'):>6} {fmt(norm, '8.2f'):>8}  "
              f"{verdict}")


def write_median(currents):
    """The per-row median of the CURRENT files, as CSV on stdout."""
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(KEY + ("frame_ms", "repeats"))
    for key, (ms, n) in medians(currents).items():
        out.writerow(key + (f"{ms:.3f}", n))


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("files", nargs="+", metavar="FILE", help="BASELINE CURRENT [CURRENT ...], or with --median CURRENT ...")
    p.add_argument("--threshold", type=float, default=2.0, help="fail above this ratio / machine (default 2.0)")
    p.add_argument("--method-threshold", type=float, default=1.5,
                   help="fail a method whose rows' geometric mean ratio / machine exceeds this (default 1.5)")
    p.add_argument("--failing-methods", action="store_true", help="print only the failing methods")
    p.add_argument("--median", action="store_true", help="print the per-row median of the files as CSV")
    a = p.parse_args(argv)
    if not a.median and len(a.files) < 2:
        p.error("give BASELINE and at least one CURRENT file")
    try:
        if a.median:
            write_median([read_rows(c) for c in a.files])
            return 0
        machine, result = compare(read_rows(a.files[0]), [read_rows(c) for c in a.files[1:]], a.threshold)
    except InputError as e:
        print(f"compare.py: {e}", file=sys.stderr)
        return 2
    failing = [r for r in result if r[5] != "ok"]
    means = method_means(machine, result)
    slow_methods = [m for m, g in means.items() if g > a.method_threshold]
    if a.failing_methods:
        print(",".join(dict.fromkeys([r[0][0] for r in failing] + slow_methods)))
    else:
        print_table(machine, result, a.threshold)
        for m, g in means.items():
            verdict = f"FAIL: more than {a.method_threshold:g}x slower" if m in slow_methods else "ok"
            print(f"method {m}: geometric mean of ratio / machine {g:.2f}  {verdict} "
                  f"(fails above {a.method_threshold:g}x)")
        norms = [r[4] / machine for r in result if r[4] is not None]
        if norms:
            print(f"ratio / machine: min {min(norms):.2f}, median {statistics.median(norms):.2f}, "
                  f"max {max(norms):.2f}; {len(failing)} of {len(result)} rows fail, "
                  f"{len(slow_methods)} of {len(means)} methods")
    return 1 if failing or slow_methods else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
