#include "commands.h"

#include "bench.h"
#include "transfers.h"
#include "core/errors.h"
#include "gl/context.h"
#include "cli_options.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace flowsurf::app {

namespace {

// --slowdown METHOD:K (hidden): K renders per timed frame of METHOD.
void parseSlowdown(const std::string& text, bench::BenchOptions& b) {
    const size_t colon = text.find(':');
    methods::Method named{};
    const bool known = methods::valueOf(methods::kMethodNames, text.substr(0, colon), &named);
    int factor = 0;
    if (colon != std::string::npos) {
        try {
            size_t used = 0;
            factor = std::stoi(text.substr(colon + 1), &used);
            if (used != text.size() - colon - 1) factor = 0;
        } catch (const std::exception&) {
            factor = 0;
        }
    }
    if (!known || factor < 1 || factor > 100)
        throw ConfigError("--slowdown: '" + text + "' is not METHOD:K (a method name, K renders per frame, 1..100)");
    b.slowdownMethod = named;
    b.slowdownFactor = factor;
}

}  // namespace

int runBench(const BenchOptions& o) {
    bench::BenchOptions b;
    b.frames = o.frames;
    b.methods.clear();
    for (const auto& m : o.methods) b.methods.push_back(parseName(methods::kMethodNames, m, "--methods"));
    b.triangles = o.triangles;
    b.imageSizes.clear();
    for (const auto& s : o.sizes) b.imageSizes.push_back(parseSize(s, "--sizes"));
    b.gridRes = o.grids;
    b.filterLengths = o.lengths;
    b.dynamicOnly = o.dynamicOnly;
    b.camera = parseName(bench::kBenchCameraNames, o.camera, "--camera");
    b.glPaths.clear();
    for (const auto& p : o.glPaths) b.glPaths.push_back(parseName(methods::kGlPathNames, p, "--gl-paths"));
    b.surfaceRasters.clear();
    for (const auto& r : o.surfaceRasters)
        b.surfaceRasters.push_back(parseName(methods::kSurfaceRasterNames, r, "--surface-rasters"));
    b.enhanceContrast.clear();
    for (const auto& e : o.enhanceContrast)
        b.enhanceContrast.push_back(parseName(methods::kEnhanceContrastNames, e, "--enhance-contrast"));
    b.ranks = o.ranks;
    b.parallel.clear();
    for (const auto& m : o.parallel) b.parallel.push_back(parseName(methods::kParallelModeNames, m, "--parallel"));
    b.stageTimes = !o.noStageTimes;
    b.calibration = o.calibration;
    if (!o.slowdown.empty()) parseSlowdown(o.slowdown, b);
    if (o.quick) {
        b.triangles = {10'000, 220'000};
        b.imageSizes = {{512, 512}};
        b.gridRes = {128, 256};
        b.filterLengths = {25};
    }
    gl::HeadlessContext context(false);
    std::printf("flowsurf bench on %s (ms per frame; frame pipelined, stages synchronised)\n",
                context.description().c_str());
    // The driver and its version, for figures from several machines (bench/gpu/run.sh).
    std::printf("GL driver: %s; %s\n", reinterpret_cast<const char*>(glGetString(GL_VENDOR)),
                reinterpret_cast<const char*>(glGetString(GL_VERSION)));
    if (o.transfers) {
        bench::runTransfers(b.imageSizes, std::max(o.frames, 5));
        return 0;
    }
    if (b.slowdownFactor > 1)
        std::printf("--slowdown: every frame of %s rendered %d times (a test of the speed check, not a measurement)\n",
                    std::string(methods::nameOf(methods::kMethodNames, *b.slowdownMethod)).c_str(), b.slowdownFactor);
    std::vector<bench::BenchRow> rows = bench::runBench(b);
    if (!o.csv.empty()) {
        std::string tmp = o.csv + ".tmp";
        std::ofstream f(tmp);
        f << bench::formatCsv(rows);
        if (!f.good() || (f.close(), std::rename(tmp.c_str(), o.csv.c_str()) != 0)) {
            std::remove(tmp.c_str());
            throw IoError(o.csv + ": cannot write the CSV file");
        }
    }
    return 0;
}

}  // namespace flowsurf::app
