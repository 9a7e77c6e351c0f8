// flowsurf — noise injection and blending, [L] eq. 9 (shared by ISA and IBFVS):
// F_a <- (1 - gamma) F_a + gamma G with gamma = alpha on the surface, 0 elsewhere.
// Computed in each method's advection pass (shaders/image_space/noise_injection.glsl) right
// after the resampling of F_a: one pass over the R32F texture per frame instead of two.
// This file supplies the shader variant, the uniforms of G for one frame, and the
// per-cell random phases phi_ij as an R32F texture (our hash, computed once on the CPU:
// the same values as core::noiseCell, at a texture gather per sample instead of 12 hashes).
#pragma once

#include "core/camera.h"
#include "core/noise.h"
#include "gl/objects.h"
#include "params/params.h"

#include <string>

namespace flowsurf::methods {

// The noise of one frame: G(.; frame) blended with `alpha` (0: frozen, F_a unchanged).
struct NoiseStep {
    uint32_t frame = 0;
    float alpha = 0.0f;
    core::NoiseParams noise;
};

class NoiseInjection {
public:
    // Swept: one sample per noise cell of the largest step, 1..8.
    NoiseInjection(const CommonParams& params, const core::Viewport& viewport);
    // `#define`s for a program that includes image_space/noise_injection.glsl.
    std::string defines() const;
    // Sets the uniforms of image_space/noise_injection.glsl on the bound `program` and binds
    // the phase texture to unit 3 (rebuilt when the seed or the scale changes).
    void bind(const gl::Program& program, const NoiseStep& step) const;

private:
    NoiseInjectionMode mode_;
    int sweepSamples_;
    core::Viewport viewport_;
    mutable gl::Texture2D phases_;  // R32F, cell (i, j) at texel (i + kMargin, j + kMargin)
    mutable float phaseScale_ = 0.0f;
    mutable uint32_t phaseSeed_ = 0;
};

}  // namespace flowsurf::methods
