// inspectFileHere: what `flowsurf info FILE` lists, read in the reader process. The
// arrays are listed as the file stores them (point and cell data); the counts and bounds
// are of the surface readDataset would produce for the first time step.
#include "io/file_inspect.h"

#include "io/surface_pipeline.h"
#include "io/vtk_messages.h"
#include "io/vtk_sources.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>

#include <algorithm>

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
            arrays.push_back({a->GetName(), a->GetNumberOfComponents(), pointData, range[0], range[1]});
        } else {
            it->rangeMin = std::min(it->rangeMin, range[0]);
            it->rangeMax = std::max(it->rangeMax, range[1]);
        }
    }
}

}  // namespace

FileInfo inspectFileHere(const std::string& path) {
    VtkMessageTrap trap;
    auto source = openSource(path, trap);
    FileInfo info;
    info.path = path;
    info.format = source->format();
    info.times = source->times();

    vtkSmartPointer<vtkDataObject> raw = source->readStep(0);
    forEachLeaf(raw, [&](vtkDataSet* ds) {
        collectArrays(ds->GetPointData(), true, info.arrays);
        collectArrays(ds->GetCellData(), false, info.arrays);
    });
    core::SurfaceMesh mesh = readSurfaceMesh(raw, trap, stepLabel(path, *source, 0));
    info.points = mesh.vertexCount();
    info.triangles = mesh.triangleCount();
    info.bounds = mesh.bounds();
    return info;
}

}  // namespace flowsurf::io::detail
