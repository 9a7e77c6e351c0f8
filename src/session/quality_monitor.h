// flowsurf — the quality measurements of a session (doc/algorithms.md, "Quality metrics"),
// the part of session::Playback that decides which frames are measured and keeps the log:
// every N-th frame that is not warm-up (animation, still and live frames alike; a still
// measures its last frame only), with the frame before each kept for the correlations.
// Off (N = 0) by default: the probes read back every frame they look at.
#pragma once

#include "methods/frame.h"
#include "quality/quality_probe.h"

#include <memory>
#include <vector>

namespace flowsurf::session {

class QualityMonitor {
public:
    // every > 0: measure every view's F_a against the field on every `every`-th frame that
    // is not warm-up, reading back the frame before each for the correlations; 0: off.
    // Throws ConfigError for every < 0.
    void configure(int every, const quality::QualityParams& params = {});
    int every() const { return every_; }
    // The frames of view `view` measured since the animation (re)started, the build, or
    // clear(); and their median and worst.
    const std::vector<quality::FrameQuality>& frames(size_t view) const { return log_.at(view); }
    quality::QualitySummary summary(size_t view) const { return quality::summarize(frames(view)); }
    // The log empty for every view, the count of frames at 0 (an animation starts over).
    void clear();
    // Wall time the quality took in the last frame (measuring, or keeping the frame for the
    // next measurement; 0: none), for timers that leave it out.
    double msLastFrame() const { return ms_; }
    // Measures the frame view `view` drew last now: `method` its renderer, drawn of
    // `surface` with `camera` at noise clock k (Playback::lastFrame()). With the monitor off
    // it has no frame before it, so no correlations. Not added to the log.
    quality::FrameQuality measure(size_t view, const methods::FlowMethod& method, const methods::SurfaceGpu& surface,
                                  const core::Camera& camera, uint32_t k);

private:
    // The frame loop's side (Playback): new renderers, and each frame planned before it is
    // drawn and collected per view after it.
    friend class Playback;
    // New renderers: `views` of them at `viewport`; the probes are made again when needed
    // and the log starts empty.
    void rebuilt(size_t views, const core::Viewport& viewport, bool cullBackFaces);
    void planFrame();                       // an animation or live frame
    void planStill(int stillFrame, int frame);  // frame `frame` of a still ending at stillFrame
    void planNothing() { next_ = Step::None; }  // warm-up
    bool plannedFrame() const { return next_ != Step::None; }
    // View `view` has drawn the planned frame with `method`: keep it or measure it.
    void collect(size_t view, const methods::FlowMethod& method, const methods::SurfaceGpu& surface,
                 const core::Camera& camera, uint32_t k);
    // The frame is done: wall time of its measurements in msLastFrame(), nothing planned.
    void frameDone() { next_ = Step::None; }
    void frameStarts() { ms_ = 0.0; }
    enum class Step { None, Keep, Measure };
    void makeProbes();

    int every_ = 0;
    quality::QualityParams params_;
    size_t views_ = 0;
    core::Viewport viewport_;
    bool cullBackFaces_ = false;
    Step next_ = Step::None;
    double ms_ = 0.0;
    int counter_ = 0;                   // frames since the log was cleared, warm-up not
    std::vector<std::unique_ptr<quality::QualityProbe>> probes_;
    std::vector<std::vector<quality::FrameQuality>> log_;
};

}  // namespace flowsurf::session
