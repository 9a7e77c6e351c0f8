"""Seam differences and the CSV of bench/paraview/flowsurf_vs_lic.sh (Debian's /usr/bin/python3,
numpy and PIL).

    compare_ranks.py OUTDIR CSV [DIFFDIR]
    compare_ranks.py --markdown CSV          (prints the CSV as the README's table)

OUTDIR holds np1/, np2/, ... written by flowsurf_vs_lic.py (timings.json and PNGs). For every
rank count N > 1, mesh and method, against the 1-rank image of the same mesh and method:

  gray            mean of R, G, B (0-255)
  surface         pixels that are surface in both ranks' ProcessId images (not background)
  mean_diff       mean |gray_N - gray_1| over the surface
  worst_tile      the largest mean |difference| over the surface pixels of one 16x16 tile (any
                  tile with a surface pixel, as tests/paraview/parallel_test.py counts)
  seam_band_diff  mean |difference| in the band around the partition seam: surface pixels within
                  B = 2S px (half a streak; streaks are ~4S px long) of a seam pixel, a surface
                  pixel whose 4-neighbour belongs to another rank in the N-rank ProcessId image
  far_diff        mean |difference| on the surface farther than 2B from the seam
  oversubscribed  1 when N > cores (here 4 ranks on 2 cores): the seam numbers hold, the
                  ms/render is no speed figure
  run_peak_rss_mb the largest peak RSS of one rank over the whole N-rank run (all meshes), from
                  /usr/bin/time in np{N}/pvbatch.log
  contrast        standard deviation of the 1-rank gray over the surface (the texture's
                  contrast: read the differences against it)

DIFFDIR (default OUTDIR/diff) gets |gray_N - gray_1| x 8 as PNG, one per mesh, method and N.
"""
import csv
import json
import os
import sys

import numpy as np
from PIL import Image

NAMES = {'flowsurf': 'FlowSurf hybrid', 'lic': 'Surface LIC', 'licenh': 'Surface LIC, enhanced'}


