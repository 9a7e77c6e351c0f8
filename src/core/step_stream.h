// flowsurf — streaming a time series through the animation: at most a small window of
// steps is resident, the next step loads on a worker thread while the current frames
// render, and the mesh at any data time is interpolated from the bracketing steps.
#pragma once

#include "core/time_series.h"

#include <future>
#include <map>
#include <memory>

namespace flowsurf::core {

class StepStream {
public:
    // `window`: most steps kept resident (>= 2). `prefetch`: load the next step on a
    // worker thread (loads never run concurrently: the provider needs no locking).
    StepStream(StepProvider& provider, size_t window = 3, bool prefetch = true);
    ~StepStream();
    StepStream(const StepStream&) = delete;
    StepStream& operator=(const StepStream&) = delete;

    // The surface at data time t. `changed` tells whether it differs from the previous
    // call's (same bracket and weight: unchanged, nothing needs uploading). Throws what the
    // provider throws for a missing or corrupt step.
    const SurfaceMesh& meshAt(double t, bool* changed = nullptr);
    // The step index whose topology the last mesh has (changes when topology may).
    size_t topologyStep() const { return topologyStep_; }
    // For methods that read the field over a window of data time around the frame (the
    // hybrid method's time levels): keeps steps lo..hi resident besides the frame's
    // bracket (the window grows to fit) and prefetches the step after hi.
    void keepRange(size_t lo, size_t hi);
    // Step `index` as loaded (cached within the window). Throws what the provider throws.
    std::shared_ptr<const SurfaceMesh> stepMesh(size_t index) { return step(index); }
    size_t resident() const { return cache_.size(); }
    std::string label(size_t index) const { return provider_.label(index); }
    const std::vector<double>& times() const { return times_; }

private:
    std::shared_ptr<const SurfaceMesh> step(size_t index);
    void startPrefetch(size_t index);
    void evict(size_t keepA, size_t keepB);
    bool kept(size_t index, size_t keepA, size_t keepB) const;

    StepProvider& provider_;
    size_t window_;
    bool prefetch_;
    std::vector<double> times_;
    std::map<size_t, std::shared_ptr<const SurfaceMesh>> cache_;
    size_t pendingIndex_ = 0;
    std::future<std::shared_ptr<const SurfaceMesh>> pending_;
    SurfaceMesh current_;
    bool haveCurrent_ = false;
    StepBracket last_;
    size_t topologyStep_ = 0;
    bool haveKeepRange_ = false;
    size_t keepLo_ = 0, keepHi_ = 0;
};

}  // namespace flowsurf::core
