"""The table of bench/parallel_work.sh: instructions per frame per rank from callgrind's
per-thread files (OUT/<method>.n<ranks>.f<frames>.cg-<thread>), the difference of the two
frame counts; then, per method, where the most ranks' added work goes: flowsurf's functions
whose instructions (inclusive, summed over the ranks) grew most against 1 rank's. llvmpipe runs
a draw only where a later call needs its result (a glFinish, a read-back), so a draw's work can
land in the function that waits for it (ScreenTiles::finishedMs under tiles, say)."""
import collections
import glob
import os
import re
import subprocess
import sys

out, fa, fb = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])


def per_thread(prefix):
    """Instructions inside renderFrame per thread of one run (threads that rendered nothing left out)."""
    counts = {}
    for path in glob.glob(prefix + '.cg-*'):
        with open(path) as f:
            total = next((int(line.split()[1]) for line in f if line.startswith('totals:')), 0)
        if total:
            counts[path.rsplit('-', 1)[1]] = total
    return counts


def compiling(prefix):
    """Instructions of one run inside LLVM (llvmpipe compiling shaders), all threads."""
    total = 0
    for path in glob.glob(prefix + '.cg-*'):
        listing = subprocess.run(['callgrind_annotate', '--threshold=100', path], capture_output=True, text=True,
                                 check=True).stdout
        for line in listing.splitlines():
            m = re.match(r'\s*([\d,]+) .*\[[^\]]*libLLVM[^\]]*\]\s*$', line)
            if m:
                total += int(m.group(1).replace(',', ''))
    return total


def by_function(prefix):
    """Inclusive instructions of each function of flowsurf's methods (what renderFrame runs) in one run, summed over its threads."""
    total = collections.Counter()
    for path in glob.glob(prefix + '.cg-*'):
        listing = subprocess.run(['callgrind_annotate', '--inclusive=yes', '--threshold=100', path],
                                 capture_output=True, text=True, check=True).stdout
        for line in listing.splitlines():
            m = re.match(r'\s*([\d,]+) \([^)]*\)\s+\S*?:(flowsurf::methods::[\w:~<>]*\w)\b', line)
            if m:
                total[m.group(2)] += int(m.group(1).replace(',', ''))
    return total


def per_frame_by_function(m, n):
    a = by_function(os.path.join(out, f'{m}.n{n}.f{fa}'))
    b = by_function(os.path.join(out, f'{m}.n{n}.f{fb}'))
    return {k: (b[k] - a.get(k, 0)) / (fb - fa) for k in b}


rows = {}
for path in sorted(glob.glob(os.path.join(out, f'*.f{fa}.log'))):
    m, n = re.match(r'(\w+)\.n(\d+)\.f', os.path.basename(path)).groups()
    a = per_thread(os.path.join(out, f'{m}.n{n}.f{fa}'))
    b = per_thread(os.path.join(out, f'{m}.n{n}.f{fb}'))
    if not a or not b or set(a) != set(b):
        print(f'{m} {n} ranks: incomplete', file=sys.stderr)
        continue
    ranks = [(b[t] - a[t]) / (fb - fa) for t in sorted(b)]
    llvm = (compiling(os.path.join(out, f'{m}.n{n}.f{fb}')) - compiling(os.path.join(out, f'{m}.n{n}.f{fa}'))) / (fb - fa)
    rows[(m, int(n))] = (ranks, llvm)

print('| method | ranks | Σ instructions per frame (G) | / 1 rank | busiest rank / mean | of which LLVM (M) |')
print('|---|---:|---:|---:|---:|---:|')
for (m, n), (ranks, llvm) in sorted(rows.items()):
    total = sum(ranks)
    one = rows.get((m, 1))
    ratio = f'{total / sum(one[0]):.3f}' if one else '—'
    print(f'| {m} | {n} | {total / 1e9:.3f} | {ratio} | {max(ranks) / (total / len(ranks)):.3f} | {llvm / 1e6:.0f} |')

for m in sorted({m for m, _ in rows}):
    counts = sorted(n for mm, n in rows if mm == m)
    if len(counts) < 2 or counts[0] != 1:
        continue
    one, most = per_frame_by_function(m, 1), per_frame_by_function(m, counts[-1])
    grown = sorted(most, key=lambda k: one.get(k, 0) - most[k])[:12]
    print(f'\n{m}: the functions whose instructions per frame grew most, {counts[-1]} ranks summed against 1 '
          '(inclusive: a function counts what it calls)\n')
    print('| function | 1 rank (M) | %d ranks, Σ (M) | added (M) |' % counts[-1])
    print('|---|---:|---:|---:|')
    for k in grown:
        print(f'| `{k}` | {one.get(k, 0) / 1e6:.1f} | {most[k] / 1e6:.1f} | {(most[k] - one.get(k, 0)) / 1e6:+.1f} |')
