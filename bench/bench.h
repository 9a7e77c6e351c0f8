// flowsurf — the timing suite behind `flowsurf bench` ([L] Tables I and II): ms/frame
// per stage for the static and the dynamic case, per mesh size, image size and ISA
// advection-mesh resolution. Timings live here, never in test assertions.
#pragma once

#include <string>
#include <vector>

namespace flowsurf::bench {

struct BenchOptions {
    std::string csv;                     // also write CSV here
    int frames = 20;                     // timed frames per row and case
    bool quick = false;                  // a small subset (smoke run)
    std::vector<std::string> methods{"isa"};
    std::vector<long> triangles{10'000, 80'000, 220'000, 1'000'000};
    std::vector<int> imageSizes{512, 1024};
    std::vector<int> gridRes{128, 256, 512, 1024};
};

struct BenchRow {
    std::string method, caseName;        // "static" or "dynamic"
    long triangles = 0;
    int imageSize = 0, gridRes = 0;
    double frameMs = 0;                  // whole frame, pipelined (timer off)
    std::vector<std::pair<std::string, double>> stageMs;  // per stage (synchronised)
};

// Runs the suite (needs a current GL context); prints the table as it goes.
std::vector<BenchRow> runBench(const BenchOptions& options);
std::string formatTable(const std::vector<BenchRow>& rows);
std::string formatCsv(const std::vector<BenchRow>& rows);

}  // namespace flowsurf::bench
