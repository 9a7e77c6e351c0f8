"""ParaView's own cost per render around FlowSurf's (bench/paraview/scaling.sh's scene and
camera): the same view and 1M-triangle split sphere shown as ParaView's plain Surface and
with nothing visible, each timed as scaling.py times FlowSurf (a camera turn, Render, a
1-pixel read-back). What a FlowSurf render at N ranks cannot divide: the view's fixed cost
and IceT's compositing. Run as scaling.py: mpiexec -np N pvbatch paraview_base.py --size WxH."""
import argparse
import statistics
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from paraview.vtk.vtkCommonCore import vtkUnsignedCharArray

ap = argparse.ArgumentParser()
ap.add_argument('--size', default='1024x1024')
ap.add_argument('--triangles', type=int, default=1000000)
ap.add_argument('--frames', type=int, default=9)
args = ap.parse_args()
W, H = (int(v) for v in args.size.split('x'))
phi = 4
while 4 * (phi + 1) * (phi - 1) < args.triangles:
    phi += 1
sphere = Sphere(Radius=1.0, ThetaResolution=2 * phi, PhiResolution=phi)
split = RedistributeDataSet(Input=sphere)
split.BoundaryMode = 'Assign to one region'
surface = ExtractSurface(Input=split)
view = CreateRenderView()
view.ViewSize = [W, H]
view.OrientationAxesVisibility = 0
rep = Show(surface, view)
rep.ColorArrayName = ['POINTS', '']
rep.Ambient, rep.Diffuse, rep.Specular = 1.0, 0.0, 0.0
Render(view)
view.CameraPosition, view.CameraFocalPoint = [0.0, -4.0, 3.0], [0.0, 0.0, 0.0]
view.CameraViewUp, view.CameraViewAngle = [0.0, 0.0, 1.0], 30.0
camera = view.GetActiveCamera()
pixel = vtkUnsignedCharArray()
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
for shown in ('Surface', 'nothing'):
    if shown == 'nothing':
        Hide(surface, view)
    Render(view)
    ms = []
    for k in range(args.frames):
        camera.Azimuth(0.5)
        t = time.perf_counter()
        Render(view)
        view.GetRenderWindow().GetRGBACharPixelData(0, 0, 0, 0, 0, pixel)
        ms.append((time.perf_counter() - t) * 1e3)
    print('paraview %s, %d ranks: median %.1f ms per render' % (shown, ranks, statistics.median(ms)), flush=True)
