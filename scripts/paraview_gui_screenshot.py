"""Startup script for the ParaView GUI (paraview --script=THIS), run by
scripts/paraview-gui-screenshot.sh: shows a surface with the FlowSurf representation, as a
user would by picking FlowSurf in the representation menu and a vector array in
FlowSurfVectors, coloured by a scalar through ParaView's own colour map.

Environment: FLOWSURF_GUI_DATA (a .vtp with point arrays; empty: a generated spinning
sphere), FLOWSURF_GUI_VECTORS, FLOWSURF_GUI_COLOR (array names), FLOWSURF_GUI_METHOD
(isa, ibfvs, hybrid). The plugin is loaded by the GUI itself (PV_PLUGIN_PATH).
"""
import os

from paraview.simple import *  # noqa: F401,F403

data = os.environ.get('FLOWSURF_GUI_DATA', '')
vectors = os.environ.get('FLOWSURF_GUI_VECTORS', 'wallShearStress')
color = os.environ.get('FLOWSURF_GUI_COLOR', 'p')
method = os.environ.get('FLOWSURF_GUI_METHOD', 'hybrid')

if data:
    src = XMLPolyDataReader(registrationName=os.path.basename(data), FileName=[data])
else:
    sphere = Sphere(Radius=1.0, ThetaResolution=192, PhiResolution=96)
    src = Calculator(registrationName='spin', Input=sphere, ResultArrayName='V',
                     Function='-coordsY*iHat+coordsX*jHat')
    vectors, color = 'V', 'V'
SetActiveSource(src)

view = GetActiveViewOrCreate('RenderView')
view.OrientationAxesVisibility = 1
rep = Show(src, view)
rep.SetRepresentationType('FlowSurf')
rep.FlowSurfMethod = method
rep.FlowSurfVectors = ['POINTS', vectors]
ColorBy(rep, ('POINTS', color))
rep.RescaleTransferFunctionToDataRange(True, False)
rep.SetScalarBarVisibility(view, True)

if data:
    # windAroundBuildings: an oblique look down onto the buildings and the ground
    view.CameraFocalPoint = [155.0, 90.0, 0.0]
    view.CameraPosition = [155.0 - 150.0, 90.0 - 380.0, 330.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
if data:
    view.GetActiveCamera().Dolly(1.3)
Render(view)
