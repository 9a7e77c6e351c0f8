"""pvbatch test of the FlowSurf plugin (run by tests/paraview/run_plugin_test.sh).

A unit sphere spinning about z (V = omega x p) seen obliquely; for each method the
screenshot's streak orientation (structure tensor per 16x16 tile) is compared with the
field projected through the same camera (ray-cast here). Then: properties change the
picture; a missing vector array leaves ParaView's error, not a crash (the wrapper checks
the message). Usage: pvbatch plugin_test.py PLUGIN.so OUTDIR
"""
import math
import os
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from paraview.vtk.util.numpy_support import vtk_to_numpy

PLUGIN, OUT = sys.argv[1], sys.argv[2]
W = H = 400
EYE, TARGET, UP, FOV = np.array([0.0, -4.0, 3.0]), np.zeros(3), np.array([0.0, 0.0, 1.0]), 30.0
LoadPlugin(PLUGIN, ns=globals())
from paraview.vtk.vtkCommonCore import vtkLogger  # noqa: E402
vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_1)  # the mapper's choice of surface pass

sphere = Sphere(Radius=1.0, ThetaResolution=192, PhiResolution=96)
spin = Calculator(Input=sphere, ResultArrayName='V', Function='-coordsY*iHat+coordsX*jHat')
view = CreateRenderView()
view.ViewSize = [W, H]
view.OrientationAxesVisibility = 0
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.Background = [0, 0, 0]
rep = Show(spin, view)
rep.FlowSurfVectors = ['POINTS', 'V']
rep.ColorArrayName = ['POINTS', '']
rep.DiffuseColor = [1, 1, 1]
rep.Ambient, rep.Diffuse = 1.0, 0.0  # no shading: the structure is the texture alone
Render(view)  # the first render resets the camera: set ours after it
view.CameraPosition, view.CameraFocalPoint = list(EYE), list(TARGET)
view.CameraViewUp, view.CameraViewAngle = list(UP), FOV
# FlowSurf after the camera is set: ISA/IBFVS warm up under this view. (A camera jump
# afterwards would advance one frame with the --on-camera-move remedy, as in the GUI.)
rep.SetRepresentationType('FlowSurf')


def shot(name):
    path = os.path.join(OUT, name + '.png')
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[W, H])
    img = FetchScreenshot(path)
    return img


def FetchScreenshot(path):
    from paraview.vtk.vtkIOImage import vtkPNGReader
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    im = r.GetOutput()
    a = vtk_to_numpy(im.GetPointData().GetScalars()).astype(np.float64)
    a = a.reshape(H, W, -1)[::-1]  # rows top-down
    return a[..., :3].mean(axis=2)


def camera_basis():
    f = TARGET - EYE
    f /= np.linalg.norm(f)
    r = np.cross(f, UP)
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    return f, r, u, math.tan(math.radians(FOV) / 2)


def project(p):
    f, r, u, t = camera_basis()
    d = p - EYE
    z = d @ f
    x, y = (d @ r) / (z * t), (d @ u) / (z * t)
    return np.array([(x + 1) / 2 * W, (1 - y) / 2 * H])  # (col, row)


def field_angle(col, row):
    """Angle (deg, mod 180, image col/row axes) of the projected field at a pixel; None off
    the sphere, near its silhouette or where the field is slow."""
    f, r, u, t = camera_basis()
    x, y = (col + 0.5) / W * 2 - 1, 1 - (row + 0.5) / H * 2
    d = f + x * t * r + y * t * u
    d /= np.linalg.norm(d)
    b = EYE @ d
    disc = b * b - (EYE @ EYE - 1.0)
    if disc <= 0:
        return None
    p = EYE + (-b - math.sqrt(disc)) * d
    if abs(p @ (EYE - p) / np.linalg.norm(EYE - p)) < 0.35:  # grazing: near the silhouette
        return None
    v = np.array([-p[1], p[0], 0.0])
    if np.linalg.norm(v) < 0.3:  # near the pole
        return None
    m = project(p + 1e-3 * v) - project(p)
    return math.degrees(math.atan2(m[1], m[0])) % 180.0


def orientation_error(gray, tile=16):
    gy, gx = np.gradient(gray)
    errs = []
    for r0 in range(0, H, tile):
        for c0 in range(0, W, tile):
            want = field_angle(c0 + tile / 2, r0 + tile / 2)
            if want is None:
                continue
            sx, sy = gx[r0:r0 + tile, c0:c0 + tile], gy[r0:r0 + tile, c0:c0 + tile]
            jxx, jyy, jxy = (sx * sx).sum(), (sy * sy).sum(), (sx * sy).sum()
            grad = 0.5 * math.degrees(math.atan2(2 * jxy, jxx - jyy))
            got = (grad + 90.0) % 180.0
            e = abs(got - want) % 180.0
            errs.append(min(e, 180.0 - e))
    return float(np.median(errs)), len(errs)


