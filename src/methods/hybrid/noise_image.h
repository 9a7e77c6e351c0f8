// Hybrid noise image — the solid noise N(r, t) [W §5] sampled on the visible surface at
// twice the image resolution, each sample with its own octave mix (constant image-space
// frequency) (compute shader shaders/hybrid/noise_image.comp). Inputs: seed positions
// (RGBA32F), the solid noise volume. Output: R32F, 2W x 2H, bilinear. Cost: 4 samples x
// two trilinear 3D lookups per pixel, once per frame; the particles then read one 2D
// lookup per step instead of two 3D ones.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/common/surface_gbuffer.h"

namespace flowsurf::methods::hybrid {

class NoiseImage {
public:
    explicit NoiseImage(const core::Viewport& viewport);
    // noise: the solid noise volume (noiseSize^3); noiseScalePx: one noise texel spans
    // about half this many pixels; depthTolerance: a fraction of the depth range.
    void render(const SurfaceGBuffer& seeds, GLuint noise, int noiseSize, const core::Camera& camera,
                float noiseScalePx, float depthTolerance);
    const gl::Texture2D& texture() const { return image_; }

private:
    core::Viewport viewport_;
    gl::Texture2D image_;
    gl::Program program_;
};

}  // namespace flowsurf::methods::hybrid
