// flowsurf — the subcommands of the command-line program.
#pragma once

#include "cli_options.h"
#include "io/dataset_reader.h"
#include "quality_report.h"
#include "session/playback.h"

#include <string>
#include <vector>

namespace flowsurf::app {

int runRender(const RenderOptions& options, const QualityOutput& quality = {});
int runInfo(const std::string& path, const io::SourceOptions& source = {});
// The flow topology of the input's shown field, written as JSON, CSV or VTP (doc/topology.md).
int runTopology(const RenderOptions& options);
// Methods side by side on the same camera and frames, labelled with ms/frame.
int runCompare(const RenderOptions& options, const std::string& methods, const QualityOutput& quality = {});
// "isa,ibfvs" -> methods; ConfigError naming a bad entry (--methods of compare, quality).
std::vector<methods::Method> splitMethods(const std::string& list);
// Frames 0..frames of `playback` from a fresh start (after its warm-up if `warmUp`),
// measured every `every` frames; returns ms/frame, each frame timed alone, the quality's
// own time left out.
double advanceMeasured(session::Playback& playback, int frames, int every, bool warmUp);
// The quality table of each method's animation (doc/algorithms.md, "Quality metrics").
int runQuality(const RenderOptions& options, const std::string& methods, const QualityOutput& quality);
// quality --auto-tune: a small parameter grid per method on this view, the trade-off
// front of orientation error, frame correlation and ms/frame, and the best trade.
int runAutoTune(const RenderOptions& options, const std::string& methods, const QualityOutput& quality);

struct BenchOptions {
    std::string csv;          // also write CSV here
    int frames = 20;          // timed frames per row
    bool quick = false;       // a small subset (for smoke runs)
    std::vector<std::string> methods = ::flowsurf::methods::names(::flowsurf::methods::kMethodNames);
    std::vector<long> triangles{10'000, 80'000, 220'000, 1'000'000};
    std::vector<std::string> sizes{"512x512", "1024x1024"};
    std::vector<int> grids{128, 256, 512, 1024};
    std::vector<int> lengths{10, 25, 50, 100};
    bool dynamicOnly = false;
    std::string camera = "fit";
    std::vector<std::string> glPaths{"auto"};
    std::vector<std::string> surfaceRasters{"auto"};
    std::vector<std::string> enhanceContrast{"off"};  // --enhance-contrast: each variant a row
    std::vector<int> ranks{1};                        // --ranks: each count a row
    std::vector<std::string> parallel{"tiles"};       // --parallel: each mode a row (ranks > 1)
    bool noStageTimes = false;
    bool calibration = false;
    bool transfers = false;   // --transfers: only the host transfer timings (bench/transfers.h)
    std::string slowdown;     // METHOD:K, hidden: proves scripts/bench-check.sh fails
};
int runBench(const BenchOptions& options);

}  // namespace flowsurf::app
