"""The table of bench/paraview/scaling.sh's run: python3 scaling_report.py OUT > results.md

Medians over the rounds of each run's median ms per render; speedups T(1 rank) / T(2 ranks)
against the issue's bars scaled by the machine's two-process speedup (min(1, S_hw / 1.9));
2 ranks of one thread against 1 rank of two llvmpipe threads; the same speedups less
ParaView's own frame (its Outline representation's render time in the same run, when
recorded); whether each 2-rank image is
byte-identical to the 1-rank image; and, when present, the per-rank CPU accounting of the
oversubscribed runs (FLOWSURF_RANK_STATS), round by round against the same round's 1-rank run."""
import filecmp
import glob
import json
import os
import re
import statistics
import sys

OUT = sys.argv[1]


def load(path):
    with open(path) as f:
        return json.load(f)


def identical(pngs, reference_of):
    """(byte-identical, compared) over `pngs` whose reference image exists."""
    same = total = 0
    for png in sorted(pngs):
        ref = reference_of(png)
        if os.path.exists(ref):
            total += 1
            same += filecmp.cmp(png, ref, shallow=False)
    return same, total


def timed_rows(run_dir):
    """A FLOWSURF_RANK_STATS run's lines of every rank, warm-up renders left out."""
    rows = []
    for f in glob.glob(os.path.join(run_dir, 'rank*.jsonl')):
        rows += [json.loads(line) for line in open(f)]
    return [r for r in rows if not r['warmup']]


cal = open(os.path.join(OUT, 'calibration.txt')).read()
s_hw = float(re.search(r'S_hw = ([0-9.]+)', cal).group(1))
scale = min(1.0, s_hw / 1.9)
inflation = {int(n): float(v) for n, v in re.findall(r'I_(\d+) = ([0-9.]+)', cal)}
runs, paraview = {}, {}
for path in sorted(glob.glob(os.path.join(OUT, 'r*', '*', 'timings.json'))):
    run = os.path.basename(os.path.dirname(path))
    timings = load(path)
    for method, v in timings['methods'].items():
        runs.setdefault(run, {}).setdefault(method, []).append(v['median_ms'])
    if 'paraview_ms' in timings:
        paraview.setdefault(run, []).append(timings['paraview_ms'])
# 1 rank on llvmpipe's 2 threads: in every round (r*/np1_lp2), or once after the rounds (np1_lp2).
lp2_once = os.path.join(OUT, 'np1_lp2', 'timings.json')
if 'np1_lp2' not in runs and os.path.exists(lp2_once):
    once = load(lp2_once)
    runs['np1_lp2'] = {method: [v['median_ms']] for method, v in once['methods'].items()}
    if 'paraview_ms' in once:
        paraview['np1_lp2'] = [once['paraview_ms']]
lp2_paraview = statistics.median(paraview['np1_lp2']) if 'np1_lp2' in paraview else None


def round_ratio(round_dir, method, num, den, less_paraview=False):
    """`num` / `den` ms of `method` in one round's directory (with `less_paraview`, each less
    its run's ParaView frame); OSError or KeyError where the round lacks either."""
    a = load(os.path.join(round_dir, num, 'timings.json'))
    b = load(os.path.join(round_dir, den, 'timings.json'))
    pa, pb = (a['paraview_ms'], b['paraview_ms']) if less_paraview else (0.0, 0.0)
    return (a['methods'][method]['median_ms'] - pa) / (b['methods'][method]['median_ms'] - pb)


def round_ratios(method, num, den, less_paraview=False):
    """round_ratio over every round that ran both (rounds in step)."""
    out = []
    for d in sorted(glob.glob(os.path.join(OUT, 'r*', den, 'timings.json'))):
        try:
            out.append(round_ratio(os.path.dirname(os.path.dirname(d)), method, num, den, less_paraview))
        except (OSError, KeyError):
            pass
    return out


info = open(os.path.join(OUT, 'plugin', 'info.txt')).read().strip().splitlines()
rounds = sorted(glob.glob(os.path.join(OUT, 'r*', 'np1', 'timings.json')))
first = load(rounds[0]) if rounds else None  # --rounds 0: the oversubscribed runs alone

