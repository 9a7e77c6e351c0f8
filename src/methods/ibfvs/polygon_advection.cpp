#include "methods/ibfvs/polygon_advection.h"

#include "methods/common/gl_path.h"
#include "methods/common/noise_injection.h"
#include "methods/common/resample.h"
#include "methods/common/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace flowsurf::methods::ibfvs {

PolygonAdvection::PolygonAdvection(const core::Viewport& viewport, const CommonParams& common,
                                   std::initializer_list<FlowPingPong::Attachment> shared)
    : noise_(common, viewport),
      path_(resolveGlPath(common.glPath)),
      raster_(common.surfaceRaster),
      renderer_(currentRendererInfo()),
      defines_(resampleDefine(common.resample) + noise_.defines() +
               (path_ == GlPath::Compute ? "#define ADVECT_IN_COMPUTE 1\n" : "")),
      lastFootprint_{0, 0, viewport.width, viewport.height} {
    program_ = program({{GL_VERTEX_SHADER, "ibfvs/polygon_advection.vert"}, {GL_FRAGMENT_SHADER, "ibfvs/polygon_advection.frag"}},
                       defines_);
    if (path_ != GlPath::Compute) return;
    advectProgram_ = program({{GL_COMPUTE_SHADER, "ibfvs/polygon_advection.comp"}},
                             resampleDefine(common.resample) + noise_.defines());
    texcoord_ = gl::Texture2D(GL_RG32F, viewport.width, viewport.height, GL_NEAREST);
    texcoordFbo_ = gl::Framebuffer::create();
    texcoordFbo_.attach(GL_COLOR_ATTACHMENT0 + outputs::kFlow, texcoord_);
    int colors = 1;
    for (const auto& [attachment, texture] : shared) {
        texcoordFbo_.attach(attachment, *texture);
        colors += attachment >= GL_COLOR_ATTACHMENT0 && attachment <= GL_COLOR_ATTACHMENT15;
    }
    texcoordFbo_.finish(colors);
}

const gl::Program& PolygonAdvection::surfaceProgram(bool visibility) {
    if (!visibility) return program_;
    if (!resolve_) {
        resolve_ = program({{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "ibfvs/polygon_resolve.frag"}},
                           defines_);
    }
    return resolve_;
}

