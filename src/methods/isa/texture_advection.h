// ISA stage 3 — texture advection [L §IV-D.1] with edge blending [L §IV-E.1]: draws the
// R x R grid textured with the previous F_a (R32F) at the advection mesh's coordinates
// into the next F_a target.
#pragma once

#include "gl/objects.h"

namespace flowsurf::methods::isa {

class TextureAdvection {
public:
    explicit TextureAdvection(int gridRes);
    void apply(const gl::Buffer& meshVertices, const gl::Texture2D& prevFlow, const gl::Framebuffer& nextFlow,
               bool edgeBlending, float gray) const;

private:
    int gridRes_;
    gl::Buffer indices_;
    gl::VertexArray vao_;
    gl::Program program_;
    GLsizei indexCount_ = 0;
};

}  // namespace flowsurf::methods::isa
