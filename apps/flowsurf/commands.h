// flowsurf — the subcommands of the command-line program.
#pragma once

#include "bench.h"
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

// `flowsurf bench`: the suite's options (the command line sets them by name) and what only
// the command does.
struct BenchCommand {
    bench::BenchOptions suite;
    bool quick = false;       // a small subset (for smoke runs)
    bool transfers = false;   // --transfers: only the host transfer timings (bench/transfers.h)
    std::string slowdown;     // METHOD:K, hidden: proves scripts/bench-check.sh fails
};
int runBench(const BenchCommand& command);

}  // namespace flowsurf::app
