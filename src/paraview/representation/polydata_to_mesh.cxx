#include "polydata_to_mesh.h"

#include "core/errors.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <limits>

namespace flowsurf::paraview {

namespace {

// The value of tuple i that a lookup table in `component` mode maps.
float colorValue(vtkDataArray* a, vtkIdType i, int component)
{
  const int n = a->GetNumberOfComponents();
  if (component >= 0)
  {
    return float(a->GetComponent(i, component < n ? component : n - 1));
  }
  if (n == 1)
  {
    return float(a->GetComponent(i, 0));
  }
  double sum = 0.0;
  for (int c = 0; c < n; ++c)
  {
    const double v = a->GetComponent(i, c);
    sum += v * v;
  }
  return float(std::sqrt(sum));
}

void appendPolyData(vtkPolyData* pd, const std::string& vectors, const ColorSource* color,
  core::SurfaceMesh& mesh, bool& normalsMissing)
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
  if (color)
  {
    if (mesh.scalars.empty())
    {
      mesh.scalars.push_back({ kColorScalarName, {} });
    }
    vtkDataArray* c = pd->GetPointData()->GetArray(color->array.c_str());
    std::vector<float>& out = mesh.scalars[0].values;
    for (vtkIdType i = 0; i < n; ++i)
    {
      out.push_back(c ? colorValue(c, i, color->component) : std::numeric_limits<float>::quiet_NaN());
    }
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

core::SurfaceMesh toSurfaceMesh(vtkDataObject* data, const std::string& vectors, const ColorSource* color)
{
  core::SurfaceMesh mesh;
  bool normalsMissing = false;
  if (auto* pd = vtkPolyData::SafeDownCast(data))
  {
    appendPolyData(pd, vectors, color, mesh, normalsMissing);
  }
  else if (auto* cd = vtkCompositeDataSet::SafeDownCast(data))
  {
    auto it = vtk::TakeSmartPointer(cd->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        appendPolyData(leaf, vectors, color, mesh, normalsMissing);
      }
    }
  }
  if (normalsMissing || mesh.normals.size() != mesh.positions.size())
  {
    mesh.normals = core::computeVertexNormals(mesh.positions, mesh.triangles);
  }
  return mesh;
}

core::Camera cameraOf(vtkCamera* c)
{
  core::Camera cam;
  double p[3], f[3], u[3], range[2];
  c->GetPosition(p);
  c->GetFocalPoint(f);
  c->GetViewUp(u);
  c->GetClippingRange(range);
  cam.eye = glm::vec3(p[0], p[1], p[2]);
  cam.target = glm::vec3(f[0], f[1], f[2]);
  cam.up = glm::vec3(u[0], u[1], u[2]);
  cam.fovDeg = float(c->GetViewAngle());
  cam.orthoHeight = c->GetParallelProjection() ? float(2.0 * c->GetParallelScale()) : 0.0f;
  cam.nearPlane = float(range[0]);
  cam.farPlane = float(range[1]);
  return cam;
}

}  // namespace flowsurf::paraview
