#include "methods/common/frame.h"

#include <algorithm>

namespace flowsurf::methods {

float dtForStep(const FrameInput& in, const core::Viewport& viewport, float stepPx) {
    float speed = in.surface->maxSpeed();
    if (speed <= 0.0f) return 0.0f;
    float pxPerUnit = core::maxPixelsPerUnit(in.camera, viewport, in.surface->bounds());
    return stepPx / (speed * std::max(pxPerUnit, 1e-30f));
}

}  // namespace flowsurf::methods
