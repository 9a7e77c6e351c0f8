// Sections: leaves · surface stages · copy into core::SurfaceMesh.
#include "io/surface_pipeline.h"

#include "core/errors.h"
#include "io/dataset_check.h"

#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include <cmath>
#include <limits>
#include <vector>

namespace flowsurf::io::detail {

// --- leaves -------------------------------------------------------------------

void forEachLeaf(vtkDataObject* data, const std::function<void(vtkDataSet*)>& visit) {
    if (auto* ds = vtkDataSet::SafeDownCast(data)) {
        if (ds->GetNumberOfPoints() > 0) visit(ds);
        return;
    }
    auto* composite = vtkCompositeDataSet::SafeDownCast(data);
    if (!composite) return;
    auto it = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
        auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
        if (ds && ds->GetNumberOfPoints() > 0) visit(ds);
    }
}

// --- surface stages ------------------------------------------------------------------------

namespace {

vtkSmartPointer<vtkPolyData> surfaceOf(vtkDataSet* data, VtkMessageTrap& trap,
                                       const std::string& where) {
    if (auto* pd = vtkPolyData::SafeDownCast(data)) return pd;
    auto filter = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    trap.watch(filter);
    filter->SetInputData(data);
    filter->Update();
    trap.throwIfError(where, "cannot extract the surface");
    return filter->GetOutput();
}

vtkSmartPointer<vtkPolyData> mergeBlocks(const std::vector<vtkSmartPointer<vtkPolyData>>& parts,
                                         VtkMessageTrap& trap, const std::string& where) {
    if (parts.empty()) return vtkSmartPointer<vtkPolyData>::New();
    if (parts.size() == 1) return parts[0];
    // Only arrays present in every block survive the append (VTK's rule).
    auto append = vtkSmartPointer<vtkAppendPolyData>::New();
    trap.watch(append);
    for (const auto& p : parts) append->AddInputData(p);
    append->Update();
    trap.throwIfError(where, "cannot merge the blocks");
    return append->GetOutput();
}

// The name of the normals array, if any: "Normals", else the active normals.
std::string normalsName(vtkPolyData* data) {
    vtkPointData* pd = data->GetPointData();
    vtkDataArray* n = pd->GetArray("Normals");
    if (n && n->GetNumberOfComponents() == 3) return "Normals";
    n = pd->GetNormals();
    if (n && n->GetNumberOfComponents() == 3 && n->GetName()) return n->GetName();
    return {};
}

vtkSmartPointer<vtkPolyData> cellToPoint(vtkPolyData* data, VtkMessageTrap& trap,
                                         const std::string& where) {
    if (data->GetCellData()->GetNumberOfArrays() == 0) return data;
    auto filter = vtkSmartPointer<vtkCellDataToPointData>::New();
    trap.watch(filter);
    filter->SetInputData(data);
    filter->PassCellDataOff();
    filter->Update();
    trap.throwIfError(where, "cannot convert cell data to point data");
    vtkSmartPointer<vtkPolyData> out = filter->GetPolyDataOutput();
    // Arrays the file gives per point are exact; averaged cell values are not: the
    // file's point arrays replace converted cell arrays of the same name.
    vtkPointData* in = data->GetPointData();
    for (int i = 0; i < in->GetNumberOfArrays(); ++i)
        out->GetPointData()->AddArray(in->GetAbstractArray(i));
    return out;
}

vtkSmartPointer<vtkPolyData> triangulate(vtkPolyData* data, VtkMessageTrap& trap,
                                         const std::string& where) {
    auto filter = vtkSmartPointer<vtkTriangleFilter>::New();
    trap.watch(filter);
    filter->SetInputData(data);
    filter->PassVertsOff();
    filter->PassLinesOff();
    filter->Update();
    trap.throwIfError(where, "cannot triangulate");
    return filter->GetOutput();
}

}  // namespace

