// flowsurf — quality reports of the command line (doc/algorithms.md, "Quality metrics"):
// `--quality FILE.json` on render, compare and quality, and the table `flowsurf quality`
// prints. The metric names and their order come from quality::metricTable().
#pragma once

#include "quality/frame_metrics.h"
#include "session/options/options.h"

#include <string>
#include <vector>

namespace flowsurf::app {

// `--quality FILE.json` and how often to measure.
struct QualityOutput {
    std::string file;  // empty: no report
    int every = 1;     // measure every N-th frame of an animation (a PNG: its last frame)
};
// Refuses, before any work, a report path that is not a .json file or an interval below 1
// (ConfigError), and a report path whose directory does not exist (IoError).
void validateQualityOutput(const QualityOutput& q);

// One method's frames and their summary.
struct MethodQuality {
    std::string method;
    double msPerFrame = 0.0;  // the quality's own time left out; NaN: not timed
    std::vector<quality::FrameQuality> frames;
    quality::QualitySummary summary;
};

// The report as JSON: the options (every option of the table), the renderer string, the
// metric parameters, and per method the median, the worst and every measured frame.
std::string qualityJson(const session::RenderOptions& o, const std::string& command, const std::string& glRenderer,
                        int every, const std::vector<MethodQuality>& methods);
// The table: one row per method, the median over frames (the worst in brackets where it
// differs by more than the printed precision); NaN prints as "-".
std::string qualityTable(const std::vector<MethodQuality>& methods);

}  // namespace flowsurf::app