failures = []
images = {}
for method in ('isa', 'ibfvs', 'hybrid'):
    rep.FlowSurfMethod = method
    images[method] = shot('sphere_' + method)
    err, n = orientation_error(images[method])
    print('orientation %-6s median error %.2f deg over %d tiles' % (method, err, n))
    if not err <= 10.0:
        failures.append('%s: streak orientation off by %.1f deg (> 10)' % (method, err))

# While an animation plays (the view time changes) ISA and IBFVS advance one frame per
# render; a render at the same time and camera shows the same texture.
for method in ('isa', 'ibfvs'):
    rep.FlowSurfMethod = method
    still = [shot('%s_still_%d' % (method, k)) for k in range(2)]
    played = []
    for t in (1.0, 2.0):
        view.ViewTime = t
        played.append(shot('%s_time_%g' % (method, t)))
    view.ViewTime = 0.0
    same = np.abs(still[1] - still[0]).mean()
    steps = [np.abs(played[0] - still[1]).mean(), np.abs(played[1] - played[0]).mean()]
    print('%s: still render changes %.3f gray levels; each played frame %.2f, %.2f' % ((method, same) + tuple(steps)))
    if same != 0.0:
        failures.append('%s: a render without a new time or camera changed the texture (%.3f)' % (method, same))
    if not min(steps) > 0.5:
        failures.append('%s: a new view time did not advance the texture (%.2f, %.2f)' % ((method,) + tuple(steps)))
rep.FlowSurfMethod = 'hybrid'

# Properties change the picture (each against the hybrid default above).
for prop, value in (('FlowSurfFilterLength', 9), ('FlowSurfNoiseSize', '128'), ('FlowSurfOverlay', 'gray')):
    default = getattr(rep, prop)
    setattr(rep, prop, value)
    changed = np.abs(shot('sphere_hybrid_' + prop) - images['hybrid']).mean()
    print('%s = %s: mean |difference| %.2f gray levels' % (prop, value, changed))
    if not changed > 2.0:
        failures.append('%s did not change the picture (%.2f)' % (prop, changed))
    setattr(rep, prop, default)
rep.FlowSurfMethod = 'isa'
rep.FlowSurfStepPx = 1.0
changed = np.abs(shot('sphere_isa_step1') - images['isa']).mean()
print('FlowSurfStepPx = 1 (isa): mean |difference| %.2f gray levels' % changed)
if not changed > 2.0:
    failures.append('FlowSurfStepPx did not change the picture (%.2f)' % changed)

# One surface pass: where the composite can reproduce ParaView's look of the surface (solid or
# point-array colours through the lookup table, ambient + diffuse under ParaView's lights) the
# plugin skips ParaView's own surface pass. With texture strength 0 the picture must then
# equal ParaView's plain Surface representation of the same colouring; so must the fallback
# (a specular highlight: ParaView draws the surface first, the texture is multiplied on).
rep.FlowSurfMethod = 'hybrid'
rep.FlowSurfOverlay = 'blend'
rep.FlowSurfBeta = 0.0
rep.Ambient, rep.Diffuse = 0.15, 0.85
for case, coloring, specular in (('magnitude', ('POINTS', 'V', 'Magnitude'), 0.0),
                                 ('component', ('POINTS', 'V', 'X'), 0.0),
                                 ('solid', None, 0.0),
                                 ('specular', ('POINTS', 'V', 'Magnitude'), 0.6)):
    ColorBy(rep, coloring)
    if coloring:
        rep.RescaleTransferFunctionToDataRange(True, False)
    rep.Specular = specular
    rep.SetRepresentationType('Surface')
    ref = shot('look_%s_paraview' % case)
    rep.SetRepresentationType('FlowSurf')
    got = shot('look_%s_flowsurf' % case)
    surf = (ref > 2) | (got > 2)
    diff = np.abs(got - ref)[surf].mean()
    print('look %-9s: FlowSurf (beta 0) vs ParaView Surface: mean |difference| %.2f gray levels over %d px'
          % (case, diff, surf.sum()))
    if not diff <= 3.0:
        failures.append('look %s: FlowSurf with beta 0 differs from ParaView\'s colouring by %.2f' % (case, diff))
ColorBy(rep, None)
rep.Specular = 0.0
rep.Ambient, rep.Diffuse = 1.0, 0.0
rep.FlowSurfBeta = 0.55

# A missing vector array: ParaView's error (checked by the wrapper), the surface still drawn.
rep.FlowSurfVectors = ['POINTS', 'NoSuchArray']
plain = shot('sphere_missing_array')
print('missing array: surface mean %.1f' % plain[H // 2 - 20:H // 2 + 20, W // 2 - 20:W // 2 + 20].mean())
print('MISSING_ARRAY_SURVIVED')

if failures:
    print('FAILED:\n  ' + '\n  '.join(failures))
    sys.exit(1)
print('PASSED')
