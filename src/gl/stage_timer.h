// flowsurf — per-stage GPU timing for the benchmark, the viewer's stats and the API. Each
// stage boundary writes a GL timestamp query (glQueryCounter, GL_TIMESTAMP) into the
// command stream, so nothing waits mid-frame; a frame's results are read once the GPU has
// passed its end: at the next beginFrame if ready, else when meanMs() asks for them.
// Contexts without timer queries (GL < 3.3) fall back to glFinish + a CPU clock at each
// boundary. Disabled by default; the per-frame pipeline then issues nothing.
#pragma once

#include "gl/objects.h"

#include <chrono>
#include <ctime>
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace flowsurf::gl {

class StageTimer {
public:
    void setEnabled(bool enabled) { enabled_ = enabled; }
    // Synchronous: glFinish + a CPU clock at each boundary instead of timestamp queries.
    // The pipeline drains at every stage, but each stage is charged its own work also on
    // renderers that defer work until a flush (llvmpipe rasterises a draw when a later
    // command needs it, so its timestamp lands inside the next stage). Call between frames.
    void setSynchronous(bool on) {
        synchronous_ = on;
        queries_ = -1;
    }
    bool enabled() const { return enabled_; }
    void beginFrame();
    // Marks the start of stage `name` (and the end of the previous one).
    void begin(const char* name);
    void endFrame();
    // Mean ms per frame for each stage since reset(), in first-seen order. A stage that
    // ran in only some frames (the dynamic stages) is averaged over all frames. Waits for
    // the frames still on the GPU, unless `waitForGpu` is false (a live display each frame:
    // the frames whose timestamps are in so far). The context must be current, as for every
    // call here.
    std::vector<std::pair<std::string, double>> meanMs(bool waitForGpu = true) const;
    // Synchronous mode only (else empty): the process's CPU time per stage (std::clock: every
    // thread of the process, a software renderer's included), mean ms per frame as meanMs().
    std::vector<std::pair<std::string, double>> meanCpuMs() const;
    void reset();

private:
    using Query = Handle<detail::deleteQuery>;
    // A timestamp and the stage that starts there ("" for none: the frame's end, or
    // before its first stage).
    struct Mark {
        std::string stage;
        Query query;
    };
    using Clock = std::chrono::steady_clock;

    void mark(const char* stage);
    // Adds the pending frames whose results are in to the totals, and waits for the
    // oldest ones until at most `keep` remain pending.
    void collect(size_t keep) const;
    void recycle(std::vector<Mark>& marks) const;
    void add(const std::string& stage, double ms) const;

    bool enabled_ = false;
    bool synchronous_ = false;
    int queries_ = -1;  // timer queries supported: -1 not yet asked
    std::vector<Mark> current_;
    // Mutable: meanMs() (const to its callers) folds in the frames still pending.
    mutable std::deque<std::vector<Mark>> pending_;
    mutable std::vector<Query> free_;
    mutable std::vector<std::string> order_;
    mutable std::map<std::string, double> totalMs_;
    std::map<std::string, double> totalCpuMs_;
    mutable int frames_ = 0;
    // Fallback without timer queries.
    std::string stage_;
    Clock::time_point since_;
    std::clock_t cpuSince_ = 0;
};

}  // namespace flowsurf::gl
