// flowsurf — hybrid physical/device-space advection with solid noise and LIC (Weiskopf
// & Ertl [W], doc/algorithms.md §7): the orchestrator. The texture is computed from 3D
// particle paths and object-fixed noise each frame, so it sticks to the surface when the
// camera moves and has no inflow at silhouettes.
#pragma once

#include "gpu/render_targets.h"
#include "methods/display_tail.h"
#include "methods/frame.h"
#include "methods/hybrid/particle_tracing.h"
#include "methods/hybrid/solid_noise.h"
#include "methods/hybrid/velocity_levels.h"
#include "methods/image_work.h"
#include "raster/surface_gbuffer.h"

#include <memory>

namespace flowsurf::methods::hybrid {

class HybridRenderer final : public FlowMethod {
public:
    // `group`: the processes rendering this view together, for the renderer's life (ImageWork).
    HybridRenderer(const MethodParams& params, const core::Viewport& viewport, ProcessGroup* group = nullptr);
    const char* name() const override { return nameOf(kMethodNames, Method::Hybrid).data(); }
    void renderFrame(const FrameInput& in) override;
    const gl::Texture2D& flowTexture() const override { return tail_.shown(lic_.texture()); }
    const gl::Texture2D& composite() const override { return composite_.texture(); }
    const gl::Texture2D& surfaceDepth() const override { return seeds_.depth(); }
    const gl::Texture2D& surfaceShade() const override { return seeds_.shade(); }
    bool lastFrameDynamic() const override { return lastDynamic_; }
    TileTraffic tileTraffic() const override { return work_.traffic(); }
    bool usesTimeLevels() const override { return true; }
    bool historyFree() const override { return true; }
    // For tests: the solid noise volume, N per texel (x fastest).
    std::vector<float> noiseValues() const { return noise_.values(); }

private:
    MethodParams params_;
    core::Viewport viewport_;
    SurfaceGBuffer seeds_;  // seed textures [W §4]: velocity (w: layer depth, gives the position), shade, depth
    VelocityLevels levels_;  // unsteady flow: the velocity image per time level [W §3]
    SolidNoise noise_;
    ParticleTracing tracing_;
    // Whole image, replicated or tiled over processes; tiles: the seeds' velocity image and
    // (unsteady) the time levels merged in place over this process's tile plus the streaks'
    // reach (guardPx), with contrast enhancement the whole surface's depth there in
    // ImageWork::wholeDepth 0.
    ImageWork work_;
    DisplayTail tail_;  // contrast, lightness, overlay with its layers
    ColorTarget lic_;              // I, R32F
    ColorTarget composite_;        // RGBA8
    bool haveSeeds_ = false, lastDynamic_ = false;
    uint64_t seedGeneration_ = 0;
    core::Camera seedCamera_;
    bool haveLevels_ = false;
    TimeLevels seedLevels_;  // the levels the seed and velocity-level textures hold
    int guardPx() const;
    // Stages of renderFrame (hybrid_renderer.cpp).
    void gatherSeeds(bool unsteady);
    void traceParticles(const FrameInput& in, bool unsteady, float speedRef);
};

}  // namespace flowsurf::methods::hybrid
