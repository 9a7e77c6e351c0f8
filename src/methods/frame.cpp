#include "methods/frame.h"

#include "core/errors.h"
#include "parallel/process_group.h"
#include "parallel/screen_split.h"
#include "raster/surface_gpu.h"

#include <algorithm>
#include <string>

namespace flowsurf::methods {

float dtForStep(const FrameInput& in, const core::Viewport& viewport, float stepPx) {
    float speed = in.surface->maxSpeed();
    if (speed <= 0.0f) return 0.0f;
    // A process of a group holds one piece: its samples would give it its own dt, so the
    // group keeps to the bounds, which all processes share.
    float pxPerUnit = core::maxPixelsPerUnit(in.camera, viewport, in.surface->bounds(),
                                             in.group ? std::span<const glm::vec3>{} : in.surface->positionSamples());
    return stepPx / (speed * std::max(pxPerUnit, 1e-30f));
}

bool tiledParallel(const FrameInput& in, const CommonParams& params) { return tiledParallel(in.group, params.parallel); }

bool tiledParallel(const ProcessGroup* group, ParallelMode mode) {
    return group && group->size() > 1 && mode == ParallelMode::Tiles;
}

std::optional<PixelRect> piecePixels(const FrameInput& in, const CommonParams& params, const core::Viewport& viewport) {
    if (!tiledParallel(in, params)) return std::nullopt;
    return projectedRect(in.surface->pieceParts(), in.camera.viewProjection(viewport.aspect()), viewport.width,
                         viewport.height);
}

void checkContrastParallel(const FrameInput& in, const CommonParams& params) {
    if (enhancesColor(params.enhanceContrast) && tiledParallel(in, params))
        throw ConfigError("enhance-contrast " + std::string(nameOf(kEnhanceContrastNames, params.enhanceContrast)) +
                          ": the colour's stretch needs the whole image's colours, which the tiles mode divides "
                          "over the processes; set parallel to replicate (FlowSurfParallel) or enhance-contrast to "
                          "texture");
}

}  // namespace flowsurf::methods
