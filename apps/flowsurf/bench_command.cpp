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

int runBench(const BenchCommand& command) {
    bench::BenchOptions b = command.suite;
    if (!command.slowdown.empty()) parseSlowdown(command.slowdown, b);
    if (command.quick) {
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
    if (command.transfers) {
        bench::runTransfers(b.imageSizes, std::max(b.frames, 5));
        return 0;
    }
    if (b.slowdownFactor > 1)
        std::printf("--slowdown: every frame of %s rendered %d times (a test of the speed check, not a measurement)\n",
                    std::string(methods::nameOf(methods::kMethodNames, *b.slowdownMethod)).c_str(), b.slowdownFactor);
    std::vector<bench::BenchRow> rows = bench::runBench(b);
    if (!b.csv.empty()) {
        std::string tmp = b.csv + ".tmp";
        std::ofstream f(tmp);
        f << bench::formatCsv(rows);
        if (!f.good() || (f.close(), std::rename(tmp.c_str(), b.csv.c_str()) != 0)) {
            std::remove(tmp.c_str());
            throw IoError(b.csv + ": cannot write the CSV file");
        }
    }
    return 0;
}

}  // namespace flowsurf::app
