#include "present/contrast_stretch.h"

#include "gpu/shader_interface.h"

namespace flowsurf::methods {

ContrastStretch::ContrastStretch(const CommonParams& params, const core::Viewport& viewport)
    : enabled_(enhancesTexture(params.enhanceContrast)), viewport_(viewport) {
    if (!enabled_) return;
    range_ = PercentileRange(params.enhancePercentile, params.enhanceSmoothing);
    histogram_ = program({{GL_COMPUTE_SHADER, "present/contrast_histogram.comp"}});
    stretch_ = program({{GL_COMPUTE_SHADER, "present/contrast_stretch.comp"}});
    stretched_ = gl::Texture2D(GL_R32F, viewport.width, viewport.height, GL_LINEAR);
}

void ContrastStretch::measure(const gl::Texture2D& flow, const gl::Texture2D& depth,
                              const std::optional<PixelRect>& pixels, ProcessGroup* group) {
    if (!enabled_) return;
    const PixelRect r = pixels.value_or(PixelRect{0, 0, viewport_.width, viewport_.height});
    range_.bindCleared();
    if (!r.empty()) {
        glBindTextureUnit(bindings::kContrastFlow, flow.id());
        glBindTextureUnit(bindings::kContrastDepth, depth.id());
        histogram_.use();
        glUniform2i(histogram_.uniform("uOrigin"), r.x0, r.y0);
        glUniform2i(histogram_.uniform("uEnd"), r.x1, r.y1);
        PercentileRange::dispatchHistogram(r.width(), r.height());
    }
    range_.update(group);
}

const gl::Texture2D& ContrastStretch::stretch(const gl::Texture2D& flow, const gl::Texture2D& depth) {
    if (!enabled_) return flow;
    const glm::vec2 r = range_.range();
    glBindTextureUnit(bindings::kContrastFlow, flow.id());
    glBindTextureUnit(bindings::kContrastDepth, depth.id());
    stretch_.use();
    glUniform2f(stretch_.uniform("uRange"), r.x, r.y);
    glUniform2i(stretch_.uniform("uEnd"), viewport_.width, viewport_.height);
    glBindImageTexture(bindings::kContrastImage, stretched_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    dispatchPerPixel(viewport_.width, viewport_.height);
    return stretched_;
}

}  // namespace flowsurf::methods