if first:
    print('# FlowSurf on ParaView\'s engine: 1 and 2 ranks, tiles and replicate\n')
    print('Machine and run: %s. %d triangles, %dx%d, camera turning %.1f deg per render, %d timed renders per '
          'method and run; one llvmpipe thread per rank, each rank bound to its own core (`--bind-to core`). '
          'The view\'s FXAA %s. %s\n' % ('; '.join(info), first['triangles'], first['size'][0], first['size'][1],
                                         first['azimuth_deg'], first['frames'],
                                         {1: 'on', 0: 'off'}.get(first.get('fxaa'), 'not recorded'), cal.strip()))
    bar = 1.7 if first['triangles'] >= 9_500_000 else 1.6  # the issue's: 1.6 at 1M, 1.7 at 10M
    print('Bar for 2 ranks: %.1f x min(1, S_hw / 1.9) = **%.2f**.\n' % (bar, bar * scale))
    print('| method | 1 rank ms | 2 ranks tiles ms | speedup tiles | 2 ranks replicate ms | speedup replicate | '
          '1 rank, 2 llvmpipe threads ms | 2 ranks tiles / that | rounds |')
    print('|---|---:|---:|---:|---:|---:|---:|---:|---:|')
    for method in runs.get('np1', {}):
        t1 = statistics.median(runs['np1'][method])
        tt = statistics.median(runs.get('np2_tiles', {}).get(method, [float('nan')]))
        tr = statistics.median(runs.get('np2_replicate', {}).get(method, [float('nan')]))
        l2 = statistics.median(runs.get('np1_lp2', {}).get(method, [float('nan')]))
        # In step: the median of each round's ratio, when every round ran both.
        per_round = round_ratios(method, 'np2_tiles', 'np1_lp2')
        both = statistics.median(per_round) if len(per_round) > 1 else tt / l2
        print('| %s | %.0f | %.0f | **%.2f** | %.0f | %.2f | %.0f | %.2f | %d |'
              % (method, t1, tt, t1 / tt, tr, t1 / tr, l2, both, len(runs['np1'][method])))
    if any(len(round_ratios(m, 'np2_tiles', 'np1_lp2')) > 1 for m in runs.get('np1', {})):
        print('\n1 rank on llvmpipe\'s 2 threads ran in every round (after its 2-rank runs); "2 ranks tiles / that" '
              'is the median of the rounds\' own ratios.')

    if 'np1' in paraview and 'np2_tiles' in paraview:
        p1, p2 = statistics.median(paraview['np1']), statistics.median(paraview['np2_tiles'])
        print('\nParaView\'s own frame (its Outline representation of the same data, same loop): %.0f ms at 1 '
              'rank, %.0f ms at 2. Less that, FlowSurf\'s part of a render:\n' % (p1, p2))
        if lp2_paraview is not None:
            print('(1 rank on llvmpipe\'s 2 threads: ParaView\'s own frame %.0f ms.)\n' % lp2_paraview)
        print('| method | 1 rank ms | 2 ranks tiles ms | speedup of FlowSurf\'s part '
              '| 1 rank, 2 llvmpipe threads ms | 2 ranks tiles / that |')
        print('|---|---:|---:|---:|---:|---:|')
        for method in runs.get('np1', {}):
            t1 = statistics.median(runs['np1'][method]) - p1
            tt = statistics.median(runs.get('np2_tiles', {}).get(method, [float('nan')])) - p2
            l2 = statistics.median(runs.get('np1_lp2', {}).get(method, [float('nan')])) - (lp2_paraview or float('nan'))
            per_round = round_ratios(method, 'np2_tiles', 'np1_lp2', less_paraview=True)
            both = statistics.median(per_round) if len(per_round) > 1 else tt / l2
            print('| %s | %.0f | %.0f | %.2f | %.0f | %.2f |' % (method, t1, tt, t1 / tt, l2, both))

    shw_path = os.path.join(OUT, 'rounds.txt')
    if os.path.exists(shw_path):
        shw = {}
        for r, s in re.findall(r'round (\d+) \w+: S_hw = ([0-9.]+)', open(shw_path).read()):
            shw.setdefault(int(r), []).append(float(s))
        methods = list(runs.get('np1', {}))
        print('\nPer round: the two-process speedup measured before and after its 2-rank runs, and the '
              '`tiles` speedup (the round\'s 1 rank / 2 ranks; a round whose S_hw fell below 1.9 measured a '
              'slower second core; in brackets, when the round ran it, its 2 ranks `tiles` / 1 rank on llvmpipe\'s '
              '2 threads):\n')
        print('| round | S_hw before / after | ' + ' | '.join(methods) + ' |')
        print('|---:|---|' + '---:|' * len(methods))
        quiet = {m: [] for m in methods}
        for k in sorted(shw):
            cells = []
            for m in methods:
                try:
                    v = load(os.path.join(OUT, 'r%d' % k, 'np1', 'timings.json'))['methods'][m]['median_ms'] / \
                        load(os.path.join(OUT, 'r%d' % k, 'np2_tiles', 'timings.json'))['methods'][m]['median_ms']
                except (OSError, KeyError):
                    cells.append('–')
                    continue
                try:
                    cells.append('%.2f (%.2f)' % (v, round_ratio(os.path.join(OUT, 'r%d' % k), m, 'np2_tiles', 'np1_lp2')))
                except (OSError, KeyError):
                    cells.append('%.2f' % v)
                if min(shw[k]) >= 1.9:
                    quiet[m].append(v)
            print('| %d | %s | %s |' % (k, ' / '.join('%.2f' % v for v in shw[k]), ' | '.join(cells)))
        if any(quiet.values()):
            print('\nMedian `tiles` speedup over the rounds with S_hw >= 1.9 before and after: ' +
                  ', '.join('%s %.2f (%d rounds)' % (m, statistics.median(v), len(v)) for m, v in quiet.items() if v) +
                  '.')

    print('\nImages (last render of each method) byte-identical to the same round\'s 1-rank image:\n')
    same, total = identical(glob.glob(os.path.join(OUT, 'r*', 'np2_*', '*.png')),
                            lambda png: os.path.join(os.path.dirname(os.path.dirname(png)), 'np1',
                                                     os.path.basename(png)))
    print('%d of %d identical.\n' % (same, total))

