// flowsurf — noise injection and blending, [L] eq. 9 (shared by ISA and IBFVS):
// F_a <- (1 - gamma) F_a + gamma G with gamma = alpha on the surface, 0 elsewhere.
// Input: depth texture (coverage). Output: blended in place into the bound F_a target.
#pragma once

#include "core/noise.h"
#include "gl/objects.h"

namespace flowsurf::methods {

class NoiseInjection {
public:
    NoiseInjection();
    // Blends G(.; frame) into `flowFbo` (R32F color 0) where `depth` < 1.
    void apply(const gl::Framebuffer& flowFbo, const gl::Texture2D& depth, uint32_t frame,
               float alpha, const core::NoiseParams& noise) const;

private:
    gl::Program program_;
    gl::VertexArray emptyVao_;
};

}  // namespace flowsurf::methods
