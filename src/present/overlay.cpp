#include "present/overlay.h"

#include "gl/readback.h"
#include "gpu/gl_path.h"
#include "gpu/shader_interface.h"
#include "present/colormap.h"
#include "present/legend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>

namespace flowsurf::methods {

namespace {
// The variant for these parameters (SCHEME, WITH_* in overlay.glsl).
// The lightness histogram of contrast enhancement [doc/contrast.md] measures the colour before
// its stretch, without dye or legend: `lightness` makes that variant.
gl::Program makeProgram(GlPath path, const CommonParams& params, bool withDye, bool lightness = false) {
    auto flag = [](const char* name, bool on) { return std::string("#define ") + name + (on ? " 1\n" : " 0\n"); };
    const std::string defines = "#define SCHEME " + std::to_string(int(params.overlay)) + "\n" +
                                flag("WITH_LEGEND", params.legend && !lightness) + flag("WITH_DYE", withDye) +
                                flag("WITH_COLORMAP", params.colormap != Colormap::None || !params.colormapTable.empty()) +
                                flag("WITH_LIGHTING", params.lighting) +
                                flag("WITH_MASK", params.velocityMask || !params.maskBy.empty()) +
                                flag("WITH_COLOR_STRETCH", enhancesColor(params.enhanceContrast) && !lightness);
    if (lightness) return program({{GL_COMPUTE_SHADER, "present/lightness_histogram.comp"}}, defines);
    if (path == GlPath::Compute) return program({{GL_COMPUTE_SHADER, "present/overlay.comp"}}, defines);
    return program({{GL_VERTEX_SHADER, "gpu/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "present/overlay.frag"}},
                   defines);
}
}  // namespace

Overlay::Overlay(const CommonParams& params)
    : params_(params),
      path_(resolveGlPath(params.glPath)),
      program_(makeProgram(path_, params, false)),
      colormap_(makeColormapTexture(params)),
      emptyVao_(gl::VertexArray::create()) {
    if (enhancesColor(params.enhanceContrast)) {
        lightnessProgram_ = makeProgram(path_, params, false, true);
        lightness_ = PercentileRange(params.enhancePercentile, params.enhanceSmoothing);
    }
}

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

void Overlay::updateLegend(const SurfaceGpu& surface, const gl::Texture2D& depth) const {
    const int width = depth.width(), height = depth.height();
    const std::string title = params_.title.empty() ? surface.colorName() : params_.title;
    const LegendScale scale = legendScale(params_, surface.colorRange(), surface.colorDataRange());
    // (1) new range, marks or title: the sizes are laid out again when next needed
    if (legendSizes_.empty() || scale.range != legendScale_.range || scale.below != legendScale_.below ||
        scale.above != legendScale_.above || title != legendTitle_) {
        legendSizes_.clear();
        legendSizes_.resize(kLegendTries);
        legendScale_ = scale;
        legendTitle_ = title;
    }
    auto sized = [&](size_t i) -> LegendSize& {
        LegendSize& l = legendSizes_[i];
        if (!l.texture.id()) {
            l.imageHeight = std::max(1, int(std::lround(float(height) * kLegendScales[i % std::size(kLegendScales)])));
            l.layout = kLegendLayouts[i / std::size(kLegendScales)];
            const RgbImage img = makeLegendImage(params_, legendScale_, legendTitle_, l.imageHeight, l.layout);
            l.size = {img.width, img.height};
            l.texture = legendTexture(img);
        }
        return l;
    };
    // (2) the largest size with a place covering no surface pixel; the one shown stays put
    // while it is free (no jumping in a movie)
    const std::vector<float> z = gl::readDepth(depth);
    for (size_t i = 0; i < legendSizes_.size(); ++i) {
        const bool placed = legendPlaced_ && i == legendShown_;
        const std::optional<glm::ivec2> keep = placed ? std::optional(legendOrigin_) : std::nullopt;
        const LegendSize& l = sized(i);
        if (auto at = freeLegendOrigin(z, width, height, l.size, keep, l.layout)) {
            legendShown_ = i;
            legendOrigin_ = *at;
            legendPlaced_ = true;
            return;
        }
    }
    // (3) nowhere free: no legend this frame, and the user told once
    legendPlaced_ = false;
    legendOrigin_ = kNowhere;
    if (!legendWarned_)
        std::fprintf(stderr,
                     "flowsurf: warning: the colour legend finds no place in the %dx%d image that leaves the "
                     "surface uncovered, so it is left out where that happens; a larger --size or a camera "
                     "that leaves some background makes room\n",
                     width, height);
    legendWarned_ = true;
}

void Overlay::bindInputs(const gl::Program& prog, const gl::Texture2D& flow, const gl::Texture2D& depth,
                         const gl::Texture2D& shade, const gl::Texture2D& mask) const {
    prog.use();
    // Per variant, some of these are compiled out (location -1: GL ignores the call). A
    // stretched texture [doc/contrast.md] has its range already: no display gain on top.
    glUniform1f(prog.uniformIfActive("uBeta"), params_.beta);
    glUniform1f(prog.uniformIfActive("uContrast"), enhancesTexture(params_.enhanceContrast) ? 1.0f : params_.contrast);
    glUniform3fv(prog.uniformIfActive("uBackground"), 1, &params_.background.x);
    glBindTextureUnit(bindings::kOverlayFlow, flow.id());
    glBindTextureUnit(bindings::kOverlayDepth, depth.id());
    glBindTextureUnit(bindings::kOverlayShade, shade.id());
    glBindTextureUnit(bindings::kOverlayColormap, colormap_.id());
    glBindTextureUnit(bindings::kOverlayMask, mask.id());
}

void Overlay::measureLightness(const gl::Texture2D& flow, const gl::Texture2D& depth, const gl::Texture2D& shade,
                               const gl::Texture2D& mask) const {
    if (!lightnessProgram_) return;
    bindInputs(lightnessProgram_, flow, depth, shade, mask);  // the legend image is compiled out
    glUniform2i(lightnessProgram_.uniform("uEnd"), flow.width(), flow.height());
    lightness_.bindCleared();
    PercentileRange::dispatchHistogram(flow.width(), flow.height());
    lightness_.update();
}

void Overlay::apply(const gl::Texture2D& flow, const gl::Texture2D& depth, const gl::Texture2D& shade,
                    const gl::Texture2D& mask, const gl::Framebuffer& target, const SurfaceGpu& surface,
                    const DyeView* dye, const std::optional<PixelRect>& pixels) const {
    if (params_.legend) updateLegend(surface, depth);
    const PixelRect r = pixels.value_or(PixelRect{0, 0, flow.width(), flow.height()});
    if (r.empty()) return;
    if (dye && !dyeProgram_) dyeProgram_ = makeProgram(path_, params_, true);
    const gl::Program& prog = dye ? dyeProgram_ : program_;
    bindInputs(prog, flow, depth, shade, mask);
    if (params_.legend) glUniform2i(prog.uniform("uLegendOrigin"), legendOrigin_.x, legendOrigin_.y);
    if (lightnessProgram_) {
        const glm::vec2 l = lightness_.range();
        glUniform2f(prog.uniform("uLightRange"), l.x, l.y);
    }
    glBindTextureUnit(bindings::kOverlayLegend, params_.legend ? legendSizes_[legendShown_].texture.id() : colormap_.id());
    if (dye) {
        glBindTextureUnit(bindings::kDyeIndex, dye->index);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kDyeValue, dye->values);
        glUniform1i(prog.uniform("uDyeSlot"), dye->slot);
        glUniform3fv(prog.uniform("uDyeOrigin"), 1, &dye->grid.origin.x);
        glUniform1f(prog.uniform("uDyeH"), dye->grid.h);
        glUniformMatrix4fv(prog.uniform("uInvViewProj"), 1, GL_FALSE, &dye->invViewProj[0][0]);
    }
    if (path_ == GlPath::Compute) {
        // The composite is the target's colour attachment (RGBA8, as every method keeps it).
        GLint composite = 0;
        glGetNamedFramebufferAttachmentParameteriv(target.id(), GL_COLOR_ATTACHMENT0,
                                                   GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &composite);
        glBindImageTexture(bindings::kOverlayImage, GLuint(composite), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
        glUniform2i(prog.uniform("uOrigin"), r.x0, r.y0);
        glUniform2i(prog.uniform("uEnd"), r.x1, r.y1);
        dispatchPerPixel(r.width(), r.height());  // read next also by the edge mask's draw
        return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, flow.width(), flow.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    if (pixels) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(r.x0, r.y0, r.width(), r.height());
    }
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (pixels) glDisable(GL_SCISSOR_TEST);
}

}  // namespace flowsurf::methods
