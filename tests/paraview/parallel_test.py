"""pvbatch test of FlowSurf on ParaView's distributed engine (run by
tests/paraview/run_parallel_test.sh under mpiexec).

  pvbatch parallel_test.py PLUGIN OUTDIR render TAG PARTITIONS
      renders a spinning sphere split over the ranks by ParaView's RedistributeDataSet
      (PARTITIONS pieces; 0 = one per rank, fewer leaves ranks empty), with each method,
      into OUTDIR/<method>_<TAG>.png, plus the surface mask OUTDIR/mask_<TAG>.png and the
      rank of each pixel's piece OUTDIR/ranks_<TAG>.png (ParaView's process ids).
  python3 parallel_test.py PLUGIN OUTDIR client TAG PARTITIONS PORT
      the same renders through a client connected to a pvserver on localhost:PORT (the
      plugin loaded on both sides), screenshots saved by the client.
  mpiexec ... pvbatch parallel_test.py PLUGIN OUTDIR glerror
      FlowSurf where one rank's OpenGL is too old: the same error on every rank, no hang.
  mpiexec -np 2 pvbatch parallel_test.py PLUGIN OUTDIR oom
      FlowSurf where one rank runs out of memory (its address space capped just above what
      ParaView itself needs at a large view): the same error on every rank, no hang.
  mpiexec -np 2 pvbatch parallel_test.py PLUGIN OUTDIR errors
      inputs that differ between the ranks (the vector array missing on one, pieces of
      different data times): the same error on every rank, no hang, rendering goes on.
  pvbatch parallel_test.py PLUGIN OUTDIR compare REF TAG...
      compares each TAG's images with REF's: the mean absolute gray difference over the
      surface must be <= 1 and every 16x16 tile's mean <= 3; prints the numbers
      and writes |difference| x 8 as OUTDIR/diff_<method>_<TAG>.png.
"""
import os
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from paraview.vtk.util.numpy_support import vtk_to_numpy, numpy_to_vtk

PLUGIN, OUT, MODE = sys.argv[1], sys.argv[2], sys.argv[3]
W = H = 400
METHODS = ('isa', 'ibfvs', 'hybrid')
MODES = ('tiles', 'replicate')  # FlowSurfParallel; the same image at any number of ranks
FRAMES = 8


def read_png(path):
    from paraview.vtk.vtkIOImage import vtkPNGReader
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    im = r.GetOutput()
    a = vtk_to_numpy(im.GetPointData().GetScalars()).astype(np.float64)
    return a.reshape(H, W, -1)[::-1][..., :3]  # rows top-down, RGB


def write_png(path, gray):
    from paraview.vtk.vtkCommonDataModel import vtkImageData
    from paraview.vtk.vtkIOImage import vtkPNGWriter
    im = vtkImageData()
    im.SetDimensions(W, H, 1)
    arr = numpy_to_vtk(np.ascontiguousarray(gray[::-1].reshape(-1)).astype(np.uint8), deep=1)
    im.GetPointData().SetScalars(arr)
    w = vtkPNGWriter()
    w.SetFileName(path)
    w.SetInputData(im)
    w.Write()


