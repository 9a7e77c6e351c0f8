// flowsurf — overlay, [L] eq. 10, with texture clipping ([L] Fig. 10) and the velocity
// mask. Inputs: F_a (R32F), depth, shade (RGBA16F: eye normal, speed). Output: RGBA8.
// Applied after advection every frame and never fed back.
#pragma once

#include "gl/objects.h"
#include "methods/common/params.h"

namespace flowsurf::methods {

class Overlay {
public:
    explicit Overlay(const CommonParams& params);
    void apply(const gl::Texture2D& flow, const gl::Texture2D& depth, const gl::Texture2D& shade,
               const gl::Framebuffer& target, float speedMax) const;

private:
    CommonParams params_;
    gl::Program program_;
    gl::Texture2D colormap_;
    gl::VertexArray emptyVao_;
};

}  // namespace flowsurf::methods
