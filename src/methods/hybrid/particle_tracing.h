// Hybrid steps 2-5 — particle tracing in P-space with D-space velocity lookups and LIC
// accumulation with the chosen kernel [W §3-5, eqs. 2, 3, 5] (shaders/hybrid/
// particle_tracing.glsl: one pass with a per-pixel loop, as a fragment or a compute
// shader, GlPath). Inputs: seed textures, solid noise. Output: the LIC result I (R32F);
// the noise mean on the background. Cost: pixels x L x (one velocity lookup and two noise
// lookups of two texel fetches each).
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "gpu/render_targets.h"
#include "parallel/screen_tiles.h"
#include "params/params.h"
#include "raster/surface_gbuffer.h"

#include <string>
#include <vector>

namespace flowsurf::methods::hybrid {

struct TracingInput {
    // The seeds' velocity image (SurfaceGBuffer::velocity, or its merge over a screen tile):
    // the seed positions come from its layer depth.
    const gl::Texture2D* seedVelocity = nullptr;
    // The pixels to trace (a parallel render's tile); empty: the whole viewport. Pixels
    // outside keep what the target held.
    PixelRect pixels;
    GLuint noise = 0;          // 3D texture
    int noiseSize = 64;
    core::Camera camera;
    core::Viewport viewport;
    float stepPx = 2.0f;       // arc length per step in pixels at the seed's distance
    float speedRef = 1.0f;     // speed that moves stepPx per step
    float noiseScalePx = 2.0f; // one noise texel ~ this many pixels
    // Unsteady flow [W §3]: velocity per time level (3D texture, layer j at data time
    // levelTimes[j] relative to the frame's, velocities divided by speedRef); 0: the seeds'
    // velocity image.
    GLuint velocityLevels = 0;
    std::vector<float> levelTimes;  // increasing, at most TimeLevelSource::kMaxLevels
    float timePerStep = 0.0f;       // data time a forward step advances
    bool lineField = false;         // vectors without sign: orient each step to the previous
};

class ParticleTracing {
public:
    // Compiles the variant for params.kernel and params.integrator as a compute shader
    // (path Compute) or a fragment shader (Fragment; Auto is resolved by the caller).
    ParticleTracing(const HybridParams& params, GlPath path);
    void apply(const TracingInput& in, const HybridParams& params, const ColorTarget& target);
    bool compute() const { return compute_; }

private:
    // The program for steady/unsteady flow and signed vectors/line fields, compiled on
    // first use.
    const gl::Program& programFor(bool unsteady, bool lineField);
    void setUniforms(const gl::Program& program, const TracingInput& in, const HybridParams& params) const;

    bool compute_;
    std::string defines_;
    gl::Program programs_[2][2];  // [unsteady][lineField]
    gl::VertexArray emptyVao_;
};

}  // namespace flowsurf::methods::hybrid
