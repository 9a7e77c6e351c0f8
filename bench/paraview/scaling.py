"""FlowSurf's strong scaling on ParaView's engine: ms per render of each method at N ranks.

Run by bench/paraview/scaling.sh as
    mpiexec -np N pvbatch scaling.py --plugin FlowSurf.so --out DIR --parallel tiles|replicate ...

The surface is a unit UV sphere spinning about z (V = omega x p) of about --triangles
triangles, split over the ranks by RedistributeDataSet, shown with the FlowSurf
representation (white, unlit: the gray is the texture). Per method (hybrid with L = 31, ISA,
IBFVS): one warm-up render, then --frames renders each after turning the camera by
--azimuth degrees (every render is a dynamic frame: new G-buffers, exchange, image stages),
each timed as Render(view) plus a 1-pixel read-back of rank 0's window (the frame, IceT's
compositing included, is finished). Then the same loop with ParaView's Outline
representation of the same data (12 lines): what ParaView's own frame costs at this size and
rank count whatever is shown ("paraview_ms"). Writes DIR/timings.json (median and every
render's ms) and DIR/<method>.png (the last image, for comparing across rank counts).
"""
import argparse
import json
import os
import statistics
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from paraview.vtk.vtkCommonCore import vtkUnsignedCharArray

ap = argparse.ArgumentParser()
ap.add_argument('--plugin', required=True)
ap.add_argument('--out', required=True)
ap.add_argument('--triangles', type=int, default=1000000)
ap.add_argument('--size', default='1024x1024')
ap.add_argument('--methods', default='hybrid,isa,ibfvs')
ap.add_argument('--parallel', default='tiles', help="FlowSurfParallel: tiles or replicate")
ap.add_argument('--frames', type=int, default=9)
ap.add_argument('--azimuth', type=float, default=0.5)
ap.add_argument('--surface-raster', choices=['auto', 'gl', 'compute'], default='auto',
                help="FlowSurfSurfaceRaster: who rasterises the surface (auto: flowsurf's rule)")
ap.add_argument('--fxaa', choices=['default', 'on', 'off'], default='default',
                help="the view's FXAA: ParaView's setting (on in 5.11), or forced on or off")
args = ap.parse_args()

LoadPlugin(args.plugin, ns=globals())
W, H = (int(v) for v in args.size.split('x'))
NRANKS = servermanager.ActiveConnection.GetNumberOfDataPartitions()
os.makedirs(args.out, exist_ok=True)


def sphere_resolution(triangles):
    """theta = 2 phi with 2 theta (phi - 2) triangles closest to the request."""
    phi = 4
    while 4 * (phi + 1) * (phi - 1) < triangles:
        phi += 1
    return 2 * phi, phi, 4 * phi * (phi - 2)


theta, phi, ntri = sphere_resolution(args.triangles)
t0 = time.perf_counter()
sphere = Sphere(Radius=1.0, ThetaResolution=theta, PhiResolution=phi)
spin = Calculator(Input=sphere, ResultArrayName='V', Function='-coordsY*iHat+coordsX*jHat')
split = RedistributeDataSet(Input=spin)
split.BoundaryMode = 'Assign to one region'
surface = ExtractSurface(Input=split)
surface.UpdatePipeline()
print('sphere: %d triangles, %d ranks, pipeline %.1f s' % (ntri, NRANKS, time.perf_counter() - t0), flush=True)

view = CreateRenderView()
view.ViewSize = [W, H]
view.OrientationAxesVisibility = 0
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.Background = [0, 0, 0]
if args.fxaa != 'default':
    view.UseFXAA = int(args.fxaa == 'on')
rep = Show(surface, view)
rep.DiffuseColor = [1, 1, 1]
rep.Ambient, rep.Diffuse, rep.Specular = 1.0, 0.0, 0.0
rep.ColorArrayName = ['POINTS', '']
Render(view)
print('FIRST_RENDER', flush=True)  # past ParaView's start-up (scaling.sh watches for it)
view.CameraPosition, view.CameraFocalPoint = [0.0, -4.0, 3.0], [0.0, 0.0, 0.0]
view.CameraViewUp, view.CameraViewAngle = [0.0, 0.0, 1.0], 30.0
rep.SetRepresentationType('FlowSurf')
rep.FlowSurfVectors = ['POINTS', 'V']
rep.FlowSurfParallel = args.parallel
rep.FlowSurfSurfaceRaster = args.surface_raster
rep.FlowSurfFilterLength = 31
camera = view.GetActiveCamera()
pixel = vtkUnsignedCharArray()

results = {'ranks': NRANKS, 'triangles': ntri, 'size': [W, H], 'parallel': args.parallel,
           'surface_raster': args.surface_raster,
           'frames': args.frames, 'azimuth_deg': args.azimuth, 'fxaa': int(view.UseFXAA), 'methods': {}}


def timed_renders():
    """--frames renders, each after turning the camera; ms of each, the camera turned back."""
    ms = []
    for k in range(args.frames):
        camera.Azimuth(args.azimuth)
        t = time.perf_counter()
        Render(view)
        view.GetRenderWindow().GetRGBACharPixelData(0, 0, 0, 0, 0, pixel)
        ms.append((time.perf_counter() - t) * 1e3)
    camera.Azimuth(-args.azimuth * args.frames)
    return ms


for method in args.methods.split(','):
    rep.FlowSurfMethod = method
    Render(view)  # warm-up: programs, buffers, the first split
    ms = timed_renders()
    SaveScreenshot(os.path.join(args.out, '%s.png' % method), view, ImageResolution=[W, H])
    results['methods'][method] = {'median_ms': statistics.median(ms), 'ms': ms}
    print('%-6s %s %d ranks: median %.1f ms per render (%s)'
          % (method, args.parallel, NRANKS, statistics.median(ms), ' '.join('%.0f' % v for v in ms)), flush=True)
rep.SetRepresentationType('Outline')
Render(view)
ms = timed_renders()
results['paraview_ms'] = statistics.median(ms)
print('ParaView alone (Outline) %d ranks: median %.1f ms per render' % (NRANKS, statistics.median(ms)), flush=True)
with open(os.path.join(args.out, 'timings.json'), 'w') as f:
    json.dump(results, f, indent=1)
print('DONE', flush=True)
