#include "io/skeleton_polydata.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

namespace flowsurf::io {

vtkSmartPointer<vtkPolyData> skeletonPolyData(const skeleton::Skeleton& s)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> verts, lines;
  // Point arrays: type and index on the critical points (-1 / 0 on line vertices),
  // strength on the lines (0 on the critical points).
  vtkNew<vtkIntArray> type, index;
  vtkNew<vtkStringArray> typeName;
  vtkNew<vtkFloatArray> strength;
  type->SetName("type");
  index->SetName("index");
  typeName->SetName("type_name");
  strength->SetName("strength");
  // Cell arrays: what each cell is; VTK orders cells verts, then lines.
  vtkNew<vtkIntArray> kind;
  vtkNew<vtkStringArray> kindName;
  kind->SetName("kind");
  kindName->SetName("kind_name");
  for (const skeleton::CriticalPoint& p : s.criticalPoints)
  {
    const vtkIdType id = points->InsertNextPoint(p.position.x, p.position.y, p.position.z);
    verts->InsertNextCell(1, &id);
    type->InsertNextValue(int(p.type));
    index->InsertNextValue(p.index);
    typeName->InsertNextValue(skeleton::pointTypeName(p.type));
    strength->InsertNextValue(0.0f);
    kind->InsertNextValue(-1);
    kindName->InsertNextValue("critical_point");
  }
  for (const skeleton::SkeletonLine& l : s.lines)
  {
    lines->InsertNextCell(vtkIdType(l.points.size()));
    for (size_t k = 0; k < l.points.size(); ++k)
    {
      const glm::vec3& p = l.points[k];
      lines->InsertCellPoint(points->InsertNextPoint(p.x, p.y, p.z));
      type->InsertNextValue(-1);
      index->InsertNextValue(0);
      typeName->InsertNextValue("");
      strength->InsertNextValue(k < l.strength.size() ? l.strength[k] : 0.0f);
    }
    kind->InsertNextValue(int(l.kind));
    kindName->InsertNextValue(skeleton::lineKindName(l.kind));
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  poly->SetLines(lines);
  poly->GetPointData()->AddArray(type);
  poly->GetPointData()->AddArray(index);
  poly->GetPointData()->AddArray(typeName);
  poly->GetPointData()->AddArray(strength);
  poly->GetCellData()->AddArray(kind);
  poly->GetCellData()->AddArray(kindName);
  // Field data: what the JSON export reports beside the points and lines.
  auto scalar = [&](const char* name, long value) {
    vtkNew<vtkIntArray> a;
    a->SetName(name);
    a->InsertNextValue(int(value));
    poly->GetFieldData()->AddArray(a);
  };
  scalar("euler_characteristic", s.eulerCharacteristic);
  scalar("index_sum", s.indexSum);
  scalar("closed", s.closed ? 1 : 0);
  scalar("parts", long(s.parts));
  return poly;
}

}  // namespace flowsurf::io
