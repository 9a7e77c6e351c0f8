// ISA stage 3 — texture advection [L §IV-D.1] with edge blending [L §IV-E.1]: the
// previous F_a (R32F) resampled at the advection mesh's coordinates into the next F_a.
// Two variants of one stage: `Mesh` draws the R x R grid as in the paper (cost grows
// with M = R^2 triangles); `Pixel` interpolates the same mesh per pixel with the
// texture filter (cost grows with pixels only; equal up to bilinear-vs-triangle
// interpolation inside a cell), the paper's "per-pixel advection" future work.
// F_a itself is resampled bilinearly (as in [L]) or bicubically (common/resample.glsl).
#pragma once

#include "gl/objects.h"
#include "methods/common/params.h"

namespace flowsurf::methods::isa {

class TextureAdvection {
public:
    TextureAdvection(int gridRes, IsaWarp warp, Resample resample);
    void apply(const gl::Texture2D& mesh, const gl::Texture2D& prevFlow, const gl::Framebuffer& nextFlow,
               bool edgeBlending, float gray) const;

private:
    int gridRes_;
    IsaWarp warp_;
    gl::Buffer indices_;
    gl::VertexArray vao_;
    gl::Program program_;
    GLsizei indexCount_ = 0;
};

}  // namespace flowsurf::methods::isa
