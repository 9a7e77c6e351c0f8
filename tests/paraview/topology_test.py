"""pvbatch test of the FlowSurf Topology filter (run by tests/paraview/run_topology_test.sh).

  pvbatch topology_test.py PLUGIN OUTDIR serial
      the filter on spheres with known fields: the tangential part of a constant direction
      (a source and a sink, swapped by ReverseField), solid-body rotation (two centres), the
      gradient of (x^2 - y^2)/2 (two sources, two sinks, two saddles and their lines); the
      generated properties and their defaults; errors (no such array, a zero field) reported
      through ParaView and pvbatch running on.
      Then the FlowSurf representation's overlay (FlowSurfTopology on) over the saddle
      field: its red and blue lines drawn untinted over ParaView's colouring, none when off.
  mpiexec -np N pvbatch topology_test.py PLUGIN OUTDIR parallel TAG [render [PARTITIONS]]
      the saddle field on a sphere split over the ranks by RedistributeDataSet (PARTITIONS
      pieces; 0, the default, one per rank; fewer leaves ranks empty); the filter's
      whole output (fetched) into OUTDIR/TAG.json; a zero field and an array missing on
      rank 1: the same error on every rank, no hang. With `render`: the FlowSurf
      representation of the pieces with FlowSurfTopology off and on, its images (and their
      pixels, OUTDIR/TAG_on.npy) saved; then a zero field, whose overlay error (found on
      process 0) is every rank's.
  python3 topology_test.py PLUGIN OUTDIR compare REF TAG...
      each TAG's result equals REF's: the same critical points (type, index, position within
      1e-6 of the extent) and the same number of lines of each kind.
  pvbatch topology_test.py PLUGIN OUTDIR overlay REF TAG...
      each TAG's overlay image equals REF's up to anti-aliasing at the piece seams: mean
      absolute difference <= 0.5 gray levels, every 15x15 tile <= 8, the lines' red and blue
      pixels present; REF's overlay itself (on vs off) far above both, or they could not see
      it wrong.
"""
import json
import math
import sys

PLUGIN, OUT, MODE = sys.argv[1], sys.argv[2], sys.argv[3]
# The tangential part of (x, -y, 0) on the unit sphere, the gradient of (x^2 - y^2)/2:
# sinks at +-x, sources at +-y, saddles at +-z. On a sphere with an odd PhiResolution (no
# vertex ring on the equator): the analysis misses a zero that lies exactly on a vertex away
# from the poles.
SADDLE_SPHERE = dict(Radius=1.0, ThetaResolution=96, PhiResolution=47)
SADDLES = ('coordsX*iHat - coordsY*jHat - (coordsX*coordsX - coordsY*coordsY)*'
           '(coordsX*iHat + coordsY*jHat + coordsZ*kHat)')


def result(topo):
    """The filter's whole output as plain data (Fetch merges the ranks' pieces)."""
    from paraview import servermanager
    from paraview.vtk.util.numpy_support import vtk_to_numpy
    pd = servermanager.Fetch(topo)
    n = pd.GetNumberOfPoints()
    pts = [list(pd.GetPoint(i)) for i in range(n)]
    pdata, cdata = pd.GetPointData(), pd.GetCellData()
    types = vtk_to_numpy(pdata.GetArray('type')).tolist() if n else []
    index = vtk_to_numpy(pdata.GetArray('index')).tolist() if n else []
    names = pdata.GetAbstractArray('type_name')
    points = []
    lines = []
    verts = pd.GetNumberOfVerts()
    kinds = cdata.GetAbstractArray('kind_name')
    for c in range(pd.GetNumberOfCells()):
        cell = pd.GetCell(c)
        ids = [cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())]
        if c < verts:
            i = ids[0]
            points.append({'position': pts[i], 'type': names.GetValue(i), 'type_id': types[i],
                           'index': index[i]})
        else:
            lines.append({'kind': kinds.GetValue(c), 'points': [pts[i] for i in ids],
                          'strength': [float(pdata.GetArray('strength').GetValue(i)) for i in ids]})
    fd = pd.GetFieldData()
    field = {k: int(fd.GetArray(k).GetValue(0)) for k in ('euler_characteristic', 'index_sum', 'closed')
             if fd.GetArray(k)}
    return {'critical_points': points, 'lines': lines, **field}


def near(p, q, tol):
    return math.dist(p, q) <= tol


