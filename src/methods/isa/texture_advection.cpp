#include "methods/isa/texture_advection.h"

#include "gpu/gl_path.h"
#include "gpu/shader_interface.h"
#include "methods/image_space/noise_injection.h"
#include "methods/image_space/resample.h"

#include <vector>

namespace flowsurf::methods::isa {

namespace {
gl::Program makeProgram(IsaWarp warp, GlPath path, EdgeFill fill, Resample resample, const NoiseInjection& noise) {
    const std::string defines =
        resampleDefine(resample) + noise.defines() + "#define EDGE_FILL " + std::to_string(int(fill)) + "\n";
    if (warp == IsaWarp::Pixel && path == GlPath::Compute)
        return program({{GL_COMPUTE_SHADER, "isa/texture_advection.comp"}}, defines);
    if (warp == IsaWarp::Pixel)
        return program({{GL_VERTEX_SHADER, "gpu/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "isa/texture_advection.frag"}},
                       "#define PER_PIXEL 1\n" + defines);
    return program({{GL_VERTEX_SHADER, "isa/texture_advection.vert"}, {GL_FRAGMENT_SHADER, "isa/texture_advection.frag"}},
                   defines);
}
}  // namespace

TextureAdvection::TextureAdvection(const core::Viewport& viewport, const IsaParams& isa, const CommonParams& common)
    : gridRes_(isa.gridRes),
      warp_(isa.warp),
      // The mesh warp rasterises the grid's 2 R^2 triangles: the paper's variant, kept as
      // its cost model (cost ~ M); per pixel in a compute pass it would be the pixel warp.
      path_(isa.warp == IsaWarp::Pixel ? resolveGlPath(common.glPath) : GlPath::Fragment),
      fill_(isa.edgeFill),
      fillAlpha_(common.alpha),
      noise_(common, viewport),
      vao_(gl::VertexArray::create()),
      program_(makeProgram(isa.warp, path_, isa.edgeFill, common.resample, noise_)) {
    const int gridRes = isa.gridRes;
    if (warp_ != IsaWarp::Mesh) return;
    // Two triangles per grid cell; vertices come from the mesh texture by gl_VertexID.
    std::vector<uint32_t> idx;
    idx.reserve(size_t(gridRes) * gridRes * 6);
    const uint32_t row = uint32_t(gridRes + 1);
    for (uint32_t j = 0; j < uint32_t(gridRes); ++j)
        for (uint32_t i = 0; i < uint32_t(gridRes); ++i) {
            uint32_t a = j * row + i;
            idx.insert(idx.end(), {a, a + 1, a + row + 1, a, a + row + 1, a + row});
        }
    indexCount_ = GLsizei(idx.size());
    indices_ = gl::Buffer(GLsizeiptr(idx.size() * sizeof(uint32_t)), idx.data(), 0);
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
}

void TextureAdvection::apply(const gl::Texture2D& mesh, const gl::Texture2D& prevFlow, const gl::Texture2D& surfaceDepth,
                             const gl::Texture2D& nextFlow, const gl::Framebuffer& nextFlowFbo, bool edgeBlending,
                             const NoiseStep& noise, const PixelRect& pixels) const {
    program_.use();
    glUniform1i(program_.uniform("uGridRes"), gridRes_);
    glUniform1i(program_.uniform("uEdgeBlending"), edgeBlending);
    if (fill_ == EdgeFill::Noise) glUniform1f(program_.uniform("uFillAlpha"), fillAlpha_);
    noise_.bind(program_, noise);
    glBindTextureUnit(bindings::kIsaPrevFlow, prevFlow.id());
    glBindTextureUnit(bindings::kIsaMesh, mesh.id());
    glBindTextureUnit(bindings::kIsaSurfaceDepth, surfaceDepth.id());
    const PixelRect r = pixels.empty() ? PixelRect{0, 0, nextFlow.width(), nextFlow.height()} : pixels;
    if (path_ == GlPath::Compute) {
        glUniform2i(program_.uniform("uOrigin"), r.x0, r.y0);
        glUniform2i(program_.uniform("uEnd"), r.x1, r.y1);
        glBindImageTexture(bindings::kIsaNextFlow, nextFlow.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
        dispatchPerPixel(r.width(), r.height());
        return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, nextFlowFbo.id());
    glViewport(0, 0, nextFlow.width(), nextFlow.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    if (!pixels.empty()) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(r.x0, r.y0, r.width(), r.height());
    }
    glBindVertexArray(vao_.id());
    if (warp_ == IsaWarp::Mesh)
        glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    else
        glDrawArrays(GL_TRIANGLES, 0, 3);
    if (!pixels.empty()) glDisable(GL_SCISSOR_TEST);
}

}  // namespace flowsurf::methods::isa