vtkSmartPointer<vtkPolyData> extractSurface(vtkDataObject* data, VtkMessageTrap& trap,
                                            const std::string& where) {
    VtkMessageTrap::Active active(trap);
    trap.clear();
    // (1) check, (2) surface per block
    std::vector<vtkSmartPointer<vtkPolyData>> parts;
    forEachLeaf(data, [&](vtkDataSet* ds) {
        checkDataSet(ds, where);
        parts.push_back(surfaceOf(ds, trap, where));
    });
    // (3) merge
    vtkSmartPointer<vtkPolyData> merged = mergeBlocks(parts, trap, where);
    const std::string normals = normalsName(merged);
    // (4) cell data → point data, (5) triangles only
    vtkSmartPointer<vtkPolyData> surface = triangulate(cellToPoint(merged, trap, where), trap, where);
    if (!normals.empty()) surface->GetPointData()->SetActiveNormals(normals.c_str());
    return surface;
}

// --- copy into core::SurfaceMesh --------------------------------------------------------------

namespace {

std::vector<glm::vec3> copyVectors(vtkDataArray* a) {
    std::vector<glm::vec3> v(static_cast<size_t>(a->GetNumberOfTuples()));
    double t[3];
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
        a->GetTuple(i, t);
        v[static_cast<size_t>(i)] = glm::vec3(t[0], t[1], t[2]);
    }
    return v;
}

// File normals are used only if all are usable; otherwise validateMesh computes them.
std::vector<glm::vec3> usableNormals(vtkDataArray* a) {
    std::vector<glm::vec3> n = copyVectors(a);
    for (auto& v : n) {
        float l = glm::length(v);
        if (!std::isfinite(l) || l == 0.0f) return {};
        v /= l;
    }
    return n;
}

}  // namespace

core::SurfaceMesh toSurfaceMesh(vtkPolyData* surface, const std::string& where) {
    core::SurfaceMesh mesh;
    const vtkIdType points = surface->GetNumberOfPoints();
    if (points > static_cast<vtkIdType>(std::numeric_limits<uint32_t>::max()))
        throw FormatError(where + ": " + std::to_string(points) + " points is more than 32-bit indices allow");
    mesh.positions.resize(static_cast<size_t>(points));
    double p[3];
    for (vtkIdType i = 0; i < points; ++i) {
        surface->GetPoint(i, p);
        mesh.positions[static_cast<size_t>(i)] = glm::vec3(p[0], p[1], p[2]);
    }

    vtkCellArray* polys = surface->GetPolys();
    mesh.triangles.reserve(static_cast<size_t>(polys->GetNumberOfCells()));
    auto it = vtkSmartPointer<vtkCellArrayIterator>::Take(polys->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell()) {
        vtkIdType n;
        const vtkIdType* ids;
        it->GetCurrentCell(n, ids);
        if (n == 3)
            mesh.triangles.emplace_back(static_cast<uint32_t>(ids[0]), static_cast<uint32_t>(ids[1]),
                                        static_cast<uint32_t>(ids[2]));
    }

    vtkPointData* pd = surface->GetPointData();
    vtkDataArray* normals = pd->GetNormals();
    if (normals && normals->GetNumberOfComponents() == 3) mesh.normals = usableNormals(normals);
    for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
        vtkDataArray* a = pd->GetArray(i);
        if (!a || a == normals || a->GetNumberOfComponents() != 3) continue;
        std::string name = a->GetName() ? a->GetName() : "array" + std::to_string(i);
        mesh.fields.push_back({name, copyVectors(a)});
    }
    return mesh;
}

core::SurfaceMesh readSurfaceMesh(vtkDataObject* data, VtkMessageTrap& trap,
                                  const std::string& where) {
    vtkSmartPointer<vtkPolyData> surface = extractSurface(data, trap, where);
    core::SurfaceMesh mesh = toSurfaceMesh(surface, where);
    // (7) validate: NaN/Inf, indices, sizes; degenerate triangles dropped.
    core::validateMesh(mesh, where);
    return mesh;
}

}  // namespace flowsurf::io::detail