def expect_points(r, expected, what, tol=0.05):
    """`expected`: (type, position) pairs; each found once, nothing else."""
    got = [(p['type'], p['position']) for p in r['critical_points']]
    print(what, 'points', [(t, [round(x, 3) for x in p]) for t, p in got], flush=True)
    assert len(got) == len(expected), '%s: %d critical points, expected %d' % (what, len(got), len(expected))
    for t, pos in expected:
        assert any(g == t and near(q, pos, tol) for g, q in got), '%s: no %s near %s' % (what, t, pos)


def serial():
    from paraview.simple import LoadPlugin, Sphere, Calculator, UpdatePipeline
    LoadPlugin(PLUGIN, ns=globals())
    sphere = Sphere(Radius=1.0, ThetaResolution=96, PhiResolution=48)
    field = Calculator(Input=sphere, ResultArrayName='V', Function='kHat - coordsZ*(coordsX*iHat + coordsY*jHat + coordsZ*kHat)')
    topo = FlowSurfTopology(Input=field)  # noqa: F821 (made by LoadPlugin)
    # The properties generated from the option table, with its defaults.
    assert topo.ReverseField == 'auto' and topo.Parts == 'points,lines', (topo.ReverseField, topo.Parts)
    assert topo.Scale == 0 and abs(topo.CancelSpeed - 0.01) < 1e-12, (topo.Scale, topo.CancelSpeed)
    assert topo.LineStrength == 4 and abs(topo.LineLength - 0.03) < 1e-12, (topo.LineStrength, topo.LineLength)
    topo.Vectors = ['POINTS', 'V']
    # The flow from the south pole to the north pole: a source and a sink, index sum 2 = chi.
    r = result(topo)
    expect_points(r, [('source', [0, 0, -1]), ('sink', [0, 0, 1])], 'constant direction')
    assert all(p['index'] == 1 for p in r['critical_points']), r['critical_points']
    assert r['euler_characteristic'] == 2 and r['index_sum'] == 2 and r['closed'] == 1, r
    assert [p['type_id'] for p in r['critical_points']].count(0) == 1  # PointType::Source
    topo.ReverseField = 'on'
    expect_points(result(topo), [('sink', [0, 0, -1]), ('source', [0, 0, 1])], 'reversed')
    topo.ReverseField = 'auto'
    # Solid-body rotation: two centres.
    field.Function = '-coordsY*iHat + coordsX*jHat'
    expect_points(result(topo), [('center', [0, 0, -1]), ('center', [0, 0, 1])], 'rotation')
    # The gradient of (x^2 - y^2)/2: every node type and two saddles with their lines.
    sphere.PhiResolution = SADDLE_SPHERE['PhiResolution']
    field.Function = SADDLES
    r = result(topo)
    expect_points(r, [('sink', [1, 0, 0]), ('sink', [-1, 0, 0]), ('source', [0, 1, 0]), ('source', [0, -1, 0]),
                      ('saddle', [0, 0, 1]), ('saddle', [0, 0, -1])], 'saddles')
    assert sorted(p['index'] for p in r['critical_points']) == [-1, -1, 1, 1, 1, 1]
    kinds = [l['kind'] for l in r['lines']]
    print('saddles lines', {k: kinds.count(k) for k in set(kinds)}, flush=True)
    assert r['lines'] and set(kinds) <= {'separation', 'attachment'}, kinds
    assert all(len(l['points']) >= 2 and max(l['strength']) > 0 for l in r['lines'])
    topo.Parts = 'points'
    assert not result(topo)['lines']
    topo.Parts = 'points,lines'
    # Errors: ParaView's error, no output, pvbatch runs on.
    topo.Vectors = ['POINTS', 'NoSuchArray']
    UpdatePipeline(proxy=topo)
    print('MISSING_ARRAY_SURVIVED', flush=True)
    topo.Vectors = ['POINTS', 'V']
    field.Function = '0*iHat'
    UpdatePipeline(proxy=topo)
    print('ZERO_FIELD_SURVIVED', flush=True)
    field.Function = SADDLES
    assert len(result(topo)['critical_points']) == 6
    overlay(field)
    print('PASSED', flush=True)