def rank_sums(run_dir):
    """Per method of a FLOWSURF_RANK_STATS run: Σ over ranks of each rank's median CPU ms per
    render, the same outside MPI and of the compute stages alone (`compute_cpu_ms`: every timed
    stage but the tile exchange and return; None for logs without it), the slowest rank / mean of
    each, the most bytes a rank sent."""
    rows = timed_rows(run_dir)
    out = {}
    for method in sorted({r['method'] for r in rows}):
        per_rank, outside, compute, sent = {}, {}, {}, []
        for r in rows:
            if r['method'] == method:
                per_rank.setdefault(r['rank'], []).append(r['cpu_ms'])
                outside.setdefault(r['rank'], []).append(r['cpu_ms'] - r.get('mpi_cpu_ms', 0.0))
                if 'compute_cpu_ms' in r:
                    compute.setdefault(r['rank'], []).append(r['compute_cpu_ms'])
                sent.append(r['bytes_sent'])
        cpu = {k: statistics.median(v) for k, v in per_rank.items()}
        own = {k: statistics.median(v) for k, v in outside.items()}
        work = {k: statistics.median(v) for k, v in compute.items()}
        slowest = lambda d: max(d.values()) / (sum(d.values()) / len(d))
        out[method] = {'ranks': len(cpu), 'cpu': sum(cpu.values()), 'own': sum(own.values()),
                       'slowest': slowest(cpu), 'slowest_own': slowest(own),
                       'compute': sum(work.values()) if len(work) == len(cpu) else None,
                       'slowest_compute': slowest(work) if len(work) == len(cpu) else None,
                       'sent': max(sent) / 1e6 if sent else 0.0}
    return out


def spread(values, fmt='%.2f'):
    """The median of `values`, and their range when there are several."""
    m = fmt % statistics.median(values)
    return m if fmt % min(values) == fmt % max(values) else '%s (%s–%s)' % (m, fmt % min(values), fmt % max(values))