def render(TAG, PARTITIONS, server=None):
    if server:  # client-server: the plugin on both sides, the pipeline and rendering remote
        Connect('localhost', server)
        # Render on the server's ranks always (else small data comes to the client to render).
        GetSettingsProxy('RenderViewSettings').RemoteRenderThreshold = 0.0
        LoadPlugin(PLUGIN, remote=False, ns=globals())
        LoadPlugin(PLUGIN, remote=True, ns=globals())
    else:
        LoadPlugin(PLUGIN, ns=globals())
    sphere = Sphere(Radius=1.0, ThetaResolution=192, PhiResolution=96)
    spin = Calculator(Input=sphere, ResultArrayName='V', Function='-coordsY*iHat+coordsX*jHat')
    split = RedistributeDataSet(Input=spin)
    split.NumberOfPartitions = PARTITIONS
    pieces = ExtractSurface(Input=ProcessIdScalars(Input=split))
    view = CreateRenderView()
    if server:
        view.RemoteRenderThreshold = 0.0  # the view's own copy of the setting, as well
    view.ViewSize = [W, H]
    view.OrientationAxesVisibility = 0
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.Background = [0, 0, 0]
    rep = Show(pieces, view)
    rep.ColorArrayName = ['POINTS', '']
    rep.DiffuseColor = [1, 1, 1]
    rep.Ambient, rep.Diffuse = 1.0, 0.0
    Render(view)
    view.CameraPosition, view.CameraFocalPoint = [0.0, -4.0, 3.0], [0.0, 0.0, 0.0]
    view.CameraViewUp, view.CameraViewAngle = [0.0, 0.0, 1.0], 30.0
    SaveScreenshot(os.path.join(OUT, 'mask_%s.png' % TAG), view, ImageResolution=[W, H])
    # The piece each pixel shows: ProcessId as gray (rank r -> 40 + 50 r), flat.
    rep.ColorArrayName = ['POINTS', 'ProcessId']
    lut = GetColorTransferFunction('ProcessId')
    lut.ApplyPreset('Grayscale', True)
    lut.RescaleTransferFunction(-0.8, 4.3)
    rep.MapScalars = 1
    SaveScreenshot(os.path.join(OUT, 'ranks_%s.png' % TAG), view, ImageResolution=[W, H])
    rep.ColorArrayName = ['POINTS', '']
    rep.FlowSurfVectors = ['POINTS', 'V']
    print('FLOWSURF_STARTED', flush=True)  # ParaView rendered; from here a hang is ours
    rep.SetRepresentationType('FlowSurf')
    # Dye released on the front: under tiles each rank advects its piece's part of the band,
    # with a halo from the others (dye/dye_shared.h).
    rep.FlowSurfDye = '0,-0.8,0.6:0.06:red;0.6,-0.8,0.1:0.06:yellow'
    rep.FlowSurfEdgeMask = 1  # IBFVS's outlines: every rank draws every piece's, seams none
    camera = view.GetActiveCamera()
    for mode in MODES:
        rep.FlowSurfParallel = mode
        for method in METHODS:
            rep.FlowSurfMethod = method
            # Still, then orbiting: history carried across tiles while the view moves.
            for k in range(FRAMES):
                if k >= FRAMES // 2:
                    camera.Azimuth(2.0)
                Render(view)
            SaveScreenshot(os.path.join(OUT, '%s_%s_%s.png' % (method, mode, TAG)), view, ImageResolution=[W, H])
            for k in range(FRAMES // 2, FRAMES):
                camera.Azimuth(-2.0)
    # A missing vector array on every rank: ParaView's error on each, no rank left
    # waiting in a collective step (the wrapper's timeout would end a hang).
    rep.FlowSurfVectors = ['POINTS', 'NoSuchArray']
    Render(view)
    print('RENDERED', TAG)


def compare(REF, TAGS):
    mask = read_png(os.path.join(OUT, 'mask_%s.png' % REF)).mean(axis=2) > 128
    failures = []
    for tag, method, mode in [(t, m, o) for t in TAGS for m in METHODS for o in MODES]:
        ref = read_png(os.path.join(OUT, '%s_tiles_%s.png' % (method, REF))).mean(axis=2)
        img = read_png(os.path.join(OUT, '%s_%s_%s.png' % (method, mode, tag))).mean(axis=2)
        diff = np.abs(img - ref)
        mean = diff[mask].mean()
        worst = 0.0
        for r0 in range(0, H, 16):
            for c0 in range(0, W, 16):
                m = mask[r0:r0 + 16, c0:c0 + 16]
                if m.any():
                    worst = max(worst, diff[r0:r0 + 16, c0:c0 + 16][m].mean())
        write_png(os.path.join(OUT, 'diff_%s_%s_%s.png' % (method, mode, tag)), np.clip(diff * 8, 0, 255))
        print('%-6s %-9s %-8s vs %s: mean %.3f, worst 16x16 tile %.3f gray levels (%d surface pixels)'
              % (method, mode, tag, REF, mean, worst, mask.sum()))
        if not (mean == 0.0 and worst == 0.0):
            failures.append('%s %s %s: mean %.3f, worst tile %.3f (both must be 0)' % (method, mode, tag, mean, worst))
    for tag in TAGS:
        ranks = read_png(os.path.join(OUT, 'ranks_%s.png' % tag)).mean(axis=2)
        counts = [int((np.abs(ranks[mask] - (r + 0.8) / 5.1 * 255) < 12).sum()) for r in range(4)]
        print('%s: surface pixels showing the piece of rank 0..3: %s' % (tag, counts))
        if sum(c > 1000 for c in counts) < 2:  # the surface must really be split
            failures.append('%s: the view shows fewer than two pieces %s' % (tag, counts))
    if failures:
        print('FAILED:\n  ' + '\n  '.join(failures))
    else:
        print('PASSED')


# No sys.exit: pvbatch's teardown after it raised an X error (GLXBadContext) here.
def gl_error():
    """One rank without OpenGL 4.5 (MESA_GL_VERSION_OVERRIDE=3.3 on it): every rank reports
    that rank's error, none waits in a collective step, and ParaView goes on rendering."""
    LoadPlugin(PLUGIN, ns=globals())
    sphere = Sphere(Radius=1.0, ThetaResolution=64, PhiResolution=32)
    spin = Calculator(Input=sphere, ResultArrayName='V', Function='-coordsY*iHat+coordsX*jHat')
    pieces = ExtractSurface(Input=RedistributeDataSet(Input=spin))
    view = CreateRenderView()
    view.ViewSize = [200, 200]
    rep = Show(pieces, view)
    Render(view)
    print('FLOWSURF_STARTED', flush=True)
    rep.SetRepresentationType('FlowSurf')
    rep.FlowSurfVectors = ['POINTS', 'V']
    Render(view)
    rep.SetRepresentationType('Surface')
    Render(view)
    print('SURVIVED', flush=True)


# Run on every process by a ProgrammableFilter: passes its input through; on process 1,
# once, caps the address space 256 MiB above what it uses.
CAP_RANK_ONE_SCRIPT = '''
import resource
from vtkmodules.vtkParallelCore import vtkMultiProcessController
self.GetOutput().ShallowCopy(self.GetInput())
if vtkMultiProcessController.GetGlobalController().GetLocalProcessId() == 1:
    size = int(open('/proc/self/statm').read().split()[0]) * resource.getpagesize()
    resource.setrlimit(resource.RLIMIT_AS, (size + (256 << 20), resource.RLIM_INFINITY))
    print('CAPPED at %d MiB' % ((size >> 20) + 256), flush=True)
'''


def out_of_memory():
    """One rank out of memory: after ParaView has rendered the surface at a large view,
    rank 1 caps its address space 256 MiB above what it uses, less than FlowSurf's per-pixel
    buffers there. Every rank reports rank 1's error, none waits, ParaView renders on."""
    LoadPlugin(PLUGIN, ns=globals())
    sphere = Sphere(Radius=1.0, ThetaResolution=64, PhiResolution=32)
    spin = Calculator(Input=sphere, ResultArrayName='V', Function='-coordsY*iHat+coordsX*jHat')
    cap = ProgrammableFilter(Input=ExtractSurface(Input=RedistributeDataSet(Input=spin)))
    cap.CopyArrays = 0
    cap.Script = 'self.GetOutput().ShallowCopy(self.GetInput())'
    view = CreateRenderView()
    view.ViewSize = [3000, 3000]
    rep = Show(cap, view)
    Render(view)
    print('FLOWSURF_STARTED', flush=True)
    cap.Script = CAP_RANK_ONE_SCRIPT
    rep.SetRepresentationType('FlowSurf')
    rep.FlowSurfVectors = ['POINTS', 'V']
    Render(view)
    rep.SetRepresentationType('Surface')
    Render(view)
    print('SURVIVED', flush=True)


# A filter that changes its piece on one process only (Python run on each process).
RANK_ONE_SCRIPT = '''
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkCommonDataModel import vtkDataObject
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
out.GetInformation().Set(vtkDataObject.DATA_TIME_STEP(), 2.5)
if rank == 1:
    %s
'''


def errors():
    """Inputs that differ between the processes: the vector array missing on one, pieces of
    different data times. Every process reports the same error (naming the process), none
    waits in a collective step, and ParaView renders on once the input is whole again."""
    LoadPlugin(PLUGIN, ns=globals())
    sphere = Sphere(Radius=1.0, ThetaResolution=64, PhiResolution=32)
    spin = Calculator(Input=sphere, ResultArrayName='V', Function='-coordsY*iHat+coordsX*jHat')
    pieces = ExtractSurface(Input=RedistributeDataSet(Input=spin))
    odd = ProgrammableFilter(Input=pieces)
    odd.CopyArrays = 0
    view = CreateRenderView()
    view.ViewSize = [200, 200]
    rep = Show(odd, view)
    Render(view)
    print('FLOWSURF_STARTED', flush=True)
    rep.SetRepresentationType('FlowSurf')
    rep.FlowSurfVectors = ['POINTS', 'V']
    for case, change in (('array', "out.GetPointData().RemoveArray('V')"),  # all at time 2.5 but
                         ('time', 'out.GetInformation().Set(vtkDataObject.DATA_TIME_STEP(), 7.5)')):
        print('CASE', case, flush=True)
        odd.Script = RANK_ONE_SCRIPT % change
        Render(view)
        odd.Script = RANK_ONE_SCRIPT % 'pass'
        Render(view)
        print('SURVIVED', case, flush=True)


if MODE == 'render':
    render(sys.argv[4], int(sys.argv[5]))
elif MODE == 'glerror':
    gl_error()
elif MODE == 'oom':
    out_of_memory()
elif MODE == 'errors':
    errors()
elif MODE == 'client':
    render(sys.argv[4], int(sys.argv[5]), int(sys.argv[6]))
else:
    compare(sys.argv[4], sys.argv[5:])