def line_pixels(view, path):
    """The view's pixels of the overlay's separation red and attachment blue."""
    import numpy as np
    from paraview.simple import Render, SaveScreenshot
    from paraview.vtk.util.numpy_support import vtk_to_numpy
    from paraview.vtk.vtkIOImage import vtkPNGReader
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[300, 300])
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    rgb = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars())[:, :3]
    np.save(path[:-len('.png')] + '.npy', rgb.reshape(300, 300, 3))
    a = rgb.astype(float) / 255
    red = int(np.sum((a[:, 0] > 0.8) & (a[:, 1] < 0.25) & (a[:, 2] < 0.25)))  # (0.95, 0.12, 0.12)
    blue = int(np.sum((a[:, 2] > 0.85) & (a[:, 0] < 0.3) & (a[:, 1] > 0.35) & (a[:, 1] < 0.65)))  # (0.15, 0.5, 1)
    return red, blue


def flowsurf_view(source):
    from paraview.simple import CreateRenderView, Show, ColorBy
    view = CreateRenderView()
    view.ViewSize = [300, 300]
    view.OrientationAxesVisibility = 0
    view.UseFXAA = 0
    rep = Show(source, view)
    rep.SetRepresentationType('FlowSurf')
    rep.FlowSurfVectors = ['POINTS', 'V']
    rep.FlowSurfMethod = 'hybrid'
    ColorBy(rep, ('POINTS', 'V', 'Magnitude'))  # the blend overlay multiplies ParaView's colour
    view.CameraPosition = [2.5, 2.0, 3.0]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    return view, rep


def overlay(field):
    """FlowSurfTopology on: the lines in their own colours over ParaView's (blend overlay and
    gray), none when off; the properties generated from the option table."""
    view, rep = flowsurf_view(field)
    assert rep.FlowSurfTopology == 'off' and rep.FlowSurfTopologyLineWidth == 2.5, rep.FlowSurfTopology
    off = line_pixels(view, OUT + '/overlay_off.png')
    rep.FlowSurfTopology = 'on'
    on = line_pixels(view, OUT + '/overlay_on.png')
    rep.FlowSurfOverlay = 'gray'
    gray = line_pixels(view, OUT + '/overlay_gray.png')
    print('overlay lines (red, blue pixels): off', off, 'on', on, 'gray', gray, flush=True)
    # Two separation and two attachment lines 2.5 px wide across a 300 px view: hundreds of
    # pixels each; none of either colour without the overlay.
    assert off == (0, 0) and min(on) > 100 and min(gray) > 100, (off, on, gray)


RANK_ONE_SCRIPT = '''
from vtkmodules.vtkParallelCore import vtkMultiProcessController
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
if vtkMultiProcessController.GetGlobalController().GetLocalProcessId() == 1:
    %s
'''


def parallel(tag, render, partitions=0):
    from paraview.simple import LoadPlugin, Sphere, Calculator, RedistributeDataSet, ProgrammableFilter, \
        UpdatePipeline
    LoadPlugin(PLUGIN, ns=globals())
    sphere = Sphere(**SADDLE_SPHERE)
    field = Calculator(Input=sphere, ResultArrayName='V', Function=SADDLES)
    split = RedistributeDataSet(Input=field)  # a vtkUnstructuredGrid: the filter's data-set road
    split.NumberOfPartitions = partitions
    odd = ProgrammableFilter(Input=split)
    odd.CopyArrays = 0
    odd.Script = RANK_ONE_SCRIPT % 'pass'
    topo = FlowSurfTopology(Input=odd, Vectors=['POINTS', 'V'])  # noqa: F821
    r = result(topo)
    with open('%s/%s.json' % (OUT, tag), 'w') as f:
        json.dump(r, f)
    kinds = [l['kind'] for l in r['lines']]
    print('RESULT', tag, len(r['critical_points']), 'points', {k: kinds.count(k) for k in set(kinds)}, flush=True)
    # Errors on every rank, no hang: a zero field (found on process 0), an array missing on
    # rank 1 only (with more than one rank).
    field.Function = '0*iHat'
    UpdatePipeline(proxy=topo)
    print('SURVIVED zero', flush=True)
    field.Function = SADDLES
    odd.Script = RANK_ONE_SCRIPT % "out.GetPointData().RemoveArray('V')"
    UpdatePipeline(proxy=topo)
    print('SURVIVED missing', flush=True)
    odd.Script = RANK_ONE_SCRIPT % 'pass'
    assert len(result(topo)['critical_points']) == len(r['critical_points'])
    if render:
        from paraview.simple import ExtractSurface
        view, rep = flowsurf_view(ExtractSurface(Input=odd))
        line_pixels(view, '%s/%s_off.png' % (OUT, tag))
        print('FLOWSURF_STARTED', flush=True)
        rep.FlowSurfTopology = 'on'
        print('OVERLAY', tag, 'lines (red, blue pixels)', line_pixels(view, '%s/%s_on.png' % (OUT, tag)), flush=True)
        field.Function = '0*iHat'  # the overlay's analysis fails (on process 0): every rank's error
        line_pixels(view, '%s/%s_zero.png' % (OUT, tag))
        print('SURVIVED overlay zero', flush=True)
        field.Function = SADDLES
        rep.FlowSurfTopology = 'off'
        line_pixels(view, '%s/%s_off.png' % (OUT, tag))
        print('SURVIVED overlay', flush=True)
    print('DONE', tag, flush=True)


