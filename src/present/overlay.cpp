#include "present/overlay.h"

#include "gpu/gl_path.h"
#include "gpu/shader_interface.h"
#include "present/colormap.h"

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

// The dye layer: the dye's values on its grid, drawn over the surface where a pixel's
// surface point lies in a dyed cell.
void bindDye(const gl::Program& prog, const DyeView& dye) {
    glBindTextureUnit(bindings::kDyeIndex, dye.index);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kDyeValue, dye.values);
    glUniform1i(prog.uniform("uDyeSlot"), dye.slot);
    glUniform3fv(prog.uniform("uDyeOrigin"), 1, &dye.grid.origin.x);
    glUniform1f(prog.uniform("uDyeH"), dye.grid.h);
    glUniformMatrix4fv(prog.uniform("uInvViewProj"), 1, GL_FALSE, &dye.invViewProj[0][0]);
}
}  // namespace

Overlay::Overlay(const CommonParams& params)
    : params_(params),
      path_(resolveGlPath(params.glPath)),
      program_(makeProgram(path_, params, false)),
      colormap_(makeColormapTexture(params)),
      emptyVao_(gl::VertexArray::create()) {
    if (params.legend) legend_.emplace(params);
    if (enhancesColor(params.enhanceContrast)) {
        lightnessProgram_ = makeProgram(path_, params, false, true);
        lightness_ = PercentileRange(params.enhancePercentile, params.enhanceSmoothing);
    }
}

void Overlay::bindInputs(const gl::Program& prog, const gl::Texture2D& flow, const SurfaceImage& image) const {
    prog.use();
    // Per variant, some of these are compiled out (location -1: GL ignores the call). A
    // stretched texture [doc/contrast.md] has its range already: no display gain on top.
    glUniform1f(prog.uniformIfActive("uBeta"), params_.beta);
    glUniform1f(prog.uniformIfActive("uContrast"), enhancesTexture(params_.enhanceContrast) ? 1.0f : params_.contrast);
    glUniform3fv(prog.uniformIfActive("uBackground"), 1, &params_.background.x);
    glBindTextureUnit(bindings::kOverlayFlow, flow.id());
    glBindTextureUnit(bindings::kOverlayDepth, image.depth.id());
    glBindTextureUnit(bindings::kOverlayShade, image.shade.id());
    glBindTextureUnit(bindings::kOverlayColormap, colormap_.id());
    glBindTextureUnit(bindings::kOverlayMask, image.mask.id());
}

void Overlay::measureLightness(const gl::Texture2D& flow, const SurfaceImage& image) const {
    if (!lightnessProgram_) return;
    bindInputs(lightnessProgram_, flow, image);  // the legend image is compiled out
    glUniform2i(lightnessProgram_.uniform("uEnd"), flow.width(), flow.height());
    lightness_.bindCleared();
    PercentileRange::dispatchHistogram(flow.width(), flow.height());
    lightness_.update();
}

void Overlay::apply(const gl::Texture2D& flow, const SurfaceImage& image, const gl::Framebuffer& target,
                    const SurfaceGpu& surface, const DyeView* dye, const std::optional<PixelRect>& pixels) const {
    if (legend_) legend_->place(surface, image.depth);
    const PixelRect r = pixels.value_or(PixelRect{0, 0, flow.width(), flow.height()});
    if (r.empty()) return;
    if (dye && !dyeProgram_) dyeProgram_ = makeProgram(path_, params_, true);
    const gl::Program& prog = dye ? dyeProgram_ : program_;
    bindInputs(prog, flow, image);
    if (lightnessProgram_) {
        const glm::vec2 l = lightness_.range();
        glUniform2f(prog.uniform("uLightRange"), l.x, l.y);
    }
    if (legend_) legend_->bind(prog);
    else glBindTextureUnit(bindings::kOverlayLegend, colormap_.id());  // a unit the variant never reads
    if (dye) bindDye(prog, *dye);
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
