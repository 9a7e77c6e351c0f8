"""The table of bench/parallel_work.sh: instructions per frame per rank from callgrind's
per-thread files (OUT/<method>.n<ranks>.f<frames>.cg-<thread>), the difference of the two
frame counts."""
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