def compare(ref, tags):
    def load(tag):
        with open('%s/%s.json' % (OUT, tag)) as f:
            return json.load(f)
    a = load(ref)
    ok = True
    for tag in tags:
        b = load(tag)
        every = [p['position'] for p in a['critical_points']] + [q for l in a['lines'] for q in l['points']]
        extent = max(max(p[k] for p in every) - min(p[k] for p in every) for k in range(3))
        tol = 1e-6 * extent
        pa, pb = a['critical_points'], b['critical_points']
        unmatched = [p for p in pa if not any(q['type'] == p['type'] and q['index'] == p['index'] and
                                              near(q['position'], p['position'], tol) for q in pb)]
        worst = max((min(math.dist(p['position'], q['position']) for q in pb) for p in pa), default=0)
        kinds = lambda r: {k: [l['kind'] for l in r['lines']].count(k) for k in ('separation', 'attachment')}
        same = len(pa) == len(pb) and not unmatched and kinds(a) == kinds(b)
        print('%s vs %s: %d / %d points, worst distance %.3g (tolerance %.3g), lines %s / %s: %s' %
              (tag, ref, len(pb), len(pa), worst, tol, kinds(b), kinds(a), 'same' if same else 'DIFFERENT'))
        ok = ok and same
    print('PASSED' if ok else 'FAILED')
    sys.exit(0 if ok else 1)


def compare_overlays(ref, tags):
    """The overlay's image at several ranks equals one rank's up to anti-aliasing at the seams."""
    import numpy as np
    load = lambda name: np.load('%s/%s.npy' % (OUT, name)).astype(float)

    def differences(a, b):
        diff = np.abs(a - b).mean(axis=2)  # gray levels, 0..255
        tiles = diff.reshape(300 // 15, 15, 300 // 15, 15).mean(axis=(1, 3))
        return diff.mean(), tiles.max()

    def lines(img):
        red = (img[..., 0] > 204) & (img[..., 1] < 64) & (img[..., 2] < 64)
        blue = (img[..., 2] > 217) & (img[..., 0] < 77) & (img[..., 1] > 89) & (img[..., 1] < 166)
        return int(red.sum()), int(blue.sum())

    a = load(ref + '_on')
    own, own_tile = differences(a, load(ref + '_off'))
    print('%s: the overlay itself (on vs off) mean %.3f, worst tile %.3f gray levels, lines %s' %
          (ref, own, own_tile, lines(a)))
    # The overlay alone must be far above the thresholds, or they could not see it wrong.
    ok = own > 2 * 0.5 and own_tile > 4 * 8 and min(lines(a)) > 100
    for tag in tags:
        b = load(tag + '_on')
        mean, tile = differences(a, b)
        same = mean <= 0.5 and tile <= 8 and min(lines(b)) > 100
        print('%s vs %s: mean %.3f (<= 0.5), worst 15x15 tile %.3f (<= 8) gray levels, lines %s / %s: %s' %
              (tag, ref, mean, tile, lines(b), lines(a), 'same' if same else 'DIFFERENT'))
        ok = ok and same
    print('PASSED' if ok else 'FAILED')
    sys.exit(0 if ok else 1)


if MODE == 'serial':
    serial()
elif MODE == 'parallel':
    parallel(sys.argv[4], len(sys.argv) > 5 and sys.argv[5] == 'render', int(sys.argv[6]) if len(sys.argv) > 6 else 0)
elif MODE == 'overlay':
    compare_overlays(sys.argv[4], sys.argv[5:])
else:
    compare(sys.argv[4], sys.argv[5:])