stat_rounds = sorted(glob.glob(os.path.join(OUT, 'stats', 'r*')), key=lambda d: int(os.path.basename(d)[1:]))
if stat_rounds:
    print('## Oversubscribed: per-rank CPU time (FLOWSURF_RANK_STATS)\n')
    print('Timed dynamic renders only (no warm-up); CPU time of the frame loop per render, the process\'s '
          '(llvmpipe\'s threads included), summed over ranks; "outside MPI": less the time its thread spent '
          'inside the group\'s MPI calls (copies and polling while waiting: `mpi_cpu_ms`); "compute stages": '
          'the CPU time of the timed stages but the tile exchange and return (`compute_cpu_ms`: the image '
          'work itself, without moving tiles or the frame loop around the stages); bytes each rank '
          'sent per render. Every rank bound to a core, N ranks round-robin over the cores '
          '(`--bind-to core:overload-allowed`), 1 rank to one. %d round(s), each a 1-rank run then the N-rank runs: each ratio is a round\'s '
          'sum over the same round\'s 1-rank sum; the median over the rounds, their range in brackets. '
          'I_N: the machine\'s own cost of N processes sharing its cores, the same loop\'s CPU time per copy '
          'when N copies run at once against one alone (calibration); "/ I_N": the median divided by it.\n'
          % len(stat_rounds))
    print('| run | method | ranks | sum of CPU ms / 1 rank | outside MPI: sum / 1 rank | compute stages: sum / 1 rank '
          '| I_N | sum / I_N | outside MPI / I_N | slowest rank / mean | outside MPI: slowest / mean '
          '| compute stages: slowest / mean | MB sent per rank per render (max) |')
    print('|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
    ratios = {}  # (run, method) -> lists over the rounds
    for rd in stat_rounds:
        base = rank_sums(os.path.join(rd, 'np1'))
        for d in sorted(glob.glob(os.path.join(rd, 'np*'))):
            for method, v in rank_sums(d).items():
                if method not in base:
                    continue
                acc = ratios.setdefault((os.path.basename(d), method), {'ranks': v['ranks']})
                for key, value in (('cpu', v['cpu'] / base[method]['cpu']), ('own', v['own'] / base[method]['own']),
                                   ('slowest', v['slowest']), ('slowest_own', v['slowest_own']), ('sent', v['sent'])):
                    acc.setdefault(key, []).append(value)
                if v['compute'] is not None and base[method]['compute']:
                    acc.setdefault('compute', []).append(v['compute'] / base[method]['compute'])
                    acc.setdefault('slowest_compute', []).append(v['slowest_compute'])
    order = lambda item: (int(re.match(r'np(\d+)', item[0][0]).group(1)), item[0])
    for (name, method), acc in sorted(ratios.items(), key=order):
        i_n = inflation.get(acc['ranks'], 1.0 if acc['ranks'] == 1 else float('nan'))
        print('| %s | %s | %d | %s | %s | %s | %.2f | %.2f | %.2f | %s | %s | %s | %.2f |' % (
            name, method, acc['ranks'], spread(acc['cpu']), spread(acc['own']),
            spread(acc['compute']) if 'compute' in acc else '—', i_n,
            statistics.median(acc['cpu']) / i_n, statistics.median(acc['own']) / i_n,
            spread(acc['slowest']), spread(acc['slowest_own']),
            spread(acc['slowest_compute']) if 'slowest_compute' in acc else '—', max(acc['sent'])))

    same = total = 0
    for rd in stat_rounds:
        s_, t_ = identical([p for p in glob.glob(os.path.join(rd, 'np*', 'run', '*.png')) if '/np1/' not in p],
                           lambda png, rd=rd: os.path.join(rd, 'np1', 'run', os.path.basename(png)))
        same, total = same + s_, total + t_
    if total:
        print('\nImages of these runs (last render of each method) byte-identical to the same round\'s 1-rank '
              'run\'s: %d of %d.' % (same, total))

    # Where the extra work goes: each stage's CPU time summed over the ranks (medians per rank),
    # against the same stage at one rank, the median over the rounds; "other": the frame loop
    # outside the timed stages.
    staged = {}  # method -> run -> stage -> [Σ per round]
    for rd in stat_rounds:
        for d in glob.glob(os.path.join(rd, 'np*')):
            rows = [r for r in timed_rows(d) if r.get('stages_cpu_ms')]
            for r in rows:
                r['stages_cpu_ms']['other'] = r['cpu_ms'] - sum(r['stages_cpu_ms'].values())
            for method in {r['method'] for r in rows}:
                per = {}
                for r in rows:
                    if r['method'] == method:
                        for stage, ms in r['stages_cpu_ms'].items():
                            per.setdefault(stage, {}).setdefault(r['rank'], []).append(ms)
                run_ = staged.setdefault(method, {}).setdefault(os.path.basename(d), {})
                for stage, ranks in per.items():
                    run_.setdefault(stage, []).append(sum(statistics.median(v) for v in ranks.values()))
    if staged:
        print('\nEach stage\'s CPU ms per render summed over the ranks (synchronous stage timing, medians per '
              'rank; the median over the rounds):\n')
        for method in sorted(staged):
            runs_ = sorted([n for n in staged[method] if n == 'np1' or n.endswith('tiles')],
                           key=lambda n: int(re.match(r'np(\d+)', n).group(1)))
            stages_ = []
            for n in runs_:
                stages_ += [s for s in staged[method][n] if s not in stages_]
            med = {n: {s: statistics.median(v) for s, v in staged[method][n].items()} for n in runs_}
            print('| %s | %s |' % (method, ' | '.join(runs_)))
            print('|---|%s' % ('---:|' * len(runs_)))
            for s in stages_:
                print('| %s | %s |' % (s, ' | '.join('%.1f' % med[n].get(s, 0.0) for n in runs_)))
            print('| **total** | %s |\n' % ' | '.join('%.1f' % sum(med[n].values()) for n in runs_))
