// flowsurf — noise injection and blending, [L] eq. 9 (shared by ISA and IBFVS):
// F_a <- (1 - gamma) F_a + gamma G with gamma = alpha on the surface, 0 elsewhere.
// Input: depth texture (coverage) and, for the swept variant, the image motion of the
// last advection (RG16F, pixels). Output: blended in place into the bound F_a target.
#pragma once

#include "core/noise.h"
#include "gl/objects.h"
#include "methods/common/params.h"

namespace flowsurf::methods {

class NoiseInjection {
public:
    explicit NoiseInjection(NoiseInjectionMode mode);
    // Blends G(.; frame) into `flowFbo` (R32F color 0) where `depth` < 1; the swept
    // variant averages G along `motion` (d' per pixel, the displacement of the last advection).
    void apply(const gl::Framebuffer& flowFbo, const gl::Texture2D& depth, const gl::Texture2D& motion,
               uint32_t frame, float alpha, const core::NoiseParams& noise) const;

private:
    gl::Program program_;
    gl::VertexArray emptyVao_;
};

}  // namespace flowsurf::methods
