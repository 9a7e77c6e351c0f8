"""FlowSurf (hybrid) against ParaView's Surface LIC inside ParaView, at N ranks.

Run by bench/paraview/flowsurf_vs_lic.sh as
    mpiexec -np N pvbatch flowsurf_vs_lic.py --plugin FlowSurf.so --out DIR/np{N} ...
(pvbatch runs this script on rank 0; the other ranks serve its pipeline and rendering.)

Per mesh (a unit UV sphere spinning about z, V = omega x p, as tests/paraview/plugin_test.py),
the surface goes Sphere -> Calculator -> RedistributeDataSet (split across the N ranks, cells
assigned to one region) -> ProcessIdScalars (cell array ProcessId), and three views of the same
size and camera (the test's: eye (0,-4,3), up z, 30 degrees) show it:

  ids      plain surface coloured by ProcessId (flat, unlit): where each rank's piece lies
  flowsurf representation FlowSurf, FlowSurfMethod hybrid, FlowSurfFilterLength 2S+1 samples
           FlowSurfLicStepPx 2 px (streak ~ 4S px)
  lic      representation Surface LIC, NumberOfSteps S each way, StepSize such that one step is
           2 px (README, Step size: VTK scales StepSize by sqrt(1/W^2+1/H^2); sqrt(2) at W = H),
           EnhancedLIC off, EnhanceContrast Off, NormalizeVectors on, LICIntensity 0.8, colour
           mode blend (the settings of surface_lic_bench.py and compare.sh)
  licenh   the same with ParaView's default EnhancedLIC on (two LIC passes) and EnhanceContrast
           'LIC Only' (a texture of about FlowSurf's contrast; plain 'lic' is faint)

Surface white, unlit (Ambient 1, Diffuse 0), black background, no scalar colouring, so the gray
is the texture alone. For each view: one screenshot at the reference camera (PNG, compared
across rank counts by compare_ranks.py), then the timing: one warm-up render, then K renders,
each after turning the camera by --azimuth degrees about the view-up axis (so both methods
recompute their LIC; neither caches across camera changes), each timed as Render(view) plus a
1-pixel read-back of rank 0's window (waits for the frame, including IceT's compositing at N>1).
Writes DIR/np{N}/timings.json and the PNGs.
"""
import argparse
import json
import math
import os
import resource
import statistics
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from paraview.vtk.vtkCommonCore import vtkUnsignedCharArray

ap = argparse.ArgumentParser()
ap.add_argument('--plugin', required=True)
ap.add_argument('--out', required=True)
ap.add_argument('--meshes', default='sphere:37056',
                help='NAME:TRIANGLES,... (UV spheres; TRIANGLES ~ 2*theta*(phi-2), theta = 2 phi)')
ap.add_argument('--size', default='400x400')
ap.add_argument('--steps', type=int, default=15, help='Surface LIC steps each way S; FlowSurf L = 2S+1')
ap.add_argument('--frames', type=int, default=9, help='timed renders K per view')
ap.add_argument('--azimuth', type=float, default=0.5, help='degrees of camera turn per timed render')
ap.add_argument('--modes', default='ids,flowsurf,lic,licenh')
ap.add_argument('--surface-raster', default='auto', help="FlowSurf's FlowSurfSurfaceRaster: auto, gl or compute")
args = ap.parse_args()

LoadPlugin(args.plugin, ns=globals())
W, H = (int(v) for v in args.size.split('x'))
NRANKS = servermanager.ActiveConnection.GetNumberOfDataPartitions()
os.makedirs(args.out, exist_ok=True)
EYE, TARGET, UP, FOV = [0.0, -4.0, 3.0], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 30.0
# One Surface LIC step = StepSize * sqrt(1 + (W/H)^2) px along x (README, Step size): 2 px.
LIC_STEP = 2.0 / math.sqrt(math.sqrt(1 + (W / H) ** 2) * math.sqrt(1 + (H / W) ** 2))


def sphere_resolution(triangles):
    """theta, phi with theta = 2 phi and 2 theta (phi - 2) closest to the request."""
    best = None
    for phi in range(4, 20000):
        theta = 2 * phi
        t = 2 * theta * (phi - 2)
        if best is None or abs(t - triangles) < abs(best[2] - triangles):
            best = (theta, phi, t)
        if t > triangles:
            break
    return best


def make_view():
    view = CreateRenderView()
    view.ViewSize = [W, H]
    view.OrientationAxesVisibility = 0
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.Background = [0, 0, 0]
    return view


def reference_camera(view):
    view.CameraPosition, view.CameraFocalPoint = EYE, TARGET
    view.CameraViewUp, view.CameraViewAngle = UP, FOV


def sync_render(view, pixel):
    """Render and read one pixel back from rank 0's window: the frame is finished."""
    Render(view)
    view.GetRenderWindow().GetRGBACharPixelData(0, 0, 0, 0, 0, pixel)


