#include "methods/common/overlay.h"

#include "methods/common/colormap.h"
#include "methods/common/gl_path.h"
#include "methods/common/legend.h"
#include "methods/common/shader_interface.h"

#include <algorithm>

namespace flowsurf::methods {

namespace {
// The variant for these parameters (SCHEME, WITH_* in overlay.glsl).
gl::Program makeProgram(GlPath path, const CommonParams& params, bool withDye) {
    auto flag = [](const char* name, bool on) { return std::string("#define ") + name + (on ? " 1\n" : " 0\n"); };
    const std::string defines = "#define SCHEME " + std::to_string(int(params.overlay)) + "\n" +
                                flag("WITH_LEGEND", params.legend) + flag("WITH_DYE", withDye) +
                                flag("WITH_COLORMAP", params.colormap != Colormap::None || !params.colormapTable.empty()) +
                                flag("WITH_LIGHTING", params.lighting) +
                                flag("WITH_MASK", params.velocityMask || !params.maskBy.empty());
    if (path == GlPath::Compute) return program({{GL_COMPUTE_SHADER, "common/overlay.comp"}}, defines);
    return program({{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "common/overlay.frag"}},
                   defines);
}
}  // namespace

Overlay::Overlay(const CommonParams& params)
    : params_(params),
      path_(resolveGlPath(params.glPath)),
      program_(makeProgram(path_, params, false)),
      colormap_(makeColormapTexture(params)),
      emptyVao_(gl::VertexArray::create()) {}

void Overlay::updateLegend(const SurfaceGpu& surface, int width, int height) const {
    const std::string title = params_.title.empty() ? surface.colorName() : params_.title;
    const LegendScale scale = legendScale(params_, surface.colorRange(), surface.colorDataRange());
    if (legend_.id() && scale.range == legendScale_.range && scale.below == legendScale_.below &&
        scale.above == legendScale_.above && title == legendTitle_)
        return;
    RgbImage img = makeLegendImage(params_, scale, title, height);
    // GL rows run bottom to top.
    std::vector<uint8_t> flipped(img.pixels.size());
    const size_t row = size_t(img.width) * 4;
    for (int y = 0; y < img.height; ++y)
        std::copy_n(&img.pixels[size_t(img.height - 1 - y) * row], row, &flipped[size_t(y) * row]);
    legend_ = gl::Texture2D(GL_RGBA8, img.width, img.height, GL_NEAREST);
    glTextureSubImage2D(legend_.id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
    legendOrigin_ = legendOrigin(img, width, height);
    legendScale_ = scale;
    legendTitle_ = title;
}

void Overlay::apply(const gl::Texture2D& flow, const gl::Texture2D& depth, const gl::Texture2D& shade,
                    const gl::Texture2D& mask, const gl::Framebuffer& target, const SurfaceGpu& surface,
                    const DyeView* dye) const {
    if (params_.legend) updateLegend(surface, flow.width(), flow.height());
    if (dye && !dyeProgram_) dyeProgram_ = makeProgram(path_, params_, true);
    const gl::Program& prog = dye ? dyeProgram_ : program_;
    prog.use();
    // Per variant, some of these are compiled out (location -1: GL ignores the call).
    glUniform1f(prog.uniformIfActive("uBeta"), params_.beta);
    glUniform1f(prog.uniformIfActive("uContrast"), params_.contrast);
    glUniform3fv(prog.uniformIfActive("uBackground"), 1, &params_.background.x);
    if (params_.legend) glUniform2i(prog.uniform("uLegendOrigin"), legendOrigin_.x, legendOrigin_.y);
    glBindTextureUnit(0, flow.id());
    glBindTextureUnit(1, depth.id());
    glBindTextureUnit(2, shade.id());
    glBindTextureUnit(3, colormap_.id());
    glBindTextureUnit(4, mask.id());
    glBindTextureUnit(5, params_.legend ? legend_.id() : colormap_.id());
    if (dye) {
        glBindTextureUnit(kDyeIndexUnit, dye->index);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDyeValueBinding, dye->values);
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
        glBindImageTexture(0, GLuint(composite), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
        dispatchPerPixel(flow.width(), flow.height());  // read next also by the edge mask's draw
        return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, flow.width(), flow.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace flowsurf::methods
