#include "present/legend_layer.h"

#include "gl/readback.h"
#include "gpu/gpu_bindings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>

namespace flowsurf::methods {

namespace {
// The legend's sizes, as fractions of the image height it is laid out for, upright at a side
// and then lying along the top or bottom: the first that finds a free place is shown
// [docs/cfd.md, colour ranges]; none is drawn over the surface.
constexpr float kLegendScales[] = {1.0f, 0.8f, 0.64f, 0.5f};
constexpr LegendLayout kLegendLayouts[] = {LegendLayout::Vertical, LegendLayout::Horizontal};
constexpr size_t kLegendTries = std::size(kLegendScales) * std::size(kLegendLayouts);
constexpr glm::ivec2 kNowhere{-(1 << 24)};  // an origin that puts every legend pixel outside the image

gl::Texture2D legendTexture(const RgbImage& img) {
    // GL rows run bottom to top.
    std::vector<uint8_t> flipped(img.pixels.size());
    const size_t row = size_t(img.width) * 4;
    for (int y = 0; y < img.height; ++y)
        std::copy_n(&img.pixels[size_t(img.height - 1 - y) * row], row, &flipped[size_t(y) * row]);
    gl::Texture2D t(GL_RGBA8, img.width, img.height, GL_NEAREST);
    glTextureSubImage2D(t.id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
    return t;
}
}  // namespace

LegendLayer::Size& LegendLayer::sized(size_t i, int imageHeight) {
    Size& l = sizes_[i];
    if (!l.texture.id()) {
        l.imageHeight = std::max(1, int(std::lround(float(imageHeight) * kLegendScales[i % std::size(kLegendScales)])));
        l.layout = kLegendLayouts[i / std::size(kLegendScales)];
        const RgbImage img = makeLegendImage(params_, scale_, title_, l.imageHeight, l.layout);
        l.size = {img.width, img.height};
        l.texture = legendTexture(img);
    }
    return l;
}

void LegendLayer::place(const SurfaceGpu& surface, const gl::Texture2D& depth) {
    const int width = depth.width(), height = depth.height();
    const std::string title = params_.title.empty() ? surface.colorName() : params_.title;
    const LegendScale scale = legendScale(params_, surface.colorRange(), surface.colorDataRange());
    // (1) new range, marks or title: the sizes are laid out again when next needed
    if (sizes_.empty() || scale.range != scale_.range || scale.below != scale_.below || scale.above != scale_.above ||
        title != title_) {
        sizes_.clear();
        sizes_.resize(kLegendTries);
        scale_ = scale;
        title_ = title;
    }
    // (2) the largest size with a place covering no surface pixel; the one shown stays put
    // while it is free
    const std::vector<float> z = gl::readDepth(depth);
    for (size_t i = 0; i < sizes_.size(); ++i) {
        const std::optional<glm::ivec2> keep = placed_ && i == shown_ ? std::optional(origin_) : std::nullopt;
        const Size& l = sized(i, height);
        if (auto at = freeLegendOrigin(z, width, height, l.size, keep, l.layout)) {
            shown_ = i;
            origin_ = *at;
            placed_ = true;
            return;
        }
    }
    // (3) nowhere free: no legend this frame, and the user told once
    placed_ = false;
    origin_ = kNowhere;
    if (!warned_)
        std::fprintf(stderr,
                     "flowsurf: warning: the colour legend finds no place in the %dx%d image that leaves the "
                     "surface uncovered, so it is left out where that happens; a larger --size or a camera "
                     "that leaves some background makes room\n",
                     width, height);
    warned_ = true;
}

void LegendLayer::bind(const gl::Program& prog) const {
    glUniform2i(prog.uniform("uLegendOrigin"), origin_.x, origin_.y);
    glBindTextureUnit(bindings::kOverlayLegend, sizes_[shown_].texture.id());
}

}  // namespace flowsurf::methods
