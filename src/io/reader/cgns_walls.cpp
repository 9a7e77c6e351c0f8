// Sections: the cell behind each face · the patch's surface.
#include "io/reader/cgns_walls.h"

#include "core/errors.h"

#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <limits>
#include <map>

namespace flowsurf::io::detail {

// --- the cell behind each face ------------------------------------------------------------
// Faces are matched by their sorted corners: a CGNS face lists only its corners, VTK's face
// of a quadratic cell its corners first and then the mid-edge nodes.
std::vector<vtkIdType> wallCells(vtkDataSet* volume, const CgnsPatch& patch) {
    std::map<std::vector<vtkIdType>, size_t> faceOf;
    std::vector<char> onPatch(size_t(volume->GetNumberOfPoints()), 0);
    for (size_t f = 0; f < patch.faceCount(); ++f) {
        std::vector<vtkIdType> key(patch.ids.begin() + patch.offsets[f], patch.ids.begin() + patch.offsets[f + 1]);
        for (vtkIdType v : key)
            if (v >= 0 && size_t(v) < onPatch.size()) onPatch[size_t(v)] = 1;
        std::sort(key.begin(), key.end());
        faceOf.emplace(std::move(key), f);
    }
    std::vector<vtkIdType> cells(patch.faceCount(), -1);
    auto cell = vtkSmartPointer<vtkGenericCell>::New();
    auto ids = vtkSmartPointer<vtkIdList>::New();
    for (vtkIdType c = 0; c < volume->GetNumberOfCells(); ++c) {
        volume->GetCellPoints(c, ids);
        int touching = 0;
        for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) touching += onPatch[size_t(ids->GetId(k))];
        if (touching < 3) continue;  // no face of this cell lies on the patch
        volume->GetCell(c, cell);
        for (int i = 0; i < cell->GetNumberOfFaces(); ++i) {
            vtkCell* face = cell->GetFace(i);
            const vtkIdType corners = std::min<vtkIdType>(face->GetNumberOfEdges(), face->GetNumberOfPoints());
            std::vector<vtkIdType> key(static_cast<size_t>(corners));
            for (vtkIdType k = 0; k < corners; ++k) key[size_t(k)] = face->GetPointId(int(k));
            std::sort(key.begin(), key.end());
            if (auto it = faceOf.find(key); it != faceOf.end()) cells[it->second] = c;
        }
    }
    return cells;
}

// --- the patch's surface --------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> patchSurface(vtkDataSet* volume, const CgnsPatch& patch, const std::vector<vtkIdType>& cells,
                                          const std::string& where) {
    const vtkIdType volumePoints = volume->GetNumberOfPoints();
    std::vector<vtkIdType> newId(size_t(volumePoints), -1);
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    auto out = vtkSmartPointer<vtkPolyData>::New();
    vtkPointData* from = volume->GetPointData();
    out->GetPointData()->CopyAllocate(from, vtkIdType(patch.ids.size()));
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    std::vector<vtkIdType> face;
    for (size_t f = 0; f < patch.faceCount(); ++f) {
        face.clear();
        for (vtkIdType k = patch.offsets[f]; k < patch.offsets[f + 1]; ++k) {
            const vtkIdType v = patch.ids[size_t(k)];
            if (v < 0 || v >= volumePoints)
                throw FormatError(where + ": BC " + patch.name + " names vertex " + std::to_string(v + 1) + ", the zone has " +
                                  std::to_string(volumePoints));
            if (newId[size_t(v)] < 0) {
                newId[size_t(v)] = points->InsertNextPoint(volume->GetPoint(v));
                out->GetPointData()->CopyData(from, v, newId[size_t(v)]);
            }
            face.push_back(newId[size_t(v)]);
        }
        polys->InsertNextCell(vtkIdType(face.size()), face.data());
    }
    out->SetPoints(points);
    out->SetPolys(polys);
    if (!cells.empty()) {
        vtkCellData* cellsFrom = volume->GetCellData();
        vtkCellData* to = out->GetCellData();
        to->CopyAllocate(cellsFrom, vtkIdType(patch.faceCount()));
        for (size_t f = 0; f < patch.faceCount(); ++f) {
            if (cells[f] >= 0) {
                to->CopyData(cellsFrom, cells[f], vtkIdType(f));
                continue;
            }
            // A face no cell of the zone has: no value (NaN draws in the NaN colour).
            for (int a = 0; a < to->GetNumberOfArrays(); ++a)
                if (vtkDataArray* arr = to->GetArray(a))
                    for (int c = 0; c < arr->GetNumberOfComponents(); ++c)
                        arr->InsertComponent(vtkIdType(f), c, std::numeric_limits<double>::quiet_NaN());
        }
    }
    return out;
}

}  // namespace flowsurf::io::detail
