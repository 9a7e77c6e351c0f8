// ISA stages 3-4 — texture advection [L §IV-D.1] with edge blending [L §IV-E.1]: the
// previous F_a (R32F) resampled at the advection mesh's coordinates into the next F_a,
// then noise injection on the surface (depth < 1) [L eq. 9] in the same pass.
// Two variants of one stage: `Mesh` draws the R x R grid as in the paper (cost grows
// with M = R^2 triangles); `Pixel` interpolates the same mesh per pixel with the
// texture filter (cost grows with pixels only; equal up to bilinear-vs-triangle
// interpolation inside a cell), the paper's "per-pixel advection" future work.
// F_a itself is resampled bilinearly (as in [L]) or bicubically (image_space/resample.glsl).
// The pixel warp runs as a fragment or a compute pass (CommonParams::glPath, the same
// image); the mesh warp is a rasterisation of the grid and stays one.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/image_space/noise_injection.h"
#include "parallel/screen_tiles.h"
#include "params/params.h"

namespace flowsurf::methods::isa {

class TextureAdvection {
public:
    // `common`: the resampling, and the noise injection mode, scale and step.
    // `isa`: grid, warp and edge fill; `common`: resampling, noise injection, alpha.
    TextureAdvection(const core::Viewport& viewport, const IsaParams& isa, const CommonParams& common);
    // Off the surface (depth 1) the next F_a is the noise mean. `nextFlowFbo` has
    // `nextFlow` as its only colour attachment (the fragment path draws into it).
    // `pixels`: the pixels to write (a parallel render's tile); empty: all.
    void apply(const gl::Texture2D& mesh, const gl::Texture2D& prevFlow, const gl::Texture2D& surfaceDepth,
               const gl::Texture2D& nextFlow, const gl::Framebuffer& nextFlowFbo, bool edgeBlending,
               const NoiseStep& noise, const PixelRect& pixels = {}) const;

private:
    int gridRes_;
    IsaWarp warp_;
    GlPath path_;
    EdgeFill fill_;
    float fillAlpha_;
    NoiseInjection noise_;
    gl::Buffer indices_;
    gl::VertexArray vao_;
    gl::Program program_;
    GLsizei indexCount_ = 0;
};

}  // namespace flowsurf::methods::isa
