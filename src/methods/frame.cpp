#include "methods/frame.h"

#include "raster/surface_gpu.h"

#include <algorithm>
#include <span>

namespace flowsurf::methods {

float dtForStep(const FrameInput& in, const core::Viewport& viewport, float stepPx, const ProcessGroup* group) {
    float speed = in.surface->maxSpeed();
    if (speed <= 0.0f) return 0.0f;
    // A process of a group holds one piece: its samples would give it its own dt, so the
    // group keeps to the bounds, which all processes share.
    float pxPerUnit = core::maxPixelsPerUnit(in.camera, viewport, in.surface->bounds(),
                                             group ? std::span<const glm::vec3>{} : in.surface->positionSamples());
    return stepPx / (speed * std::max(pxPerUnit, 1e-30f));
}

}  // namespace flowsurf::methods
