#include "polydata_to_mesh.h"

#include "core/errors.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

namespace flowsurf::paraview {

namespace {

void appendPolyData(vtkPolyData* pd, const std::string& vectors, core::SurfaceMesh& mesh, bool& normalsMissing)
{
  const vtkIdType n = pd->GetNumberOfPoints();
  if (n == 0 || (pd->GetNumberOfPolys() == 0 && pd->GetNumberOfStrips() == 0))
  {
    return;
  }
  vtkDataArray* v = pd->GetPointData()->GetArray(vectors.c_str());
  if (!v || v->GetNumberOfComponents() != 3)
  {
    throw FieldError("FlowSurf: the surface has no 3-component point array '" + vectors +
      "' (FlowSurfVectors): pick one of its point vector arrays");
  }
  vtkDataArray* normals = pd->GetPointData()->GetNormals();
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    normalsMissing = true;
  }
  const uint32_t base = uint32_t(mesh.positions.size());
  if (mesh.fields.empty())
  {
    mesh.fields.push_back({ vectors, {} });
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], w[3];
    pd->GetPoint(i, p);
    v->GetTuple(i, w);
    mesh.positions.emplace_back(p[0], p[1], p[2]);
    mesh.fields[0].values.emplace_back(w[0], w[1], w[2]);
    if (!normalsMissing)
    {
      double nn[3];
      normals->GetTuple(i, nn);
      mesh.normals.emplace_back(nn[0], nn[1], nn[2]);
    }
  }
  // Polygons as fans, strips with alternating winding.
  auto polys = vtk::TakeSmartPointer(pd->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    polys->GetCurrentCell(count, ids);
    for (vtkIdType k = 2; k < count; ++k)
    {
      mesh.triangles.emplace_back(base + ids[0], base + ids[k - 1], base + ids[k]);
    }
  }
  auto strips = vtk::TakeSmartPointer(pd->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    strips->GetCurrentCell(count, ids);
    for (vtkIdType k = 2; k < count; ++k)
    {
      if (k % 2 == 0)
        mesh.triangles.emplace_back(base + ids[k - 2], base + ids[k - 1], base + ids[k]);
      else
        mesh.triangles.emplace_back(base + ids[k - 1], base + ids[k - 2], base + ids[k]);
    }
  }
}

}  // namespace

core::SurfaceMesh toSurfaceMesh(vtkDataObject* data, const std::string& vectors)
{
  core::SurfaceMesh mesh;
  bool normalsMissing = false;
  if (auto* pd = vtkPolyData::SafeDownCast(data))
  {
    appendPolyData(pd, vectors, mesh, normalsMissing);
  }
  else if (auto* cd = vtkCompositeDataSet::SafeDownCast(data))
  {
    auto it = vtk::TakeSmartPointer(cd->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        appendPolyData(leaf, vectors, mesh, normalsMissing);
      }
    }
  }
  if (normalsMissing || mesh.normals.size() != mesh.positions.size())
  {
    mesh.normals = core::computeVertexNormals(mesh.positions, mesh.triangles);
  }
  return mesh;
}

}  // namespace flowsurf::paraview
