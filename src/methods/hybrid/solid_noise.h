// Hybrid solid noise N(r, t) [W §5] — a wrapped 3D texture (64^3 or 128^3) refreshed per
// frame on the GPU from per-texel random phases and the periodic profile (compute shader
// shaders/hybrid/solid_noise.comp). Each texel holds 8-bit codes of N over a 2 x 2
// neighbourhood in x and y, so that the particle tracing's trilinear lookup fetches two
// texels instead of eight; the paper found 8-bit noise adequate. Cost: size^3 texels per
// frame. Oriented LIC takes a sparse variant: rare drops on a dark ground.
#pragma once

#include "core/noise.h"
#include "gl/objects.h"

#include <string>
#include <vector>

namespace flowsurf::methods::hybrid {

class SolidNoise {
public:
    // The code of a value N: 0.5 + kCode (N - 0.5). The blurred square profile reaches
    // 0.5 +- 1.09, so every value stays inside [0, 1].
    static constexpr float kCode = 0.45f;
    // NOISE_SIZE and NOISE_CODE for the shaders that write or read the texture.
    static std::string defines(int size);

    // Sparse noise for oriented LIC: this fraction of the texels are drops at a time (a
    // dense texel is lit half the time). Drops are spaced so that the streaks of the
    // default filter length cover about a third of the surface.
    static constexpr float kSparseDensity = 0.0024f;

    // sparse: drops on a dark ground (oriented LIC), coded as N itself instead.
    SolidNoise(int size, bool sparse);
    // Recomputes the volume for frame k (skipped if k is unchanged).
    void update(uint32_t frame, const core::NoiseParams& params);
    // RGBA8, texel (x, y, z): codes of N at (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)
    // at depth z, wrapped.
    GLuint texture() const { return texture_.id(); }
    int size() const { return size_; }
    // N per texel, x fastest, decoded from the texture (read back: for inspection).
    std::vector<float> values() const;

private:
    int size_;
    bool sparse_;
    gl::Handle<gl::detail::deleteTexture> texture_;
    gl::Program program_;
    bool valid_ = false;
    uint32_t frame_ = 0;
};

}  // namespace flowsurf::methods::hybrid
