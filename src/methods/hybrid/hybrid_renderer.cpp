#include "methods/hybrid/hybrid_renderer.h"

#include "core/errors.h"
#include "methods/common/gl_path.h"

#include <cmath>

namespace flowsurf::methods::hybrid {

HybridRenderer::HybridRenderer(const MethodParams& params, const core::Viewport& viewport)
    : params_(params),
      viewport_(viewport),
      seeds_(viewport, false, params.common.cullBackFaces, true, params.common.surfaceRaster),
      levels_(viewport, params.common.cullBackFaces),
      noise_(params.hybrid.noiseSize),
      tracing_(params.hybrid, resolveGlPath(params.common.glPath)),
      overlay_(params.common),
      lic_(GL_R32F, viewport),
      composite_(GL_RGBA8, viewport) {}

void HybridRenderer::renderFrame(const FrameInput& in) {
    const CommonParams& c = params_.common;
    timer_.beginFrame();

    // (1) seed textures: P-space velocity and layer depth per pixel (the seed position is
    // the surface point on the pixel ray at that depth) [W §4]; the static
    // case (same view, same data, same time levels) reuses them.
    const bool unsteady = in.levels && !in.levels->empty();
    if (unsteady && in.group)
        throw ConfigError("the hybrid method's unsteady time levels cannot be merged over processes yet; "
                    "render each time step as steady (no time levels) in a parallel render");
    lastDynamic_ = !haveSeeds_ || in.surface->generation() != seedGeneration_ ||
                   !core::sameCamera(in.camera, seedCamera_) || unsteady != haveLevels_ ||
                   (unsteady && !(*in.levels == seedLevels_));
    if (lastDynamic_) {
        timer_.begin("seed textures");
        seeds_.render(*in.surface, in.camera);
        if (in.group) seeds_.merge(*in.group);  // the whole surface's seeds
        haveSeeds_ = true;
        seedGeneration_ = in.surface->generation();
        seedCamera_ = in.camera;
    }
    // (1b) unsteady flow: the velocity image of every time level the particles pass
    // through, "the projection of the vector data within the integration loop" [W §3]
    const float speedRef = in.surface->maxSpeed();
    if (unsteady && lastDynamic_) {
        timer_.begin("velocity levels");
        levels_.render(*in.surface, *in.levels, in.camera, c, speedRef);
    }
    haveLevels_ = unsteady;
    if (unsteady) seedLevels_ = *in.levels;

    // (2) solid noise N(r, t) at this frame's phase [W §5]
    timer_.begin("solid noise");
    noise_.update(in.frame, c.noise);

    // (3) particle tracing and LIC accumulation, both halves [W eqs. 2, 3, 5]
    timer_.begin("particle tracing");
    TracingInput t;
    t.seeds = &seeds_;
    t.noise = noise_.texture();
    t.noiseSize = noise_.size();
    t.camera = in.camera;
    t.viewport = viewport_;
    t.stepPx = params_.hybrid.stepPx;
    t.lineField = in.surface->lineField();
    t.speedRef = speedRef;
    t.noiseScalePx = c.noise.scale;
    if (unsteady) {
        const TimeLevels& lv = *in.levels;
        t.velocityLevels = levels_.texture();
        for (const TimeLevel& l : lv.levels) t.levelTimes.push_back(float(l.time - lv.frameTime));
        t.timePerStep = float(std::abs(lv.timePerStep));
    }
    tracing_.apply(t, params_.hybrid, lic_);

    // (4) overlay / colour scheme [W §5, Fig. 6; L eq. 10]
    timer_.begin("overlay");
    overlay_.apply(lic_.texture(), seeds_.depth(), seeds_.shade(), seeds_.mask(), composite_.fbo(), *in.surface, in.dye);
    timer_.endFrame();
}

}  // namespace flowsurf::methods::hybrid
