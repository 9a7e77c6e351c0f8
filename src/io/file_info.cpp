// inspectFile / formatFileInfo: what `flowsurf info FILE` prints. The arrays are
// listed as the file stores them (point and cell data); the counts and bounds are of
// the surface readDataset would produce for the first time step.
#include "io/dataset_reader.h"

#include "io/surface_pipeline.h"
#include "io/vtk_messages.h"
#include "io/vtk_sources.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace flowsurf::io {

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

std::string number(double v) {
    std::ostringstream s;
    s << std::setprecision(6) << v;
    return s.str();
}

std::string timesText(const std::vector<double>& times) {
    if (times.size() <= 1)
        return times.empty() ? "1 (no time information)" : "1, t = " + number(times[0]);
    std::string s = std::to_string(times.size()) + ", t = " + number(times.front()) + " .. " +
                    number(times.back()) + "\n             ";
    // Long lists: the first few and the last, enough to see the spacing.
    const size_t head = times.size() <= 10 ? times.size() : 6;
    for (size_t i = 0; i < head; ++i) s += (i ? " " : "") + number(times[i]);
    if (head < times.size()) s += " ... " + number(times.back());
    return s;
}

}  // namespace

FileInfo inspectFile(const std::string& path) {
    detail::VtkMessageTrap trap;
    auto source = detail::openSource(path, trap);
    FileInfo info;
    info.path = path;
    info.format = source->format();
    info.times = source->times();

    vtkSmartPointer<vtkDataObject> raw = source->readStep(0);
    detail::forEachLeaf(raw, [&](vtkDataSet* ds) {
        collectArrays(ds->GetPointData(), true, info.arrays);
        collectArrays(ds->GetCellData(), false, info.arrays);
    });
    core::SurfaceMesh mesh = detail::readSurfaceMesh(raw, trap, detail::stepLabel(path, *source, 0));
    info.points = mesh.vertexCount();
    info.triangles = mesh.triangleCount();
    info.bounds = mesh.bounds();
    return info;
}

std::string formatFileInfo(const FileInfo& info) {
    std::ostringstream s;
    s << "File         " << info.path << "\n";
    s << "Format       " << info.format << "\n";
    s << "Surface      " << info.points << " points, " << info.triangles
      << " triangles (first time step, triangulated)\n";
    if (info.bounds.valid()) {
        const auto& lo = info.bounds.lo;
        const auto& hi = info.bounds.hi;
        s << "Bounds       x [" << number(lo.x) << ", " << number(hi.x) << "]  y [" << number(lo.y)
          << ", " << number(hi.y) << "]  z [" << number(lo.z) << ", " << number(hi.z) << "]\n";
    }
    s << "Time steps   " << timesText(info.times) << "\n";

    size_t width = 4;
    for (const auto& a : info.arrays) width = std::max(width, a.name.size());
    s << "Arrays       " << (info.arrays.empty() ? "none" : "(range of the magnitude for vectors)")
      << "\n";
    std::vector<std::string> vectors;
    for (const auto& a : info.arrays) {
        s << "  " << (a.pointData ? "point " : "cell  ") << std::left << std::setw(int(width) + 2)
          << a.name << std::right << std::setw(2) << a.components << " comp   "
          << (a.components == 1 ? "" : "|v| ") << number(a.rangeMin) << " .. " << number(a.rangeMax)
          << "\n";
        // Cell vectors become point vectors on read, so both can be shown.
        if (a.components == 3 && a.name != "Normals" &&
            std::find(vectors.begin(), vectors.end(), a.name) == vectors.end())
            vectors.push_back(a.name);
    }
    s << "Vector fields";
    if (vectors.empty()) s << " none (no array with 3 components)";
    for (size_t i = 0; i < vectors.size(); ++i) s << (i ? ", " : " ") << vectors[i];
    s << "\n";
    return s.str();
}

}  // namespace flowsurf::io
