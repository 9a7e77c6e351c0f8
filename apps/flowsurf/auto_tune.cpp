// flowsurf quality --auto-tune: a small grid of each method's parameters on the current
// view (the render options given, e.g. --config saved by the viewer), each setting's
// animation measured as `flowsurf quality` does; prints every setting by its score (see
// rank()), marks those on the trade-off front of orientation error, frame correlation
// and ms/frame, and names the best trade.
#include "commands.h"

#include "core/errors.h"
#include "gl/context.h"
#include "io/series_reader.h"
#include "progress.h"
#include "session/playback.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace flowsurf::app {

namespace {

// The grid: option names of the table and the values tried; a method's grid has the axes
// whose rows apply to it (OptionSpec::appliesTo), in this order.
struct Axis {
    const char* option;
    std::vector<const char*> values;
};
std::vector<Axis> gridFor(methods::Method m) {
    static const std::vector<Axis> axes{{"filter-length", {"15", "31", "61"}}, {"lic-step-px", {"1", "2", "3"}},
                                        {"step-px", {"2", "4", "6"}},          {"alpha", {"0.05", "0.08", "0.15"}},
                                        {"noise-scale", {"2", "3"}}};
    std::vector<Axis> grid;
    for (const Axis& a : axes)
        if (findOption(a.option)->appliesTo(m)) grid.push_back(a);
    return grid;
}

struct Trial {
    std::vector<std::string> values;
    double error = 0, correlation = 0, counted = 0, ms = 0;
    bool front = false;
    double score = 0;
};

// Every combination of the axes' values, first axis slowest.
std::vector<std::vector<std::string>> combinations(const std::vector<Axis>& axes) {
    std::vector<std::vector<std::string>> out{{}};
    for (const Axis& a : axes) {
        std::vector<std::vector<std::string>> next;
        for (const auto& prefix : out)
            for (const char* v : a.values) {
                next.push_back(prefix);
                next.back().push_back(v);
            }
        out.swap(next);
    }
    return out;
}

// Marks the trials no other trial beats in all three (error, 1 - correlation, ms), and
// scores each: error in degrees + 100 (1 - frame correlation) + 10 (1 - counted fraction)
// + 5 log2(ms / fastest ms), so 1 degree weighs as much as 0.01 of correlation, a tenth of
// the surface without clear streaks and 15 % of time.
void rank(std::vector<Trial>& trials) {
    double fastest = 1e300;
    for (const Trial& t : trials) fastest = std::min(fastest, t.ms);
    for (Trial& t : trials) {
        t.score = t.error + 100.0 * (1.0 - t.correlation) + 10.0 * (1.0 - t.counted) +
                  5.0 * std::log2(std::max(t.ms / fastest, 1.0));
        t.front = std::none_of(trials.begin(), trials.end(), [&](const Trial& o) {
            const bool noWorse = o.error <= t.error && o.correlation >= t.correlation && o.ms <= t.ms;
            return noWorse && (o.error < t.error || o.correlation > t.correlation || o.ms < t.ms);
        });
    }
}

}  // namespace

int runAutoTune(const RenderOptions& o, const std::string& methodList, const QualityOutput& q) {
    validateRenderOptions(o);
    validateQualityOutput(q);
    if (!q.file.empty()) throw ConfigError("--auto-tune prints its table: leave out --quality");
    const std::vector<methods::Method> names = splitMethods(methodList);
    std::unique_ptr<core::StepProvider> steps = io::openInput(o.input, sourceOptions(o));
    (void)FrameCameras(o, steps->bounds());
    gl::HeadlessContext context(o.verbose);

    for (methods::Method name : names) {
        const std::vector<Axis> axes = gridFor(name);
        const auto grid = combinations(axes);
        const std::string method(methods::nameOf(methods::kMethodNames, name));
        std::vector<Trial> trials;
        ProgressBar progress("auto-tune " + method, int(grid.size()), !o.quiet);
        int done = 0;
        for (const auto& values : grid) {
            RenderOptions oc = o;
            for (size_t a = 0; a < axes.size(); ++a) setOption(oc, axes[a].option, values[a]);
            Playback playback(oc, {name});
            playback.open(*steps);
            Trial t;
            t.values = values;
            t.ms = advanceMeasured(playback, oc.frames, q.every, true);
            const quality::QualitySummary s = playback.quality().summary(0);
            t.error = s.median.orientationErrorDeg;
            t.correlation = s.median.frameCorrelationReprojected;
            t.counted = s.median.countedFraction;
            // Streaks too incoherent to count on most of the surface: not a candidate.
            if (!std::isnan(t.error) && !std::isnan(t.correlation) && t.counted >= 0.5) trials.push_back(t);
            progress.update(++done);
        }
        progress.finish();
        if (trials.empty()) {
            std::printf("%s: no setting drew coherent streaks on half the surface\n", method.c_str());
            continue;
        }
        rank(trials);
        std::sort(trials.begin(), trials.end(), [](const Trial& a, const Trial& b) { return a.score < b.score; });
        std::printf("%s: %zu settings, %d frames after the warm-up each, measured every %d\n", method.c_str(),
                    grid.size(), o.frames + 1, q.every);
        for (const Axis& a : axes) std::printf("%-14s", a.option);
        std::printf("%-11s%-11s%-9s%-10s%-7s%s\n", "orient_err", "frame_corr", "counted", "ms/frame", "score", "front");
        for (const Trial& t : trials) {
            for (const std::string& v : t.values) std::printf("%-14s", v.c_str());
            std::printf("%-11.2f%-11.3f%-9.2f%-10.1f%-7.2f%s\n", t.error, t.correlation, t.counted, t.ms, t.score,
                        t.front ? "*" : "");
        }
        const Trial& best = trials.front();
        std::printf("best trade for %s:", method.c_str());
        for (size_t a = 0; a < axes.size(); ++a) std::printf(" --%s %s", axes[a].option, best.values[a].c_str());
        std::printf("  (error %.2f deg, frame correlation %.3f, %.1f ms/frame)\n\n", best.error, best.correlation, best.ms);
    }
    return 0;
}

}  // namespace flowsurf::app
