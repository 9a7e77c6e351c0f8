// flowsurf — per-stage timing for the benchmark. Each stage boundary waits for the GPU
// (glFinish) and reads a CPU clock: exact on llvmpipe and on GPUs alike, at the cost of
// pipelining, so the benchmark times whole frames separately with the timer off.
// Disabled by default; the per-frame pipeline then does no synchronisation at all.
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace flowsurf::gl {

class StageTimer {
public:
    void setEnabled(bool enabled) { enabled_ = enabled; }
    bool enabled() const { return enabled_; }
    void beginFrame();
    // Marks the start of stage `name` (and the end of the previous one).
    void begin(const char* name);
    void endFrame();
    // Mean ms per frame for each stage since reset(), in first-seen order. A stage that
    // ran in only some frames (the dynamic stages) is averaged over all frames.
    std::vector<std::pair<std::string, double>> meanMs() const;
    void reset();

private:
    using Clock = std::chrono::steady_clock;
    bool enabled_ = false;
    std::string current_;
    Clock::time_point mark_;
    std::vector<std::string> order_;
    std::map<std::string, double> totalMs_;
    int frames_ = 0;
    void close();
};

}  // namespace flowsurf::gl
