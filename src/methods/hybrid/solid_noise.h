// Hybrid solid noise N(r, t) [W §5] — a wrapped R32F 3D texture (64^3 or 128^3), refreshed
// per frame on the GPU from per-texel random phases and the periodic profile (compute
// shader shaders/hybrid/solid_noise.comp), sampled with trilinear filtering.
#pragma once

#include "core/noise.h"
#include "gl/objects.h"

namespace flowsurf::methods::hybrid {

class SolidNoise {
public:
    explicit SolidNoise(int size);
    // Recomputes the volume for frame k (skipped if k is unchanged).
    void update(uint32_t frame, const core::NoiseParams& params);
    GLuint texture() const { return texture_.id(); }
    int size() const { return size_; }

private:
    int size_;
    gl::Handle<gl::detail::deleteTexture> texture_;
    gl::Program program_;
    bool valid_ = false;
    uint32_t frame_ = 0;
};

}  // namespace flowsurf::methods::hybrid
