// IBFVS stages 1-3 — object-space mesh projection [L eq. 13] (in the vertex shader,
// shaders/ibfvs/mesh_projection.glsl), polygonal texture advection [L §IV-D.2] and noise
// injection [L eq. 9] (shaders/ibfvs/polygon_advection.*): one draw of the surface mesh
// into the next F_a (R32F), sampling the previous F_a; also writes shade (RGBA16F) and
// depth. Cost grows with the triangles N, in the static and the dynamic case alike. F_a
// is resampled bilinearly (as in [L]) or bicubically (shaders/image_space/resample.glsl).
// Compute path (CommonParams::glPath): the draw stays a rasterisation of the surface (any
// triangles, depth-tested) but only interpolates the texture coordinate (RG32F); a compute
// pass then resamples and injects per pixel: the same image, the arithmetic off the
// fragment stage, at the cost of one RG32F write and read.
// Compute raster (CommonParams::surfaceRaster, the rule of SurfaceGBuffer): the draw is
// replaced by the visibility buffer and a resolve (ibfvs/polygon_resolve.frag) that writes
// the same outputs per pixel from each pixel's nearest triangle; either path above follows.
// Tiles (CommonParams::parallel): the draw is the compute path's, on either GL path; after
// the group merges the coordinates by depth, each tile's owner runs the per-pixel pass on
// its tile alone (advect()), so the image work divides by the tiles, not by the pieces.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "gpu/gl_path.h"
#include "gpu/render_targets.h"
#include "methods/image_space/noise_injection.h"
#include "parallel/screen_split.h"
#include "params/params.h"
#include "raster/surface_gpu.h"
#include "raster/visibility_buffer.h"

#include <memory>
#include <string>
#include <vector>

namespace flowsurf::methods::ibfvs {

class PolygonAdvection {
public:
    // `common`: the resampling, the noise injection mode, scale and step, the GL path, the
    // surface raster.
    // `shared`: what the draw writes besides F_a (shade, mask, depth; as FlowPingPong's).
    PolygonAdvection(const core::Viewport& viewport, const CommonParams& common,
                     std::initializer_list<FlowPingPong::Attachment> shared);
    // `prevCamera` projects the pathline points into the previous F_a. `nextFlowFbo`:
    // `nextFlow` at colour attachment 0 with the shared attachments; `depth` the shared depth.
    // `occluders`: collective then, the group agrees on the rasteriser and this piece's
    // pixels that the group's other pieces hide are skipped (SurfaceGBuffer::render's);
    // the draw writes the texture coordinate (texcoord()), not F_a: advect() follows.
    void apply(const SurfaceGpu& surface, const core::Camera& camera, const core::Camera& prevCamera,
               const core::Viewport& viewport, float dt, const gl::Texture2D& prevFlow,
               const gl::Texture2D& nextFlow, const gl::Framebuffer& nextFlowFbo, const gl::Texture2D& depth,
               float flowBackground, bool cullBackFaces, const NoiseStep& noise, ProcessGroup* occluders = nullptr);
    // Tiles: the coordinates the last apply drew (RG32F), for the group's merge.
    const gl::Texture2D& texcoord() const { return texcoord_; }
    // Tiles: the texels of the previous F_a that the surface's pixels of `rect` read, after
    // the merge (`texcoord()` and `depth` the whole surface's there), the resampling's reach
    // included, within the image; empty where no pixel is on the surface.
    PixelRect readRegion(const gl::Texture2D& depth, const PixelRect& rect);
    // Tiles: the per-pixel pass over `rect` from the merged `texcoord()` and `depth`:
    // `nextFlow` there from `prevFlow` with the noise, the gray background off the surface.
    void advect(const gl::Texture2D& prevFlow, const gl::Texture2D& nextFlow, const gl::Texture2D& depth,
                float flowBackground, const NoiseStep& noise, const PixelRect& rect);
    // Whether the last apply rasterised with the visibility buffer.
    bool lastUsedVisibility() const { return lastVisibility_; }
    // The pixels the last apply's surface can cover; its depth is 1 outside them.
    const PixelRect& footprint() const { return footprint_; }

private:
    struct Views {
        glm::mat4 view, viewProj, prevViewProj;
        float dt;
    };
    // Clears `target` (F_a to the gray background, shade, mask, depth) over `rect` and binds it.
    static void clearTarget(const gl::Framebuffer& target, const core::Viewport& viewport, float flowBackground,
                            const PixelRect& rect);
    static void setViews(const gl::Program& program, const Views& views);
    void draw(const SurfaceGpu& surface, bool cullBackFaces) const;
    void rasterizeVisibility(const SurfaceGpu& surface, const glm::mat4& viewProj, const core::Viewport& viewport,
                             bool cullBackFaces, const PixelRect& clear, ProcessGroup* occluders,
                             const PixelRect& cells);
    // Over the bound target, from the visibility buffer, with `resolve` in use.
    void resolveVisibility(const SurfaceGpu& surface, const core::Viewport& viewport, const gl::Program& resolve) const;
    // The surface program of this apply: the draw's, or the resolve's; writing F_a, or the
    // texture coordinate (`deferred`). Made on first use.
    const gl::Program& surfaceProgram(bool visibility, bool deferred);
    // The compute path's texture coordinates, their framebuffer and the per-pixel pass.
    void makeDeferred(const core::Viewport& viewport);

    NoiseInjection noise_;
    GlPath path_;
    std::string defines_;                      // the resampling and the noise
    gl::Program draw_[2], resolve_[2];         // [deferred]
    gl::Program advectProgram_;                // compute path and tiles: the per-pixel pass
    gl::Texture2D texcoord_;                   // RG32F, the draw's texture coordinates
    gl::Framebuffer texcoordFbo_;
    std::vector<FlowPingPong::Attachment> shared_;
    gl::Program boundsProgram_;  // tiles: readRegion's pass and its four integers
    gl::Buffer bounds_;
    // Compute raster: made on first use.
    SurfaceRaster raster_;
    RendererInfo renderer_;  // for the auto rule of useComputeRaster
    std::unique_ptr<VisibilityBuffer> visibility_;
    PixelRect footprint_;      // the pixels this apply's surface can cover
    PixelRect lastFootprint_;  // where the last one can have left fragments (in every buffer)
    bool lastVisibility_ = false;
};

}  // namespace flowsurf::methods::ibfvs
