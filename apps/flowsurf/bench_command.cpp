#include "commands.h"

#include "bench.h"
#include "core/errors.h"
#include "gl/context.h"
#include "cli_options.h"

#include <cstdio>
#include <fstream>

namespace flowsurf::app {

int runBench(const BenchOptions& o) {
    bench::BenchOptions b;
    b.frames = o.frames;
    b.methods = o.methods;
    b.triangles = o.triangles;
    b.imageSizes.clear();
    for (const auto& s : o.sizes) b.imageSizes.push_back(parseSize(s, "--sizes"));
    b.gridRes = o.grids;
    b.filterLengths = o.lengths;
    b.dynamicOnly = o.dynamicOnly;
    b.camera = o.camera;
    if (o.quick) {
        b.triangles = {10'000, 220'000};
        b.imageSizes = {{512, 512}};
        b.gridRes = {128, 256};
        b.filterLengths = {25};
    }
    gl::HeadlessContext context(false);
    std::printf("flowsurf bench on %s (ms per frame; frame pipelined, stages from GPU timestamps)\n",
                context.description().c_str());
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
