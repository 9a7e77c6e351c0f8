// Sections: leaves · surface stages · copy into core::SurfaceMesh.
#include "io/reader/surface_pipeline.h"

#include "core/errors.h"
#include "io/reader/checks.h"

#include <vtkAlgorithm.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkInformation.h>
#include <vtkInformationStringKey.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include <cmath>
#include <map>
#include <set>
#include <limits>
#include <vector>

namespace flowsurf::io::detail {

// --- leaves -------------------------------------------------------------------

void forEachNamedLeaf(vtkDataObject* data, const std::function<void(vtkDataSet*, const std::string&)>& visit) {
    if (auto* ds = vtkDataSet::SafeDownCast(data)) {
        if (ds->GetNumberOfPoints() > 0) visit(ds, "");
        return;
    }
    auto* composite = vtkCompositeDataSet::SafeDownCast(data);
    if (!composite) return;
    auto it = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
        auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
        std::string name;
        if (it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
            name = it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME());
        if (ds && ds->GetNumberOfPoints() > 0) visit(ds, name.empty() ? "block " + std::to_string(it->GetCurrentFlatIndex()) : name);
    }
}

// --- surface stages ------------------------------------------------------------------------

namespace {

// Runs `filter` (its input set) watched by `trap`; its output, or a FormatError "WHERE: WHAT: why".
vtkSmartPointer<vtkPolyData> run(vtkAlgorithm* filter, VtkMessageTrap& trap, const std::string& where, const char* what) {
    trap.watch(filter);
    filter->Update();
    trap.throwIfError(where, what);
    return vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
}

vtkSmartPointer<vtkPolyData> surfaceOf(vtkDataSet* data, VtkMessageTrap& trap, const std::string& where) {
    if (auto* pd = vtkPolyData::SafeDownCast(data)) return pd;
    auto filter = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    filter->SetInputData(data);
    return run(filter, trap, where, "cannot extract the surface");
}

// VTK's append keeps only arrays present in every block; a CFD field written on some
// patches only would vanish. Pads each block lacking an array that another block has
// (same point/cell association, components and type): scalars with NaN (drawn in the
// NaN colour), vectors with zero (no advection there), and names the patches.
void padPartialArrays(std::vector<vtkSmartPointer<vtkPolyData>>& parts, const std::vector<std::string>& names,
                      const std::string& where) {
    // One warning per set of patches: the arrays missing there (point and cell alike).
    std::map<std::string, std::set<std::string>> missingOn;
    for (int assoc = 0; assoc < 2; ++assoc) {
        auto dataOf = [assoc](vtkPolyData* p) -> vtkFieldData* {
            return assoc == 0 ? static_cast<vtkFieldData*>(p->GetPointData()) : p->GetCellData();
        };
        std::map<std::string, vtkDataArray*> models;
        for (auto& p : parts)
            for (int i = 0; i < dataOf(p)->GetNumberOfArrays(); ++i)
                if (vtkDataArray* a = dataOf(p)->GetArray(i); a && a->GetName()) models.try_emplace(a->GetName(), a);
        for (const auto& [name, model] : models) {
            std::string missing;
            for (size_t b = 0; b < parts.size(); ++b) {
                vtkFieldData* fd = dataOf(parts[b]);
                vtkDataArray* have = fd->GetArray(name.c_str());
                if (have && have->GetNumberOfComponents() == model->GetNumberOfComponents()) continue;
                if (have) fd->RemoveArray(name.c_str());
                const vtkIdType n = assoc == 0 ? parts[b]->GetNumberOfPoints() : parts[b]->GetNumberOfCells();
                auto pad = vtkSmartPointer<vtkDataArray>::Take(model->NewInstance());
                pad->SetName(name.c_str());
                pad->SetNumberOfComponents(model->GetNumberOfComponents());
                pad->SetNumberOfTuples(n);
                pad->Fill(model->GetNumberOfComponents() == 1 ? std::numeric_limits<double>::quiet_NaN() : 0.0);
                fd->AddArray(pad);
                missing += (missing.empty() ? "" : ", ") + names[b];
            }
            if (!missing.empty()) missingOn[missing].insert(name);
        }
    }
    for (const auto& [patches, arrays] : missingOn) {
        std::string list;
        for (const auto& a : arrays) list += (list.empty() ? "'" : ", '") + a + "'";
        warnOnce(where + ": " + list + (arrays.size() == 1 ? " is" : " are") + " missing on " + patches +
                 "; kept, with NaN (no colour) for scalars and zero vectors (no motion) there");
    }
}

vtkSmartPointer<vtkPolyData> mergeBlocks(std::vector<vtkSmartPointer<vtkPolyData>>& parts,
                                         const std::vector<std::string>& names, VtkMessageTrap& trap,
                                         const std::string& where) {
    if (parts.empty()) return vtkSmartPointer<vtkPolyData>::New();
    if (parts.size() == 1) return parts[0];
    padPartialArrays(parts, names, where);
    // Only arrays present in every block survive the append (VTK's rule).
    auto append = vtkSmartPointer<vtkAppendPolyData>::New();
    for (const auto& p : parts) append->AddInputData(p);
    return run(append, trap, where, "cannot merge the blocks");
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

// VTK's filter averages every cell around a point, so one NaN cell scalar ("no value
// here": a field missing on part of the surface) makes the whole ring of points around it
// NaN. Scalars with a NaN are averaged over the cells that have a value instead; a point
// none of whose cells has one stays NaN.
void averageFiniteCells(vtkPolyData* data, vtkDataArray* cells, vtkDataArray* points) {
    std::vector<double> sum(size_t(data->GetNumberOfPoints()), 0.0);
    std::vector<int> count(sum.size(), 0);
    for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
        const double v = cells->GetComponent(c, 0);
        if (!std::isfinite(v)) continue;
        vtkIdType n;
        const vtkIdType* ids;
        data->GetCellPoints(c, n, ids);
        for (vtkIdType k = 0; k < n; ++k) {
            sum[size_t(ids[k])] += v;
            ++count[size_t(ids[k])];
        }
    }
    for (size_t p = 0; p < sum.size(); ++p)
        points->SetComponent(vtkIdType(p), 0, count[p] ? sum[p] / count[p] : std::numeric_limits<double>::quiet_NaN());
}

bool hasNonFinite(vtkDataArray* a) {
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
        if (!std::isfinite(a->GetComponent(i, 0))) return true;
    return false;
}

vtkSmartPointer<vtkPolyData> cellToPoint(vtkPolyData* data, VtkMessageTrap& trap, const std::string& where) {
    if (data->GetCellData()->GetNumberOfArrays() == 0) return data;
    auto filter = vtkSmartPointer<vtkCellDataToPointData>::New();
    filter->SetInputData(data);
    filter->PassCellDataOff();
    vtkSmartPointer<vtkPolyData> out = run(filter, trap, where, "cannot convert cell data to point data");
    vtkCellData* cd = data->GetCellData();
    for (int i = 0; i < cd->GetNumberOfArrays(); ++i) {
        vtkDataArray* a = cd->GetArray(i);
        vtkDataArray* converted = a && a->GetName() ? out->GetPointData()->GetArray(a->GetName()) : nullptr;
        if (converted && a->GetNumberOfComponents() == 1 && converted->GetNumberOfComponents() == 1 && hasNonFinite(a))
            averageFiniteCells(data, a, converted);
    }
    // Arrays the file gives per point are exact; averaged cell values are not: the
    // file's point arrays replace converted cell arrays of the same name.
    vtkPointData* in = data->GetPointData();
    for (int i = 0; i < in->GetNumberOfArrays(); ++i)
        out->GetPointData()->AddArray(in->GetAbstractArray(i));
    return out;
}

vtkSmartPointer<vtkPolyData> triangulate(vtkPolyData* data, VtkMessageTrap& trap, const std::string& where) {
    auto filter = vtkSmartPointer<vtkTriangleFilter>::New();
    filter->SetInputData(data);
    filter->PassVertsOff();
    filter->PassLinesOff();
    return run(filter, trap, where, "cannot triangulate");
}

// Stages 1–5. Point arrays win over converted cell arrays of the same name.
vtkSmartPointer<vtkPolyData> extractSurface(vtkDataObject* data, VtkMessageTrap& trap, const std::string& where) {
    VtkMessageTrap::Active active(trap);
    // (1) check, (2) surface per block
    std::vector<vtkSmartPointer<vtkPolyData>> parts;
    std::vector<std::string> names;
    forEachNamedLeaf(data, [&](vtkDataSet* ds, const std::string& name) {
        checkDataSet(ds, where);
        // A shallow copy: padding partial arrays must not touch the reader's output.
        auto part = vtkSmartPointer<vtkPolyData>::New();
        part->ShallowCopy(surfaceOf(ds, trap, where));
        parts.push_back(part);
        names.push_back(name);
    });
    // (3) merge, arrays missing on some blocks padded
    vtkSmartPointer<vtkPolyData> merged = mergeBlocks(parts, names, trap, where);
    const std::string normals = normalsName(merged);
    // (4) cell data → point data, (5) triangles only
    vtkSmartPointer<vtkPolyData> surface = triangulate(cellToPoint(merged, trap, where), trap, where);
    if (!normals.empty()) surface->GetPointData()->SetActiveNormals(normals.c_str());
    return surface;
}

// --- copy into core::SurfaceMesh --------------------------------------------------------------

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

// Stage 6: positions, triangles, normals ("Normals" or the active normals, dropped if
// any is zero or non-finite), every other 3-component point array as a field and every
// 1-component point array (converted cell arrays included) as a scalar.
core::SurfaceMesh toSurfaceMesh(vtkPolyData* surface, const std::string& where) {
    core::SurfaceMesh mesh;
    const vtkIdType points = surface->GetNumberOfPoints();
    if (points > static_cast<vtkIdType>(std::numeric_limits<uint32_t>::max()))
        throw FormatError(where + ": " + std::to_string(points) + " points is more than 32-bit indices allow");
    if (points > 0) mesh.positions = copyVectors(surface->GetPoints()->GetData());

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
        if (!a || a == normals) continue;
        std::string name = a->GetName() ? a->GetName() : "array" + std::to_string(i);
        if (a->GetNumberOfComponents() == 3) {
            mesh.fields.push_back({name, copyVectors(a)});
        } else if (a->GetNumberOfComponents() == 1) {
            core::ScalarField f{name, std::vector<float>(static_cast<size_t>(a->GetNumberOfTuples()))};
            for (vtkIdType k = 0; k < a->GetNumberOfTuples(); ++k) f.values[size_t(k)] = float(a->GetComponent(k, 0));
            mesh.scalars.push_back(std::move(f));
        }
    }
    return mesh;
}

}  // namespace

std::map<std::string, std::string> arrayUnits(vtkDataObject* data) {
    std::map<std::string, std::string> units;
    auto collect = [&units](vtkFieldData* fd) {
        for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
            vtkDataArray* a = fd->GetArray(i);
            if (a && a->GetName() && a->HasInformation() && a->GetInformation()->Has(vtkDataArray::UNITS_LABEL()))
                units[a->GetName()] = a->GetInformation()->Get(vtkDataArray::UNITS_LABEL());
        }
    };
    forEachNamedLeaf(data, [&](vtkDataSet* ds, const std::string&) {
        collect(ds->GetPointData());
        collect(ds->GetCellData());
    });
    return units;
}

core::SurfaceMesh readSurfaceMesh(vtkDataObject* data, VtkMessageTrap& trap, const std::string& where) {
    vtkSmartPointer<vtkPolyData> surface = extractSurface(data, trap, where);
    core::SurfaceMesh mesh = toSurfaceMesh(surface, where);
    mesh.units = arrayUnits(data);
    // (7) validate: NaN/Inf, indices, sizes; degenerate triangles dropped.
    core::validateMesh(mesh, where);
    return mesh;
}

}  // namespace flowsurf::io::detail
