#include "methods/ibfvs/polygon_advection.h"

#include "gpu/gl_path.h"
#include "gpu/shader_interface.h"
#include "methods/image_space/noise_injection.h"
#include "methods/image_space/resample.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <limits>

namespace flowsurf::methods::ibfvs {

namespace {
// readRegion's pass (texcoord_bounds.comp, which says why it has no shared memory):
// invocations side by side in a work group, and the pixels each walks down its column.
constexpr int kBoundsColumns = 64, kBoundsRows = 64;
}  // namespace

PolygonAdvection::PolygonAdvection(const core::Viewport& viewport, const CommonParams& common,
                                   std::initializer_list<FlowPingPong::Attachment> shared)
    : noise_(common, viewport),
      path_(resolveGlPath(common.glPath)),
      defines_(resampleDefine(common.resample) + noise_.defines()),
      shared_(shared),
      raster_(common.surfaceRaster),
      renderer_(currentRendererInfo()),
      lastFootprint_{0, 0, viewport.width, viewport.height} {
    surfaceProgram(false, path_ == GlPath::Compute);
    if (path_ == GlPath::Compute) makeDeferred(viewport);
}

void PolygonAdvection::makeDeferred(const core::Viewport& viewport) {
    if (advectProgram_) return;
    advectProgram_ = program({{GL_COMPUTE_SHADER, "ibfvs/polygon_advection.comp"}}, defines_);
    texcoord_ = gl::Texture2D(GL_RG32F, viewport.width, viewport.height, GL_NEAREST);
    texcoordFbo_ = gl::Framebuffer::create();
    texcoordFbo_.attach(GL_COLOR_ATTACHMENT0 + outputs::kFlow, texcoord_);
    int colors = 1;
    for (const auto& [attachment, texture] : shared_) {
        texcoordFbo_.attach(attachment, *texture);
        colors += attachment >= GL_COLOR_ATTACHMENT0 && attachment <= GL_COLOR_ATTACHMENT15;
    }
    texcoordFbo_.finish(colors);
}

const gl::Program& PolygonAdvection::surfaceProgram(bool visibility, bool deferred) {
    gl::Program& p = visibility ? resolve_[deferred] : draw_[deferred];
    if (p) return p;
    const std::string defines = defines_ + (deferred ? "#define ADVECT_IN_COMPUTE 1\n" : "");
    if (visibility)
        p = program({{GL_VERTEX_SHADER, "gpu/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "ibfvs/polygon_resolve.frag"}},
                    defines);
    else
        p = program({{GL_VERTEX_SHADER, "ibfvs/polygon_advection.vert"}, {GL_FRAGMENT_SHADER, "ibfvs/polygon_advection.frag"}},
                    defines);
    return p;
}

void PolygonAdvection::apply(const SurfaceGpu& surface, const core::Camera& camera, const core::Camera& prevCamera,
                             const core::Viewport& viewport, float dt, const gl::Texture2D& prevFlow,
                             const gl::Texture2D& nextFlow, const gl::Framebuffer& nextFlowFbo,
                             const gl::Texture2D& depth, float flowBackground, bool cullBackFaces,
                             const NoiseStep& noise, ProcessGroup* occluders) {
    const Views views{camera.view(), camera.projection(viewport.aspect()) * camera.view(),
                      prevCamera.viewProjection(viewport.aspect()), dt};
    // Where this surface can be, and what the last one can have left (the buffers hold the
    // background elsewhere). Tiles (`occluders`): the clears cover just that; F_a is
    // written by advect() over the tile alone and keeps stale texels elsewhere, which nothing
    // reads: the history comes from the tiles' owners (ScreenTiles::pull), and the overlay
    // reads this piece's pixels, returned to it. Otherwise F_a is the next frame's history:
    // cleared and written whole.
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
    // Tiles: the draw writes the coordinates, each tile's owner advects after the merge.
    const bool deferred = occluders || path_ == GlPath::Compute;
    if (deferred) makeDeferred(viewport);
    const gl::Program& surfacePass = surfaceProgram(lastVisibility_, deferred);
    if (lastVisibility_) rasterizeVisibility(surface, views.viewProj, viewport, cullBackFaces, drawn, occluders, raster.cells);
    clearTarget(deferred ? texcoordFbo_ : nextFlowFbo, viewport, flowBackground, work);
    surfacePass.use();
    setViews(surfacePass, views);
    if (!deferred) {  // the fragments resample and inject
        noise_.bind(surfacePass, noise);
        glBindTextureUnit(bindings::kIbfvsPrevFlow, prevFlow.id());
    }
    if (lastVisibility_) resolveVisibility(surface, viewport, surfacePass);
    else draw(surface, cullBackFaces);
    if (deferred && !occluders) advect(prevFlow, nextFlow, depth, flowBackground, noise, work);
}

void PolygonAdvection::advect(const gl::Texture2D& prevFlow, const gl::Texture2D& nextFlow, const gl::Texture2D& depth,
                              float flowBackground, const NoiseStep& noise, const PixelRect& rect) {
    if (rect.empty()) return;
    advectProgram_.use();
    noise_.bind(advectProgram_, noise);
    glUniform1f(advectProgram_.uniform("uFlowBackground"), flowBackground);
    glBindTextureUnit(bindings::kIbfvsPrevFlow, prevFlow.id());
    glBindTextureUnit(bindings::kIbfvsTexcoord, texcoord_.id());
    glBindTextureUnit(bindings::kIbfvsDepth, depth.id());
    glBindImageTexture(bindings::kIbfvsNextFlow, nextFlow.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glUniform2i(advectProgram_.uniform("uOrigin"), rect.x0, rect.y0);
    glUniform2i(advectProgram_.uniform("uEnd"), rect.x1, rect.y1);
    dispatchPerPixel(rect.width(), rect.height());
}

PixelRect PolygonAdvection::readRegion(const gl::Texture2D& depth, const PixelRect& rect) {
    if (rect.empty()) return {};
    if (!boundsProgram_) {
        boundsProgram_ = program({{GL_COMPUTE_SHADER, "ibfvs/texcoord_bounds.comp"}},
                                 "#define BOUNDS_COLUMNS " + std::to_string(kBoundsColumns) + "\n#define BOUNDS_ROWS " +
                                     std::to_string(kBoundsRows) + "\n");
        bounds_ = gl::Buffer(4 * sizeof(GLint), nullptr);
    }
    constexpr GLint kNone[4] = {std::numeric_limits<GLint>::max(), std::numeric_limits<GLint>::max(),
                                -std::numeric_limits<GLint>::max(), -std::numeric_limits<GLint>::max()};
    glNamedBufferSubData(bounds_.id(), 0, sizeof kNone, kNone);
    boundsProgram_.use();
    glBindTextureUnit(bindings::kIbfvsTexcoord, texcoord_.id());
    glBindTextureUnit(bindings::kIbfvsDepth, depth.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kIbfvsBounds, bounds_.id());
    glUniform2i(boundsProgram_.uniform("uOrigin"), rect.x0, rect.y0);
    glUniform2i(boundsProgram_.uniform("uEnd"), rect.x1, rect.y1);
    glDispatchCompute(GLuint((rect.width() + kBoundsColumns - 1) / kBoundsColumns),
                      GLuint((rect.height() + kBoundsRows - 1) / kBoundsRows), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    GLint box[4];
    glGetNamedBufferSubData(bounds_.id(), 0, sizeof box, box);
    if (box[0] > box[2]) return {};
    // The bicubic's 4 x 4 texels around a coordinate (the bilinear's 2 x 2 within), and rounding.
    constexpr int kReach = 3;
    return PixelRect{box[0] - kReach, box[1] - kReach, box[2] + kReach + 1, box[3] + kReach + 1}.intersect(
        {0, 0, texcoord_.width(), texcoord_.height()});
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

void PolygonAdvection::resolveVisibility(const SurfaceGpu& surface, const core::Viewport& viewport,
                                         const gl::Program& resolve) const {
    if (footprint_.empty()) return;
    glUniform2i(resolve.uniform("uSize"), viewport.width, viewport.height);
    visibility_->drawResolve(surface, footprint_);  // the surface's pixels only
}

}  // namespace flowsurf::methods::ibfvs
