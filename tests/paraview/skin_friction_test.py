"""pvbatch test of the FlowSurf Skin Friction filter (run by tests/paraview/run_skin_friction_test.sh).

  pvbatch skin_friction_test.py PLUGIN CASE
      ParaView's own OpenFOAM reader on the shipped laminar cavity (internalMesh and the two
      wall patches), the filter with the case's viscosity: its skin-friction against OpenFOAM's
      wallShearStress (negated, tangential part) face by face, as the unit test does for
      flowsurf's reader; then the internal mesh alone (its boundary is the wall); then an input
      without volume: an error through ParaView, and pvbatch running on.
"""
import math
import sys

from paraview.simple import LoadPlugin, OpenFOAMReader
from paraview import servermanager
from paraview.vtk.util.numpy_support import vtk_to_numpy
import numpy as np

PLUGIN, CASE = sys.argv[1], sys.argv[2]
LoadPlugin(PLUGIN, ns=globals())  # defines FlowSurfSkinFriction here


def leaves(data):
    it = data.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        yield it.GetCurrentDataObject()
        it.GoToNextItem()


reader = OpenFOAMReader(FileName=CASE)
reader.MeshRegions = ['internalMesh', 'patch/movingWall', 'patch/fixedWalls']
reader.CellArrays = ['U', 'wallShearStress']
reader.Decomposepolyhedra = 0
reader.UpdatePipeline(1.0)
sf = FlowSurfSkinFriction(Input=reader, Viscosity=0.01)
sf.UpdatePipeline(1.0)
out = servermanager.Fetch(sf)
angles, ratios, faces = [], [], 0
for patch in leaves(out):
    tau = vtk_to_numpy(patch.GetCellData().GetArray('skin-friction'))
    wss = vtk_to_numpy(patch.GetCellData().GetArray('wallShearStress'))
    for f in range(patch.GetNumberOfCells()):
        ids = patch.GetCell(f).GetPointIds()
        p = np.array([patch.GetPoint(ids.GetId(k)) for k in range(ids.GetNumberOfIds())])
        n = np.cross(p[1] - p[0], p[2] - p[0])
        n /= np.linalg.norm(n)
        t = -(wss[f] - np.dot(wss[f], n) * n)
        c = np.dot(tau[f], t) / (np.linalg.norm(tau[f]) * np.linalg.norm(t))
        angles.append(math.degrees(math.acos(max(-1.0, min(1.0, c)))))
        ratios.append(np.linalg.norm(tau[f]) / np.linalg.norm(t))
        faces += 1
median_angle, median_ratio = float(np.median(angles)), float(np.median(ratios))
within10 = sum(a <= 10 for a in angles) / len(angles)
print("cavity: %d wall faces, median angle %.2f deg, %.1f %% within 10 deg, median ratio %.3f"
      % (faces, median_angle, 100 * within10, median_ratio))
assert faces == 80, faces
assert median_angle < 1.0 and within10 > 0.95 and abs(median_ratio - 1) < 0.02

# The internal mesh alone: its boundary surface (walls and the empty front and back) carries it.
volume = OpenFOAMReader(FileName=CASE)
volume.MeshRegions = ['internalMesh']
volume.CellArrays = ['U']
boundary = servermanager.Fetch(FlowSurfSkinFriction(Input=volume, Viscosity=0.01))
block = next(leaves(boundary))
assert block.GetCellData().GetArray('skin-friction') is not None
assert block.GetNumberOfCells() == 80 + 800, block.GetNumberOfCells()

# No volume: ParaView reports the filter's error, and pvbatch goes on.
patches = OpenFOAMReader(FileName=CASE)
patches.MeshRegions = ['patch/movingWall']
bad = FlowSurfSkinFriction(Input=patches)
bad.UpdatePipeline(1.0)
print("NO_VOLUME_SURVIVED")
print("PASSED")
