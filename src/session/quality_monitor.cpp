// flowsurf — which frames a session measures and the log of their quality
// (quality_monitor.h).
#include "session/quality_monitor.h"

#include "core/errors.h"

#include <epoxy/gl.h>

#include <chrono>

namespace flowsurf::session {

void QualityMonitor::configure(int every, const quality::QualityParams& params) {
    if (every < 0) throw ConfigError("quality: measure every N frames, N >= 0 (0: off)");
    every_ = every;
    params_ = params;
    probes_.clear();
    clear();
}

void QualityMonitor::rebuilt(size_t views, const core::Viewport& viewport, bool cullBackFaces) {
    views_ = views;
    viewport_ = viewport;
    cullBackFaces_ = cullBackFaces;
    probes_.clear();
    clear();
}

void QualityMonitor::clear() {
    log_.assign(views_, {});
    counter_ = 0;
}

void QualityMonitor::planFrame() {
    if (every_ <= 0) {
        next_ = Step::None;
        return;
    }
    const int phase = counter_++ % every_;
    next_ = phase == every_ - 1 ? Step::Measure : phase == every_ - 2 ? Step::Keep : Step::None;
}

void QualityMonitor::planStill(int stillFrame, int frame) {
    // A still: its last frame, and the one before it for the correlations.
    if (every_ <= 0) next_ = Step::None;
    else next_ = frame == stillFrame ? Step::Measure : frame + 1 == stillFrame ? Step::Keep : Step::None;
}

void QualityMonitor::makeProbes() {
    if (probes_.size() == views_) return;
    probes_.clear();
    for (size_t i = 0; i < views_; ++i)
        probes_.push_back(std::make_unique<quality::QualityProbe>(viewport_, params_, cullBackFaces_));
}

void QualityMonitor::collect(size_t view, const methods::FlowMethod& method, const methods::SurfaceGpu& surface,
                             const core::Camera& camera, uint32_t k) {
    makeProbes();
    glFinish();  // the method's frame is not the quality's time
    const auto t0 = std::chrono::steady_clock::now();
    if (next_ == Step::Keep) probes_[view]->keep(method, camera, k);
    else log_[view].push_back(probes_[view]->measure(method, surface, camera, k));
    ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

quality::FrameQuality QualityMonitor::measure(size_t view, const methods::FlowMethod& method,
                                              const methods::SurfaceGpu& surface, const core::Camera& camera,
                                              uint32_t k) {
    makeProbes();
    return probes_.at(view)->measure(method, surface, camera, k);
}

}  // namespace flowsurf::session
