// inspectFileHere: what `flowsurf info FILE` lists, read in the reader process. The
// arrays are listed as the file stores them (point and cell data); the counts and bounds
// are of the surface readDataset would produce for the first time step.
#include "io/reader/file_inspect.h"

#include "io/reader/cgns_boundaries.h"
#include "io/reader/reader_wire.h"
#include "io/reader/skin_friction.h"
#include "io/reader/surface_pipeline.h"
#include "io/reader/vtk_messages.h"
#include "io/reader/vtk_sources.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>

#include <algorithm>
#include <map>

namespace flowsurf::io::detail {

namespace {
// Adds the numeric arrays of one block, merging ranges with earlier blocks.
void collectArrays(vtkFieldData* data, bool pointData, std::vector<ArrayInfo>& arrays) {
    for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
        vtkDataArray* a = data->GetArray(i);
        if (!a || !a->GetName()) continue;
        double range[2] = {0, 0};
        if (a->GetNumberOfTuples() > 0)
            a->GetRange(range, a->GetNumberOfComponents() == 1 ? 0 : -1);  // -1: magnitude
        auto same = [&](const ArrayInfo& x) { return x.name == a->GetName() && x.pointData == pointData; };
        auto it = std::find_if(arrays.begin(), arrays.end(), same);
        if (it == arrays.end()) {
            arrays.push_back({a->GetName(), a->GetNumberOfComponents(), pointData, range[0], range[1], ""});
        } else {
            it->rangeMin = std::min(it->rangeMin, range[0]);
            it->rangeMax = std::max(it->rangeMax, range[1]);
        }
    }
}

// One block's name, faces and arrays (cell arrays first: an OpenFOAM field is a cell
// array on its patch, the point array beside it VTK's interpolation of it).
PartInfo partOf(vtkDataSet* ds, const std::string& name) {
    PartInfo part{name, size_t(ds->GetNumberOfCells()), {}};
    for (vtkFieldData* fd : {static_cast<vtkFieldData*>(ds->GetCellData()), static_cast<vtkFieldData*>(ds->GetPointData())})
        for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
            const char* n = fd->GetArrayName(i);
            if (n && std::find(part.arrays.begin(), part.arrays.end(), n) == part.arrays.end()) part.arrays.push_back(n);
        }
    return part;
}

// What --field skin-friction would take in a volume file's first step.
std::string volumeSkinFrictionNote(vtkDataObject* raw, const SourceOptions& options) {
    std::string velocity;
    bool volume = false;
    forEachNamedLeaf(raw, [&](vtkDataSet* ds, const std::string&) {
        if (!hasVolumeCells(ds)) return;
        volume = true;
        if (velocity.empty()) velocity = findVelocityArray(ds);
    });
    if (!volume) return {};
    if (velocity.empty()) return "not available: the volume has no velocity (a 3-component array named U, velocity or vel)";
    return "from " + velocity + " in the cells next to the boundary surface; " +
           (options.viscosity > 0 ? "nu from --viscosity" : "a relative magnitude unless --viscosity is given");
}

// What --field skin-friction would take in a CGNS file: the wall BCs read and the velocity on
// them (the patches carry the zone's solution, vertex or cell-centred); the boundary
// surface's note when no BC is read.
std::string cgnsSkinFrictionNote(vtkDataObject* raw, const std::vector<PatchInfo>& patches, const SourceOptions& options) {
    std::string walls;
    bool read = false;
    for (const auto& p : patches) {
        read = read || p.read;
        if (p.read && isCgnsWallType(p.type)) walls += (walls.empty() ? "" : ", ") + p.name;
    }
    if (!read) return volumeSkinFrictionNote(raw, options);
    if (walls.empty()) return "not available: none of the BCs read is a wall (BC type BCWall*)";
    std::string velocity, where;
    forEachNamedLeaf(raw, [&](vtkDataSet* ds, const std::string&) {
        if (!velocity.empty()) return;
        velocity = findVelocityArray(ds);
        where = ds->GetCellData()->GetArray(velocity.c_str()) ? "cell-centred" : "at the vertices";
    });
    if (velocity.empty()) return "not available: the solution has no velocity (a 3-component array named U, velocity or vel)";
    return "from " + velocity + " (" + where + ") in the cells next to the wall BCs " + walls + "; " +
           (options.viscosity > 0 ? "nu from --viscosity" : "a relative magnitude unless --viscosity is given");
}

}  // namespace

FileInfo inspectFileHere(const std::string& path, const SourceOptions& options) {
    VtkMessageTrap trap;
    auto source = openSource(path, trap, options);
    FileInfo info;
    info.path = path;
    info.format = source->format();
    info.times = source->times();
    info.patches = source->patches();

    vtkSmartPointer<vtkDataObject> raw = source->readStep(0);
    forEachNamedLeaf(raw, [&](vtkDataSet* ds, const std::string& name) {
        collectArrays(ds->GetPointData(), true, info.arrays);
        collectArrays(ds->GetCellData(), false, info.arrays);
        if (!name.empty()) info.parts.push_back(partOf(ds, name));
    });
    const std::map<std::string, std::string> units = arrayUnits(raw);
    for (auto& a : info.arrays)
        if (auto it = units.find(a.name); it != units.end()) a.units = it->second;
    core::SurfaceMesh mesh = readSurfaceMesh(raw, trap, wire::stepLabel(path, source->times(), 0));
    info.points = mesh.vertexCount();
    info.triangles = mesh.triangleCount();
    info.bounds = mesh.bounds();
    if (info.format.rfind("OpenFOAM", 0) == 0) info.skinFriction = foamSkinFrictionNote(path, options);
    else if (info.format.rfind("CGNS", 0) == 0) info.skinFriction = cgnsSkinFrictionNote(raw, info.patches, options);
    else info.skinFriction = volumeSkinFrictionNote(raw, options);
    return info;
}

}  // namespace flowsurf::io::detail
