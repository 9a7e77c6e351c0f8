// flowsurf — the timing suite behind `flowsurf bench` ([L] Tables I and II, [W] Table 1):
// ms/frame per stage for the static and the dynamic case, per mesh size, image size,
// ISA advection-mesh resolution and hybrid filter length. Timings live here, never in
// test assertions.
#pragma once

#include "core/camera.h"
#include "params/params.h"

#include <optional>
#include <string>
#include <vector>

namespace flowsurf::bench {

// Camera placement: our default framing, or ParaView's ResetCamera (the bounding box's
// sphere fills a 30 degree view), for like-for-like comparisons.
enum class BenchCamera { Fit, ParaView };
inline constexpr size_t kBenchCameras = size_t(BenchCamera::ParaView) + 1;  // the last one + 1
inline constexpr methods::EnumNames<BenchCamera, kBenchCameras> kBenchCameraNames{
    {{BenchCamera::Fit, "fit"}, {BenchCamera::ParaView, "paraview"}}};

struct BenchOptions {
    std::string csv;                     // also write CSV here
    int frames = 20;                     // timed frames per row and case
    std::vector<methods::Method> methods = [] {  // every method, in table order
        std::vector<::flowsurf::methods::Method> all;
        for (const auto& [m, name] : ::flowsurf::methods::kMethodNames) all.push_back(m);
        return all;
    }();
    std::vector<long> triangles{10'000, 80'000, 220'000, 1'000'000};
    std::vector<core::Viewport> imageSizes{{512, 512}, {1024, 1024}};
    std::vector<int> gridRes{128, 256, 512, 1024};   // ISA
    std::vector<int> filterLengths{10, 25, 50, 100};  // hybrid
    bool dynamicOnly = false;            // skip the static case (animation cost only)
    bool stageTimes = true;              // also time each stage (a second, synchronised pass)
    // Per-pixel passes as compute or fragment shaders: each path asked for; a path that
    // resolves (auto -> the renderer's) to one already run is not run again.
    std::vector<methods::GlPath> glPaths{methods::GlPath::Auto};
    // Who rasterises the surface passes: each asked for; one that resolves (auto: by
    // renderer, triangles and pixels) to one already run for the row is not run again.
    std::vector<methods::SurfaceRaster> surfaceRasters{methods::SurfaceRaster::Auto};
    // Contrast enhancement [doc/contrast.md]: each variant asked for; a row's param gains
    // "+texture" etc. for the ones that are not off (the contrast column: its stages).
    std::vector<methods::EnhanceContrast> enhanceContrast{methods::EnhanceContrast::Off};
    // Proof that the speed check fails (scripts/bench-check.sh): every frame of the method
    // named here is rendered `slowdownFactor` times, as if it had become that much slower.
    std::optional<methods::Method> slowdownMethod;
    int slowdownFactor = 1;
    // Also time the fixed calibration frame (calibration.h) before each method's rows and
    // add one row, method "calib", with the median: the machine's speed in this run.
    bool calibration = false;
    BenchCamera camera = BenchCamera::Fit;
    // Ranks [docs/parallel.md], each count its rows. Above 1: that many threads of this program, each
    // with its own GL context and a slab of the sphere (equal triangle counts along x), as
    // one methods::ThreadGroup — the ParaView plugin's ranks with memory instead of MPI —
    // in each mode of `parallel`. A row's frame and stage times are the slowest rank's.
    std::vector<int> ranks{1};
    std::vector<methods::ParallelMode> parallel{methods::ParallelMode::Tiles};
};

struct BenchRow {
    std::string method, caseName;        // "static" or "dynamic"
    long triangles = 0;
    core::Viewport image;
    std::string param;                   // "R=256" (ISA), "L=50" (hybrid), "-"
    std::string glPath;                  // the path that ran: "fragment" or "compute"
    std::string raster;                  // who rasterised the surface: "gl" or "compute"
    double frameMs = 0;                  // whole frame, pipelined (timer off)
    std::vector<std::pair<std::string, double>> stageMs;  // per stage (synchronised pass)
    int ranks = 1;                       // threads rendering the view together
    std::string parallel = "-";          // their parallel mode: "tiles" or "replicate"
};

// Runs the suite (needs a current GL context); prints the table as it goes.
std::vector<BenchRow> runBench(const BenchOptions& options);
// `ranks`: with the ranks column (a run with more than one rank).
std::string tableHeader(bool ranks = false);
std::string formatRow(const BenchRow& row, bool ranks = false);
std::string formatCsv(const std::vector<BenchRow>& rows);

}  // namespace flowsurf::bench
