#include "session/topology_overlay.h"

#include <cmath>

namespace flowsurf::session {

TopologyOverlay::TopologyOverlay(core::StepProvider& steps, const RenderOptions& o)
    : steps_(steps),
      source_(steps, o),
      series_(steps.count() > 1 && !o.timeStepGiven),
      fixedStep_(o.timeStepGiven ? o.timeStep : 0) {
    style_.points = o.topologyParts != "lines";
    style_.lines = o.topologyParts != "points";
    style_.glyphSize = o.topologyGlyphSize;
    style_.lineWidth = o.topologyLineWidth;
    uploaded_ = series_ ? stepAt(o.timeRange ? o.timeRange->first : steps.time(0)) : fixedStep_;
    shown_ = &source_.at(uploaded_);
    layer_.upload(*shown_);
}

size_t TopologyOverlay::stepAt(double time) const {
    if (!series_) return fixedStep_;
    size_t best = 0;
    for (size_t i = 1; i < steps_.count(); ++i)
        if (std::abs(steps_.time(i) - time) < std::abs(steps_.time(best) - time)) best = i;
    return best;
}

void TopologyOverlay::draw(const methods::FlowMethod& method, const core::Camera& camera, double time) {
    const size_t step = stepAt(time);
    if (step != uploaded_) {
        shown_ = &source_.at(step);
        layer_.upload(*shown_);
        uploaded_ = step;
    }
    layer_.draw(method.composite(), method.surfaceDepth(), camera, style_);
}

}  // namespace flowsurf::session
