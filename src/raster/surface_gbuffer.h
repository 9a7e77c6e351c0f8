// flowsurf — one render of the surface into per-pixel float buffers, shared by two paper
// stages: ISA's velocity image [L §IV-C.1] and the hybrid method's seed textures [W §4].
// Outputs: velocity RGBA32F (P-space, w = 1 on the surface; linear filtering, the D-space
// velocity texture of [W eq. 3]), shade RGBA16F (eye normal, colour value), mask R16F
// (texture mask value), depth DEPTH32F,
// and with `withPosition` the P-space position RGBA32F. Cost grows with the triangles N;
// the per-pixel work (clears, the visibility buffer's resolve) covers the surface's
// projected rectangle only (footprint), and the last frame's, for what it left there.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "gpu/gl_path.h"
#include "parallel/process_group.h"
#include "parallel/screen_split.h"
#include "raster/surface_gpu.h"
#include "raster/visibility_buffer.h"

#include <memory>
#include <string>

namespace flowsurf::methods {

// The velocity image's w on the surface: the visible layer's eye depth d mapped to
// 1 + (d - near) / (far - near) (the background stays 0), as dot(row, (p, 1)) for a P-space
// point p. Shared by every pass that writes or checks it; in [1, 2] it keeps 16-bit
// precision (~1e-3 of the depth range) whatever the scene's scale and distance, and a depth
// tolerance is a plain fraction of the range.
glm::vec4 layerDepthRow(const core::Camera& camera);

class SurfaceGBuffer {
public:
    // `clearBackground`: the velocity (and position) buffers are cleared to 0 off the
    // surface, for consumers that sample them there (the hybrid's bilinear lookups, its
    // coverage test); false: nothing is cleared, for consumers that read every buffer where
    // depth < 1 only (ISA). Shade and mask are never cleared: every consumer (overlay, merge,
    // ParaView's composite) reads them where depth < 1 only.
    // `raster`: who rasterises (params.h SurfaceRaster), decided per render from the
    // surface's triangle count (with `occluders`: for the whole group, VisibilityBuffer::agree).
    SurfaceGBuffer(const core::Viewport& viewport, bool withPosition, bool cullBackFaces = false,
                   bool clearBackground = true, SurfaceRaster raster = SurfaceRaster::Auto);
    // `occluders`: collective then, the group agrees on the rasteriser and, on the visibility
    // buffer, the other pieces hide this one's pixels behind them (VisibilityBuffer::
    // dropOccluded: every buffer holds the background there, as if those fragments had lost a
    // merge by depth already); null: this piece alone.
    void render(const SurfaceGpu& surface, const core::Camera& camera, ProcessGroup* occluders = nullptr);
    // Collective: every buffer merged by depth over `group` (process_group.h).
    void merge(ProcessGroup& group);
    // The pixels the last render can have drawn (its surface's projected bounds); outside
    // it the depth holds the background (1). The whole image after a merge.
    const PixelRect& footprint() const { return footprint_; }
    // Whether the velocity (and position) buffers hold 0 wherever no fragment was drawn.
    bool clearsBackground() const { return clearBackground_; }
    // Another stage wrote over `rect` of these buffers (ScreenTiles merging in place): the
    // next render clears it too, so that off its own fragments they hold the background again.
    void overwritten(const PixelRect& rect) { lastFootprint_ = lastFootprint_.united(rect); }

    const gl::Texture2D& velocity() const { return velocity_; }
    const gl::Texture2D& shade() const { return shade_; }
    const gl::Texture2D& mask() const { return mask_; }
    const gl::Texture2D& depth() const { return depth_; }
    const gl::Texture2D& position() const { return position_; }  // withPosition only

private:
    void renderVisibility(const SurfaceGpu& surface, const core::Camera& camera, const glm::mat4& viewProj,
                          const PixelRect& clear, ProcessGroup* occluders, const PixelRect& cells);
    // Binds the framebuffer; clears depth and what `clearBackground` says over `rect`.
    void bindAndClear(const PixelRect& rect);
    // This render's footprint, and what must be cleared: it and the last one's.
    PixelRect beginFootprint(const SurfaceGpu& surface, const glm::mat4& viewProj);

    core::Viewport viewport_;
    gl::Texture2D velocity_, shade_, mask_, depth_, position_;
    gl::Framebuffer fbo_;
    gl::Program program_;
    SurfaceRaster raster_;
    RendererInfo renderer_;  // for the auto rule of useComputeRaster
    std::unique_ptr<VisibilityBuffer> visibility_;  // made on first use
    gl::Program resolve_;                         // visibility buffer -> these buffers
    int targets_;
    bool cullBackFaces_;
    bool clearBackground_;
    PixelRect footprint_, lastFootprint_;  // lastFootprint_: the whole image until the first render
};

}  // namespace flowsurf::methods
