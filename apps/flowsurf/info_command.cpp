#include "commands.h"

#include "core/builtin_scenes.h"
#include "io/dataset_reader.h"
#include "io/series_reader.h"
#include "session/options/options.h"
#include "skeleton/skeleton.h"
#include "core/derived_fields.h"

#include <algorithm>
#include <cstdio>

namespace flowsurf::app {

namespace {

// What can be shown beside the stored arrays, and which vector arrays are shown reversed by
// default (--reverse-field auto).
void printDerived(const std::vector<std::string>& vectorArrays, const std::string& skinFriction = {}) {
    std::string fields, scalars;
    for (const char* f : core::kDerivedFieldSyntax) fields += (fields.empty() ? "" : ", ") + std::string(f);
    for (const char* s : skeleton::kDerivedScalarNames) scalars += (scalars.empty() ? "" : ", ") + std::string(s);
    std::printf("Derived fields   --field %s\n", fields.c_str());
    // The wall stress from a volume's velocity, derived where the file is read.
    if (!skinFriction.empty()) std::printf("Wall stress      --field skin-friction: %s\n", skinFriction.c_str());
    std::printf("Derived scalars  --color-by, --mask-by: %s (of the shown field)\n", scalars.c_str());
    const session::RenderOptions defaults;
    for (const std::string& name : vectorArrays)
        if (session::fieldShownReversed(defaults, name))
            std::printf("Shown reversed   %s (--reverse-field auto: OpenFOAM's stress on the fluid points against "
                        "the near-wall flow; --reverse-field off shows it as stored)\n", name.c_str());
}

// Each vector array's name once: an OpenFOAM field is a cell array and a point array of the same name.
std::vector<std::string> vectorArrays(const io::FileInfo& info) {
    std::vector<std::string> names;
    for (const auto& a : info.arrays)
        if (a.components == 3 && std::find(names.begin(), names.end(), a.name) == names.end()) names.push_back(a.name);
    return names;
}

}  // namespace

int runInfo(const std::string& path, const io::SourceOptions& source) {
    if (core::isBuiltinSpec(path)) {
        core::Dataset d = core::makeBuiltin(path);
        const auto& m = d.steps.front().mesh;
        core::Bounds b = d.bounds();
        std::printf("%s\n  points: %zu\n  triangles: %zu\n  time steps: %zu\n", path.c_str(), m.vertexCount(),
                    m.triangleCount(), d.steps.size());
        if (d.steps.size() > 1) {
            std::printf("  time values:");
            for (const auto& st : d.steps) std::printf(" %g", st.time);
            std::printf("\n");
        }
        for (const auto& f : m.fields) std::printf("  point array '%s' (3 components)\n", f.name.c_str());
        std::printf("  bounds: [%g %g %g] - [%g %g %g]\n", b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z);
        std::vector<std::string> names;
        for (const auto& f : m.fields) names.push_back(f.name);
        printDerived(names);
        return 0;
    }
    if (io::isSeriesPattern(path)) {
        std::unique_ptr<core::StepProvider> steps = io::openSeries(path, source);
        std::printf("Series       %s\nTime steps   %zu:", path.c_str(), steps->count());
        for (size_t i = 0; i < steps->count(); ++i) std::printf(" %g", steps->time(i));
        std::printf("\nFirst step   %s\n\n", steps->label(0).c_str());
        const std::string first = steps->label(0).substr(0, steps->label(0).find(" (step"));
        const io::FileInfo info = io::inspectFile(first, source);
        std::fputs(io::formatFileInfo(info).c_str(), stdout);
        printDerived(vectorArrays(info));
        return 0;
    }
    const io::FileInfo info = io::inspectFile(path, source);
    std::fputs(io::formatFileInfo(info).c_str(), stdout);
    printDerived(vectorArrays(info), info.skinFriction);
    return 0;
}

}  // namespace flowsurf::app
