#include "commands.h"

#include "core/builtin_scenes.h"
#include "io/dataset_reader.h"
#include "io/series_reader.h"

#include <cstdio>

namespace flowsurf::app {

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
        return 0;
    }
    if (io::isSeriesPattern(path)) {
        std::unique_ptr<core::StepProvider> steps = io::openSeries(path);
        std::printf("Series       %s\nTime steps   %zu:", path.c_str(), steps->count());
        for (size_t i = 0; i < steps->count(); ++i) std::printf(" %g", steps->time(i));
        std::printf("\nFirst step   %s\n\n", steps->label(0).c_str());
        const std::string first = steps->label(0).substr(0, steps->label(0).find(" (step"));
        std::fputs(io::formatFileInfo(io::inspectFile(first)).c_str(), stdout);
        return 0;
    }
    std::fputs(io::formatFileInfo(io::inspectFile(path, source)).c_str(), stdout);
    return 0;
}

}  // namespace flowsurf::app
