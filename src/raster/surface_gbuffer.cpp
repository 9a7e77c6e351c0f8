#include "raster/surface_gbuffer.h"

#include "gpu/gl_path.h"
#include "gpu/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace flowsurf::methods {

namespace {
constexpr size_t kPieceTriangles = 4096;
constexpr size_t kMaxPieces = 8;
}  // namespace

SurfaceGBuffer::SurfaceGBuffer(const core::Viewport& viewport, bool withPosition, bool cullBackFaces,
                               bool clearBackground, SurfaceRaster raster)
    : viewport_(viewport),
      velocity_(GL_RGBA32F, viewport.width, viewport.height, GL_LINEAR),
      shade_(GL_RGBA16F, viewport.width, viewport.height, GL_NEAREST),
      mask_(GL_R16F, viewport.width, viewport.height, GL_NEAREST),
      depth_(GL_DEPTH_COMPONENT32F, viewport.width, viewport.height, GL_NEAREST),
      fbo_(gl::Framebuffer::create()),
      program_(program({{GL_VERTEX_SHADER, "raster/surface_gbuffer.vert"}, {GL_FRAGMENT_SHADER, "raster/surface_gbuffer.frag"}},
               withPosition ? "#define WITH_POSITION 1\n" : "")),
      raster_(raster),
      renderer_(currentRendererInfo()),
      targets_(withPosition ? 4 : 3),
      cullBackFaces_(cullBackFaces),
      clearBackground_(clearBackground) {
    fbo_.attach(GL_COLOR_ATTACHMENT0 + outputs::kVelObj, velocity_);
    fbo_.attach(GL_COLOR_ATTACHMENT0 + outputs::kShade, shade_);
    fbo_.attach(GL_COLOR_ATTACHMENT0 + outputs::kMask, mask_);
    if (withPosition) {
        position_ = gl::Texture2D(GL_RGBA32F, viewport.width, viewport.height, GL_NEAREST);
        fbo_.attach(GL_COLOR_ATTACHMENT0 + outputs::kPosObj, position_);
    }
    fbo_.attach(GL_DEPTH_ATTACHMENT, depth_);
    fbo_.finish(targets_);
    lastFootprint_ = {0, 0, viewport.width, viewport.height};
}

glm::vec4 layerDepthRow(const core::Camera& camera) {
    const glm::mat4 view = camera.view();
    const float range = std::max(camera.farPlane - camera.nearPlane, 1e-30f);
    // Eye depth d = -(view row 2) . (p, 1).
    glm::vec4 row = -glm::vec4(view[0][2], view[1][2], view[2][2], view[3][2]) / range;
    row.w += 1.0f - camera.nearPlane / range;
    return row;
}

PixelRect SurfaceGBuffer::beginFootprint(const SurfaceGpu& surface, const glm::mat4& viewProj) {
    footprint_ = projectedRect(surface.pieceParts(), viewProj, viewport_.width, viewport_.height);
    const PixelRect clear = lastFootprint_.united(footprint_);
    lastFootprint_ = footprint_;
    return clear;
}

void SurfaceGBuffer::bindAndClear(const PixelRect& rect) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, viewport_.width, viewport_.height);
    if (rect.empty()) return;
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x0, rect.y0, rect.width(), rect.height());
    const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
    if (clearBackground_)
        for (int i : {0, 3})  // velocity, position (surface_gbuffer.h)
            if (i < targets_) glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, i, zero);
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
    glDisable(GL_SCISSOR_TEST);
}

void SurfaceGBuffer::render(const SurfaceGpu& surface, const core::Camera& camera, ProcessGroup* occluders) {
    const glm::mat4 view = camera.view(), viewProj = camera.projection(viewport_.aspect()) * view;
    const PixelRect clear = beginFootprint(surface, viewProj);
    const bool compute = surface.vertexTexture() && useComputeRaster(raster_, renderer_, surface.wholeTriangleCount(),
                                                                     size_t(viewport_.width) * viewport_.height);
    const RasterAgreement raster =
        occluders ? VisibilityBuffer::agree(*occluders, footprint_, compute, viewport_) : RasterAgreement{compute, {}};
    if (raster.compute) {
        renderVisibility(surface, camera, viewProj, clear, occluders, raster.cells);
        return;
    }
    bindAndClear(clear);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    if (cullBackFaces_) glEnable(GL_CULL_FACE);  // see CommonParams::cullBackFaces
    else glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    program_.use();
    glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniformMatrix4fv(program_.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
    glUniform4fv(program_.uniform("uLayerDepthRow"), 1, glm::value_ptr(layerDepthRow(camera)));
    // Pieces of at least kPieceTriangles, at most kMaxPieces: on llvmpipe (2 cores) the
    // surface pass of a 59k-triangle sphere at 512^2 took 10.5-11.0 ms in 8 pieces, 13.9-15.0
    // in 3 of 16k and ~18 in one draw (218k: 26.5-28.5 / 31.5-33.1 ms); 16 pieces gained
    // nothing more. Small surfaces stay one draw.
    const int pieces = int(std::clamp<size_t>(surface.triangleCount() / kPieceTriangles, 1, kMaxPieces));
    surface.drawInPieces(pieces);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
}

void SurfaceGBuffer::renderVisibility(const SurfaceGpu& surface, const core::Camera& camera, const glm::mat4& viewProj,
                                      const PixelRect& clear, ProcessGroup* occluders, const PixelRect& cells) {
    if (!visibility_) {
        visibility_ = std::make_unique<VisibilityBuffer>(viewport_);
        resolve_ = program({{GL_VERTEX_SHADER, "gpu/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "raster/visibility_resolve.frag"}},
                           targets_ == 4 ? "#define WITH_POSITION 1\n" : "");
    }
    visibility_->rasterize(surface, viewProj, cullBackFaces_, clear);
    if (occluders) visibility_->dropOccluded(*occluders, cells, footprint_);
    bindAndClear(clear);
    if (footprint_.empty()) return;
    resolve_.use();
    glUniformMatrix4fv(resolve_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniformMatrix4fv(resolve_.uniform("uView"), 1, GL_FALSE, glm::value_ptr(camera.view()));
    glUniform4fv(resolve_.uniform("uLayerDepthRow"), 1, glm::value_ptr(layerDepthRow(camera)));
    glUniform2i(resolve_.uniform("uSize"), viewport_.width, viewport_.height);
    visibility_->drawResolve(surface, footprint_);
}

void SurfaceGBuffer::merge(ProcessGroup& group) {
    footprint_ = lastFootprint_ = PixelRect{0, 0, viewport_.width, viewport_.height};  // every pixel may hold a fragment now
    if (position_) mergeByDepth(group, depth_, {&velocity_, &shade_, &mask_, &position_});
    else mergeByDepth(group, depth_, {&velocity_, &shade_, &mask_});
}

}  // namespace flowsurf::methods
