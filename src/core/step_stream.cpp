#include "core/step_stream.h"

#include "core/errors.h"

#include <algorithm>

namespace flowsurf::core {

StepStream::StepStream(StepProvider& provider, size_t window, bool prefetch)
    : provider_(provider), window_(std::max<size_t>(window, 2)), prefetch_(prefetch) {
    if (provider.count() == 0) throw FormatError("the time series has no steps");
    for (size_t i = 0; i < provider.count(); ++i) times_.push_back(provider.time(i));
    if (!std::is_sorted(times_.begin(), times_.end()))
        throw FormatError(provider.label(0) + ": time values are not increasing");
}

StepStream::~StepStream() {
    if (pending_.valid()) pending_.wait();  // a load may be running on the worker
}

std::shared_ptr<const SurfaceMesh> StepStream::step(size_t index) {
    if (auto it = cache_.find(index); it != cache_.end()) return it->second;
    std::shared_ptr<const SurfaceMesh> mesh;
    if (pending_.valid() && pendingIndex_ == index) {
        mesh = pending_.get();  // rethrows the worker's error, naming the step
    } else {
        if (pending_.valid()) pending_.wait();  // never two loads at once
        mesh = std::make_shared<const SurfaceMesh>(provider_.load(index));
    }
    cache_[index] = mesh;
    return mesh;
}

void StepStream::startPrefetch(size_t index) {
    if (!prefetch_ || index >= times_.size() || cache_.count(index)) return;
    if (pending_.valid()) {
        if (pendingIndex_ == index) return;
        // Keep a finished prefetch; an unfinished one for another step is awaited.
        try {
            auto mesh = pending_.get();
            cache_[pendingIndex_] = mesh;
        } catch (...) {
            // The step is loaded again, and its error reported, when it is needed.
        }
    }
    pendingIndex_ = index;
    pending_ = std::async(std::launch::async,
                          [this, index] { return std::make_shared<const SurfaceMesh>(provider_.load(index)); });
}

bool StepStream::kept(size_t index, size_t keepA, size_t keepB) const {
    return index == keepA || index == keepB || (haveKeepRange_ && index >= keepLo_ && index <= keepHi_);
}

void StepStream::keepRange(size_t lo, size_t hi) {
    FLOWSURF_CHECK(lo <= hi && hi < times_.size());
    haveKeepRange_ = true;
    keepLo_ = lo;
    keepHi_ = hi;
    // The range, the frame's bracket beside it and one prefetched step.
    window_ = std::max(window_, hi - lo + 4);
    evict(last_.a, last_.b);
    startPrefetch(hi + 1);
}

void StepStream::evict(size_t keepA, size_t keepB) {
    // Drop the steps farthest behind first: the animation moves forward.
    while (cache_.size() > window_ - (pending_.valid() ? 1 : 0)) {
        auto victim = cache_.end();
        for (auto it = cache_.begin(); it != cache_.end(); ++it)
            if (!kept(it->first, keepA, keepB)) {
                victim = it;
                break;
            }
        if (victim == cache_.end()) break;
        cache_.erase(victim);
    }
}

const SurfaceMesh& StepStream::meshAt(double t, bool* changed) {
    StepBracket br = bracket(times_, t);
    const bool same = haveCurrent_ && br.a == last_.a && br.b == last_.b && br.weight == last_.weight;
    if (changed) *changed = !same;
    if (same) return current_;
    auto a = step(br.a);
    if (br.a != br.b) {
        auto b = step(br.b);
        if (sameTopology(*a, *b)) {
            current_ = interpolate(*a, *b, br.weight);
            topologyStep_ = br.a;
        } else {
            // Topology changes between the steps: use the nearer one, never mix buffers.
            const bool nearerB = br.weight >= 0.5;
            current_ = nearerB ? *b : *a;
            topologyStep_ = nearerB ? br.b : br.a;
        }
    } else {
        current_ = *a;
        topologyStep_ = br.a;
    }
    haveCurrent_ = true;
    last_ = br;
    evict(br.a, br.b);
    startPrefetch(std::max(br.b, haveKeepRange_ ? keepHi_ : 0) + 1);
    return current_;
}

}  // namespace flowsurf::core