def rss_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


results = {'ranks': NRANKS, 'size': [W, H], 'steps': args.steps, 'filter_length': 2 * args.steps + 1,
           'frames': args.frames, 'azimuth_deg': args.azimuth, 'lic_step_size': LIC_STEP, 'runs': []}
for spec in args.meshes.split(','):
    name, tris = spec.split(':')
    theta, phi, ntri = sphere_resolution(int(tris))
    t0 = time.perf_counter()
    sphere = Sphere(Radius=1.0, ThetaResolution=theta, PhiResolution=phi)
    spin = Calculator(Input=sphere, ResultArrayName='V', Function='-coordsY*iHat+coordsX*jHat')
    split = RedistributeDataSet(Input=spin)
    split.BoundaryMode = 'Assign to one region'
    ids = ProcessIdScalars(Input=split)
    ids.CellScalars = 1
    ids.UpdatePipeline()
    pipeline_s = time.perf_counter() - t0
    print('%s: %d triangles (theta %d, phi %d), %d ranks, pipeline %.1f s, rank 0 max RSS %.0f MB'
          % (name, ntri, theta, phi, NRANKS, pipeline_s, rss_mb()), flush=True)
    for mode in args.modes.split(','):
        view = make_view()
        rep = Show(ids, view)
        rep.DiffuseColor = [1, 1, 1]
        rep.Ambient, rep.Diffuse, rep.Specular = 1.0, 0.0, 0.0
        Render(view)  # the first render resets the camera: set ours after it
        reference_camera(view)
        if mode == 'ids':
            ColorBy(rep, ('CELLS', 'ProcessId'))
            lut = GetColorTransferFunction('ProcessId')
            top = max(1, NRANKS - 1)
            lut.ColorSpace = 'RGB'  # rank k: (1 - t, 0, t), t = k / (N - 1); compare_ranks decodes t
            lut.RGBPoints = [0.0, 1.0, 0.0, 0.0, float(top), 0.0, 0.0, 1.0]
            lut.AutomaticRescaleRangeMode = 'Never'
            lut.RescaleTransferFunction(0.0, float(top))
            rep.InterpolateScalarsBeforeMapping = 1
        else:
            ColorBy(rep, None)
            if mode == 'flowsurf':
                rep.SetRepresentationType('FlowSurf')
                rep.FlowSurfVectors = ['POINTS', 'V']
                rep.FlowSurfMethod = 'hybrid'
                rep.FlowSurfFilterLength = 2 * args.steps + 1
                rep.FlowSurfLicStepPx = 2.0
                rep.FlowSurfSurfaceRaster = args.surface_raster
            elif mode in ('lic', 'licenh'):
                rep.SetRepresentationType('Surface LIC')
                rep.SelectInputVectors = ['POINTS', 'V']
                rep.NumberOfSteps = args.steps
                rep.StepSize = LIC_STEP
                rep.EnhancedLIC = 1 if mode == 'licenh' else 0
                rep.EnhanceContrast = 'LIC Only' if mode == 'licenh' else 'Off'
                rep.NormalizeVectors = 1
                rep.LICIntensity = 0.8
                rep.ColorMode = 'Blend'
                rep.UseLICForLOD = 1
            else:
                raise SystemExit('unknown mode ' + mode)
        t0 = time.perf_counter()
        png = os.path.join(args.out, '%s_%s.png' % (name, mode))
        SaveScreenshot(png, view, ImageResolution=[W, H])
        first_ms = (time.perf_counter() - t0) * 1e3
        run = {'mesh': name, 'triangles': ntri, 'mode': mode, 'png': os.path.basename(png),
               'first_screenshot_ms': first_ms, 'pipeline_s': pipeline_s}
        if mode != 'ids':
            pixel = vtkUnsignedCharArray()
            sync_render(view, pixel)  # warm-up
            ms = []
            cam = view.GetActiveCamera()
            for _ in range(args.frames):
                cam.Azimuth(args.azimuth)
                t0 = time.perf_counter()
                sync_render(view, pixel)
                ms.append((time.perf_counter() - t0) * 1e3)
            run.update(ms_median=statistics.median(ms), ms_min=min(ms), ms_all=ms)
            print('  %-8s median %7.1f ms/render (min %.1f, first screenshot %.0f ms)'
                  % (mode, run['ms_median'], run['ms_min'], first_ms), flush=True)
        run['rank0_max_rss_mb'] = rss_mb()
        results['runs'].append(run)
        Delete(rep)
        Delete(view)
        del rep, view
    for proxy in (ids, split, spin, sphere):
        Delete(proxy)
    with open(os.path.join(args.out, 'timings.json'), 'w') as f:
        json.dump(results, f, indent=1)
print('DONE', flush=True)
