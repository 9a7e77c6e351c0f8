// inspectFile / formatFileInfo: what `flowsurf info FILE` prints. The file is read in
// the reader process (reader_process.h, file_inspect.cpp).
#include "io/dataset_reader.h"

#include "io/reader_process.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace flowsurf::io {

namespace {

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
    for (size_t i = 0; i < head; ++i) s.append(i ? " " : "").append(number(times[i]));
    if (head < times.size()) s += " ... " + number(times.back());
    return s;
}

}  // namespace

FileInfo inspectFile(const std::string& path, const SourceOptions& options) {
    return detail::ReaderProcess().inspect(path, options);
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
          << (a.units.empty() ? "" : "  [" + a.units + "]") << "\n";
        // Cell vectors become point vectors on read, so both can be shown.
        if (a.components == 3 && a.name != "Normals" &&
            std::find(vectors.begin(), vectors.end(), a.name) == vectors.end())
            vectors.push_back(a.name);
    }
    if (!info.parts.empty()) {
        // Which array is on which part: an OpenFOAM field may be missing on some patches.
        size_t nameWidth = 4;
        for (const auto& p : info.parts) nameWidth = std::max(nameWidth, p.name.size());
        s << "Parts        " << info.parts.size() << " (boundary patches, blocks or zones), faces and arrays of each\n";
        for (const auto& p : info.parts) {
            s << "  " << std::left << std::setw(int(nameWidth) + 2) << p.name << std::right << std::setw(8) << p.faces
              << " faces  ";
            if (p.arrays.empty()) s << " (no arrays)";
            for (const auto& a : p.arrays) s << " " << a;
            s << "\n";
        }
    }
    if (!info.patches.empty()) {
        // All of a CGNS file's boundary conditions or an OpenFOAM case's patches, with what is read.
        size_t nameWidth = 4, typeWidth = 4, familyWidth = 1;
        for (const auto& p : info.patches) {
            nameWidth = std::max(nameWidth, p.name.size());
            typeWidth = std::max(typeWidth, p.type.size());
            familyWidth = std::max(familyWidth, p.family.size());
        }
        s << "Boundaries   " << info.patches.size()
          << " (name, type, family; 'read': in the surface: the walls by default, --patches NAME|FAMILY picks others)\n";
        for (const auto& p : info.patches)
            s << "  " << std::left << std::setw(int(nameWidth) + 2) << p.name << std::setw(int(typeWidth) + 2) << p.type
              << std::setw(int(familyWidth) + 2) << (p.family.empty() ? "-" : p.family) << std::right << std::setw(8) << p.faces
              << " faces"
              << (p.read ? "  read" : "") << "\n";
    }
    s << "Vector fields";
    if (vectors.empty()) s << " none (no array with 3 components)";
    for (size_t i = 0; i < vectors.size(); ++i) s << (i ? ", " : " ") << vectors[i];
    s << "\n";
    return s.str();
}

}  // namespace flowsurf::io