void PolygonAdvection::apply(const SurfaceGpu& surface, const core::Camera& camera, const core::Camera& prevCamera,
                             const core::Viewport& viewport, float dt, const gl::Texture2D& prevFlow,
                             const gl::Texture2D& nextFlow, const gl::Framebuffer& nextFlowFbo,
                             const gl::Texture2D& depth, float flowBackground, bool cullBackFaces,
                             const NoiseStep& noise, ProcessGroup* occluders) {
    const Views views{camera.view(), camera.projection(viewport.aspect()) * camera.view(),
                      prevCamera.viewProjection(viewport.aspect()), dt};
    // Where this surface can be, and what the last one can have left (the buffers hold the
    // background elsewhere). Tiles (`occluders`): the clears and the per-pixel pass cover
    // just that, F_a keeping stale texels elsewhere, which nothing reads: the history comes
    // from the tiles' owners (ScreenTiles::pull), the exchange and the overlay read this
    // piece's pixels. Otherwise F_a is the next frame's history: cleared and written whole.
    footprint_ = projectedRect(surface.pieceParts(), views.viewProj, viewport.width, viewport.height);
    const PixelRect drawn = lastFootprint_.united(footprint_);
    lastFootprint_ = footprint_;
    const PixelRect work = occluders ? drawn : PixelRect{0, 0, viewport.width, viewport.height};
    // As SurfaceGBuffer: the rule counts the whole surface's triangles; a group agrees.
    const bool compute = surface.vertexTexture() && useComputeRaster(raster_, renderer_, surface.wholeTriangleCount(),
                                                                     size_t(viewport.width) * viewport.height);
    const RasterAgreement raster =
        occluders ? VisibilityBuffer::agree(*occluders, footprint_, compute, viewport) : RasterAgreement{compute, {}};
    lastVisibility_ = raster.compute;
    const gl::Program& surfacePass = surfaceProgram(lastVisibility_);
    if (lastVisibility_) rasterizeVisibility(surface, views.viewProj, viewport, cullBackFaces, drawn, occluders, raster.cells);
    const bool advectHere = path_ != GlPath::Compute;  // the fragments resample and inject
    clearTarget(advectHere ? nextFlowFbo : texcoordFbo_, viewport, flowBackground, work);
    surfacePass.use();
    setViews(surfacePass, views);
    if (advectHere) {
        noise_.bind(surfacePass, noise);
        glBindTextureUnit(bindings::kIbfvsPrevFlow, prevFlow.id());
    }
    if (lastVisibility_) resolveVisibility(surface, viewport);
    else draw(surface, cullBackFaces);
    if (advectHere) return;
    advectProgram_.use();
    noise_.bind(advectProgram_, noise);
    glUniform1f(advectProgram_.uniform("uFlowBackground"), flowBackground);
    glBindTextureUnit(bindings::kIbfvsPrevFlow, prevFlow.id());
    glBindTextureUnit(bindings::kIbfvsTexcoord, texcoord_.id());
    glBindTextureUnit(bindings::kIbfvsDepth, depth.id());
    glBindImageTexture(bindings::kIbfvsNextFlow, nextFlow.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glUniform2i(advectProgram_.uniform("uOrigin"), work.x0, work.y0);
    glUniform2i(advectProgram_.uniform("uEnd"), work.x1, work.y1);
    dispatchPerPixel(work.width(), work.height());
}

void PolygonAdvection::clearTarget(const gl::Framebuffer& target, const core::Viewport& viewport, float flowBackground,
                                   const PixelRect& rect) {
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, viewport.width, viewport.height);
    if (rect.empty()) return;
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x0, rect.y0, rect.width(), rect.height());
    // Gray background in F_a [L §IV-F.2]: what flows in from outside is the noise mean.
    const float bg[4] = {flowBackground, 0, 0, 1}, zero[4] = {0, 0, 0, 0}, one = 1.0f;
    glClearNamedFramebufferfv(target.id(), GL_COLOR, outputs::kFlow, bg);
    glClearNamedFramebufferfv(target.id(), GL_COLOR, outputs::kShade, zero);
    glClearNamedFramebufferfv(target.id(), GL_COLOR, outputs::kMask, zero);
    glClearNamedFramebufferfv(target.id(), GL_DEPTH, 0, &one);
    glDisable(GL_SCISSOR_TEST);
}

void PolygonAdvection::setViews(const gl::Program& program, const Views& views) {
    glUniformMatrix4fv(program.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(views.viewProj));
    glUniformMatrix4fv(program.uniform("uPrevViewProj"), 1, GL_FALSE, glm::value_ptr(views.prevViewProj));
    glUniformMatrix4fv(program.uniform("uView"), 1, GL_FALSE, glm::value_ptr(views.view));
    glUniform1f(program.uniform("uDt"), views.dt);
}

void PolygonAdvection::draw(const SurfaceGpu& surface, bool cullBackFaces) const {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    if (cullBackFaces) glEnable(GL_CULL_FACE);  // cost ~ N: halve it on closed surfaces
    else glDisable(GL_CULL_FACE);                // open surfaces are seen from both sides
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    surface.draw();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
}

void PolygonAdvection::rasterizeVisibility(const SurfaceGpu& surface, const glm::mat4& viewProj,
                                           const core::Viewport& viewport, bool cullBackFaces, const PixelRect& clear,
                                           ProcessGroup* occluders, const PixelRect& cells) {
    if (!visibility_) visibility_ = std::make_unique<VisibilityBuffer>(viewport);
    // Cleared where this or the last surface can be (elsewhere it holds no triangle already).
    visibility_->rasterize(surface, viewProj, cullBackFaces, clear);
    if (occluders) visibility_->dropOccluded(*occluders, cells, footprint_);
}

void PolygonAdvection::resolveVisibility(const SurfaceGpu& surface, const core::Viewport& viewport) const {
    if (footprint_.empty()) return;
    glUniform2i(resolve_.uniform("uSize"), viewport.width, viewport.height);
    visibility_->drawResolve(surface, footprint_);  // the surface's pixels only
}

}  // namespace flowsurf::methods::ibfvs
