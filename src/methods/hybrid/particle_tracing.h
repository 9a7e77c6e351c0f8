// Hybrid steps 2-5 — particle tracing in P-space with D-space velocity lookups and LIC
// accumulation with the chosen kernel [W §3-5, eqs. 2, 3, 5] (shaders/hybrid/
// particle_tracing.frag, one pass with a per-pixel loop). Inputs: seed textures, solid
// noise. Output: the LIC result I (R32F) on the surface pixels.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/common/params.h"
#include "methods/common/surface_gbuffer.h"

namespace flowsurf::methods::hybrid {

struct TracingInput {
    const SurfaceGBuffer* seeds = nullptr;  // with positions
    GLuint noise = 0;          // 3D texture
    int noiseSize = 64;
    core::Camera camera;
    core::Viewport viewport;
    float stepPx = 2.0f;       // arc length per step in pixels at the seed's distance
    float speedRef = 1.0f;     // speed that moves stepPx per step
    float noiseScalePx = 2.0f; // one noise texel ~ this many pixels
};

class ParticleTracing {
public:
    ParticleTracing();
    void apply(const TracingInput& in, const HybridParams& params, const gl::Framebuffer& target) const;

private:
    gl::Program program_;
    gl::VertexArray emptyVao_;
};

}  // namespace flowsurf::methods::hybrid
