#include "methods/common/contrast_stretch.h"

#include "core/errors.h"
#include "methods/common/frame.h"
#include "methods/common/shader_interface.h"

namespace flowsurf::methods {

ContrastStretch::ContrastStretch(const CommonParams& params, const core::Viewport& viewport)
    : enabled_(enhancesTexture(params.enhanceContrast)), viewport_(viewport) {
    if (!enabled_) return;
    range_ = PercentileRange(params.enhancePercentile, params.enhanceSmoothing);
    histogram_ = program({{GL_COMPUTE_SHADER, "common/contrast_histogram.comp"}});
    stretch_ = program({{GL_COMPUTE_SHADER, "common/contrast_stretch.comp"}});
    stretched_ = gl::Texture2D(GL_R32F, viewport.width, viewport.height, GL_LINEAR);
}

const gl::Texture2D& ContrastStretch::apply(const gl::Texture2D& flow, const gl::Texture2D& depth) {
    if (!enabled_) return flow;
    glBindTextureUnit(kContrastFlowUnit, flow.id());
    glBindTextureUnit(kContrastDepthUnit, depth.id());
    // (a) the histogram over the surface and its smoothed percentiles
    histogram_.use();
    glUniform2i(histogram_.uniform("uEnd"), viewport_.width, viewport_.height);
    range_.bindCleared();
    PercentileRange::dispatchHistogram(viewport_.width, viewport_.height);
    const glm::vec2 r = range_.update();
    // (b) the stretch
    stretch_.use();
    glUniform2f(stretch_.uniform("uRange"), r.x, r.y);
    glUniform2i(stretch_.uniform("uEnd"), viewport_.width, viewport_.height);
    glBindImageTexture(0, stretched_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    dispatchPerPixel(viewport_.width, viewport_.height);
    return stretched_;
}

void checkContrastParallel(const FrameInput& in, const CommonParams& params) {
    if (params.enhanceContrast != EnhanceContrast::Off && tiledParallel(in, params))
        throw ConfigError("enhance-contrast " + std::string(nameOf(kEnhanceContrastNames, params.enhanceContrast)) +
                          ": the stretch needs the whole image's percentiles, which the tiles mode divides over "
                          "the processes; set parallel to replicate (FlowSurfParallel) or enhance-contrast to off");
}

}  // namespace flowsurf::methods
