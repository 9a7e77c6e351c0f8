// The flow topology as VTK PolyData (.vtp) through VTK's own XML writer, to a temporary
// file renamed on success.
#include "io/skeleton_writer.h"

#include "core/errors.h"
#include "io/temp_file.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <unistd.h>

namespace flowsurf::io {

void writeSkeletonVtp(const std::string& path, const skeleton::Skeleton& s, const SkeletonSource& source) {
    (void)source;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkCellArray> verts, lines;
    // point arrays: type and index on the critical points (-1 / 0 on line vertices), strength on lines
    vtkNew<vtkIntArray> type, index;
    vtkNew<vtkStringArray> typeName;
    vtkNew<vtkFloatArray> strength;
    type->SetName("type");
    index->SetName("index");
    typeName->SetName("type_name");
    strength->SetName("strength");
    // cell arrays: what each cell is
    vtkNew<vtkIntArray> kind;
    vtkNew<vtkStringArray> kindName;
    kind->SetName("kind");
    kindName->SetName("kind_name");
    for (const skeleton::CriticalPoint& p : s.criticalPoints) {
        const vtkIdType id = points->InsertNextPoint(p.position.x, p.position.y, p.position.z);
        verts->InsertNextCell(1, &id);
        type->InsertNextValue(int(p.type));
        index->InsertNextValue(p.index);
        typeName->InsertNextValue(skeleton::pointTypeName(p.type));
        strength->InsertNextValue(0.0f);
    }
    for (const skeleton::SkeletonLine& l : s.lines) {
        lines->InsertNextCell(vtkIdType(l.points.size()));
        for (size_t k = 0; k < l.points.size(); ++k) {
            const glm::vec3& p = l.points[k];
            lines->InsertCellPoint(points->InsertNextPoint(p.x, p.y, p.z));
            type->InsertNextValue(-1);
            index->InsertNextValue(0);
            typeName->InsertNextValue("");
            strength->InsertNextValue(l.strength[k]);
        }
    }
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    poly->SetVerts(verts);
    poly->SetLines(lines);
    // VTK orders cells verts, then lines: the cell arrays follow that order.
    for (size_t i = 0; i < s.criticalPoints.size(); ++i) {
        kind->InsertNextValue(-1);
        kindName->InsertNextValue("critical_point");
    }
    for (const skeleton::SkeletonLine& l : s.lines) {
        kind->InsertNextValue(int(l.kind));
        kindName->InsertNextValue(skeleton::lineKindName(l.kind));
    }
    poly->GetPointData()->AddArray(type);
    poly->GetPointData()->AddArray(index);
    poly->GetPointData()->AddArray(typeName);
    poly->GetPointData()->AddArray(strength);
    poly->GetCellData()->AddArray(kind);
    poly->GetCellData()->AddArray(kindName);

    detail::TempFile tmp(path, ".vtp");
    ::close(tmp.fd());
    tmp.fd() = -1;
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(tmp.path().c_str());
    writer->SetInputData(poly);
    writer->SetDataModeToBinary();
    if (writer->Write() != 1) throw IoError(path + ": cannot write (VTK's XML writer failed)");
    tmp.commit();
}

}  // namespace flowsurf::io