def markdown(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    print('| triangles | method | ranks | ms/render (min) | contrast | mean diff | worst 16² tile '
          '| seam band | far from seam |')
    print('|---:|---|---:|---:|---:|---:|---:|---:|---:|')
    for r in rows:
        over = r.get('oversubscribed') == '1'
        print('| {:,} | {} | {} | {}{} ({}) | {} | {} | {} | {} | {} |'.format(
            int(r['triangles']), NAMES.get(r['method'], r['method']), r['ranks'], r['ms_median'],
            ' †' if over else '', r['ms_min'], r['contrast'], r['mean_diff'] or '–', r['worst_tile'] or '–',
            r['seam_band_diff'] or '–', r['far_diff'] or '–'))


if sys.argv[1] == '--markdown':
    markdown(sys.argv[2])
    print('\n† more ranks than cores: no speed figure (the seam numbers hold)')
    sys.exit(0)
out, csv_path = sys.argv[1], sys.argv[2]
diff_dir = sys.argv[3] if len(sys.argv) > 3 else os.path.join(out, 'diff')
os.makedirs(diff_dir, exist_ok=True)
TILE = 16


def load(path):
    return np.asarray(Image.open(path).convert('RGB'), dtype=np.float64)


def rank_image(path, nranks):
    """Rank per pixel from the ProcessId picture (red = 0 ... blue = N-1), -1 off the surface."""
    rgb = load(path)
    r, b = rgb[..., 0], rgb[..., 2]
    surface = rgb.sum(axis=2) > 30
    ranks = np.full(r.shape, -1, dtype=np.int64)
    ranks[surface] = np.rint(b[surface] / np.maximum(r[surface] + b[surface], 1) * max(1, nranks - 1))
    return ranks


def seam_distance(ranks):
    """Euclidean distance (px) from each pixel to the nearest seam pixel (inf: no seam)."""
    seam = np.zeros(ranks.shape, dtype=bool)
    for dy, dx in ((0, 1), (1, 0)):
        a = ranks[:ranks.shape[0] - dy, :ranks.shape[1] - dx]
        b = ranks[dy:, dx:]
        edge = (a >= 0) & (b >= 0) & (a != b)
        seam[:ranks.shape[0] - dy, :ranks.shape[1] - dx] |= edge
        seam[dy:, dx:] |= edge
    sy, sx = np.nonzero(seam)
    dist = np.full(ranks.shape, np.inf)
    if len(sy) == 0:
        return dist, seam
    yy, xx = np.mgrid[0:ranks.shape[0], 0:ranks.shape[1]]
    py, px = yy.ravel().astype(np.float64), xx.ravel().astype(np.float64)
    best = np.full(py.shape, np.inf)
    for i in range(0, len(sy), 256):
        d2 = (py[:, None] - sy[None, i:i + 256]) ** 2 + (px[:, None] - sx[None, i:i + 256]) ** 2
        best = np.minimum(best, d2.min(axis=1))
    return np.sqrt(best).reshape(ranks.shape), seam


def worst_tile(diff, surface):
    h, w = diff.shape
    worst = 0.0
    for r0 in range(0, h - TILE + 1, TILE):
        for c0 in range(0, w - TILE + 1, TILE):
            m = surface[r0:r0 + TILE, c0:c0 + TILE]
            if m.any():
                worst = max(worst, float(diff[r0:r0 + TILE, c0:c0 + TILE][m].mean()))
    return worst


runs = {}
for sub in sorted(os.listdir(out)):
    path = os.path.join(out, sub, 'timings.json')
    if sub.startswith('np') and os.path.isfile(path):
        with open(path) as f:
            runs[int(sub[2:])] = json.load(f)
if 1 not in runs:
    sys.exit('no np1/timings.json under %s: the 1-rank run is the reference' % out)

CORES = os.cpu_count() or 1


def peak_rss_mb(n):
    try:
        with open(os.path.join(out, 'np%d' % n, 'pvbatch.log')) as f:
            kb = [int(line.split()[2]) for line in f if line.startswith('rank maxrss_kb')]
        return round(max(kb) / 1024.0) if kb else ''
    except OSError:
        return ''


rows = []
for n in sorted(runs):
    info = runs[n]
    band = 2 * info['steps']
    by_mesh = {}
    for run in info['runs']:
        by_mesh.setdefault(run['mesh'], {})[run['mode']] = run
    for mesh, modes in by_mesh.items():
        ref_modes = {r['mode']: r for r in runs[1]['runs'] if r['mesh'] == mesh}
        ranks_n = rank_image(os.path.join(out, 'np%d' % n, modes['ids']['png']), n)
        ranks_1 = rank_image(os.path.join(out, 'np1', ref_modes['ids']['png']), 1)
        surface = (ranks_n >= 0) & (ranks_1 >= 0)
        dist, seam = seam_distance(ranks_n)
        in_band = surface & (dist <= band)
        far = surface & (dist > 2 * band)
        pieces = sorted(int(v) for v in np.unique(ranks_n[ranks_n >= 0]))
        for mode, run in modes.items():
            if mode == 'ids':
                continue
            g_n = load(os.path.join(out, 'np%d' % n, run['png'])).mean(axis=2)
            g_1 = load(os.path.join(out, 'np1', ref_modes[mode]['png'])).mean(axis=2)
            diff = np.abs(g_n - g_1)
            row = {
                'mesh': mesh, 'triangles': run['triangles'], 'size': '%dx%d' % tuple(info['size']),
                'method': mode, 'ranks': n, 'ms_median': round(run['ms_median'], 1),
                'ms_min': round(run['ms_min'], 1), 'frames': info['frames'],
                'steps_S': info['steps'], 'filter_length_L': info['filter_length'],
                'surface_px': int(surface.sum()), 'ranks_seen': len(pieces),
                'contrast': round(float(g_1[surface].std()), 2),
                'oversubscribed': int(n > CORES), 'run_peak_rss_mb': peak_rss_mb(n),
            }
            if n > 1:
                row.update(
                    mean_diff=round(float(diff[surface].mean()), 2),
                    worst_tile=round(worst_tile(diff, surface), 2),
                    seam_band_diff=round(float(diff[in_band].mean()), 2) if in_band.any() else '',
                    far_diff=round(float(diff[far].mean()), 2) if far.any() else '',
                    band_px=int(in_band.sum()), band_halfwidth_px=band)
                img = np.clip(diff * 8, 0, 255).astype(np.uint8)
                Image.fromarray(img).save(os.path.join(diff_dir, '%s_%s_np%d_vs_np1_x8.png' % (mesh, mode, n)))
            rows.append(row)
            print(' '.join('%s=%s' % kv for kv in row.items()))

order = {'flowsurf': 0, 'lic': 1, 'licenh': 2}
rows.sort(key=lambda r: (r['triangles'], order.get(r['method'], 9), r['ranks']))
fields = ['mesh', 'triangles', 'size', 'method', 'ranks', 'ms_median', 'ms_min', 'frames', 'steps_S',
          'filter_length_L', 'oversubscribed', 'run_peak_rss_mb', 'contrast', 'mean_diff', 'worst_tile', 'seam_band_diff', 'far_diff',
          'band_px', 'band_halfwidth_px', 'surface_px', 'ranks_seen']
with open(csv_path, 'w', newline='') as f:
    w = csv.DictWriter(f, fieldnames=fields)
    w.writeheader()
    for row in rows:
        w.writerow(row)
print(csv_path)
