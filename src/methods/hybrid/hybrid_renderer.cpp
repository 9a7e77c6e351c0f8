#include "methods/hybrid/hybrid_renderer.h"

#include "core/errors.h"
#include "gpu/gl_path.h"
#include "methods/stages.h"

#include <algorithm>
#include <cmath>

namespace flowsurf::methods::hybrid {

HybridRenderer::HybridRenderer(const MethodParams& params, const core::Viewport& viewport, ProcessGroup* group)
    : params_(params),
      viewport_(viewport),
      seeds_(viewport, false, params.common.cullBackFaces, true, params.common.surfaceRaster),
      levels_(viewport, params.common.cullBackFaces),
      noise_(params.hybrid.noiseSize, params.hybrid.oriented),
      tracing_(params.hybrid, resolveGlPath(params.common.glPath)),
      // I needs no history; the contrast histogram, the whole surface's depth.
      work_(viewport, params.common, group, 0, enhancesTexture(params.common.enhanceContrast) ? 1 : 0),
      tail_(params.common, viewport, work_),
      lic_(GL_R32F, viewport),
      composite_(GL_RGBA8, viewport) {}

void HybridRenderer::renderFrame(const FrameInput& in) {
    const CommonParams& c = params_.common;
    timer_.beginFrame();
    work_.beginFrame();

    // (1) seed textures: P-space velocity and layer depth per pixel (the seed position is
    // the surface point on the pixel ray at that depth) [W §4]; the static
    // case (same view, same data, same time levels) reuses them.
    const bool unsteady = in.levels && !in.levels->empty();
    if (unsteady && work_.mode() == ImageWork::Mode::Replicated)
        throw ConfigError("the hybrid method's unsteady time levels are merged over processes in the tiled mode only: "
                          "set parallel to tiles (FlowSurfParallel), or render each time step as steady");
    lastDynamic_ = !haveSeeds_ || in.surface->generation() != seedGeneration_ ||
                   !core::sameCamera(in.camera, seedCamera_) || unsteady != haveLevels_ ||
                   (unsteady && !(*in.levels == seedLevels_));
    if (params_.hybrid.oriented && in.surface->lineField())
        throw ConfigError("--oriented on: the field has no sign (a line field such as principal directions), so "
                          "its streaks have no direction to show; use --oriented off");
    const float speedRef = in.surface->maxSpeed();
    if (lastDynamic_) {
        timer_.begin(stageName(Stage::SeedTextures));
        seeds_.render(*in.surface, in.camera, work_.occluders());  // what other pieces hide, skipped
        // (1b) unsteady flow: the velocity image of every time level the particles pass
        // through, "the projection of the vector data within the integration loop" [W §3]
        if (unsteady) {
            timer_.begin(stageName(Stage::VelocityLevels));
            levels_.render(*in.surface, *in.levels, in.camera, c, speedRef);
        }
        haveSeeds_ = true;
        seedGeneration_ = in.surface->generation();
        seedCamera_ = in.camera;
    }
    if (lastDynamic_ || work_.splitDue()) gatherSeeds(unsteady);
    haveLevels_ = unsteady;
    if (unsteady) seedLevels_ = *in.levels;

    // (2) solid noise N(r, t) at this frame's phase [W §5]
    timer_.begin(stageName(Stage::SolidNoise));
    noise_.update(in.frame, c.noise);

    // (3) particle tracing and LIC accumulation, both halves [W eqs. 2, 3, 5]
    timer_.begin(stageName(Stage::ParticleTracing));
    traceParticles(in, unsteady, speedRef);

    // (3b) contrast enhancement [doc/contrast.md] and (4) overlay / colour scheme [W §5,
    // Fig. 6; L eq. 10]
    tail_.show(in, lic_.texture(), {seeds_.depth(), seeds_.shade(), seeds_.mask()}, composite_.fbo(), timer_);
    timer_.endFrame();
}

// The whole surface's seeds where this process traces: replicated, all of them on every
// process; tiles, the seeds (and time levels) over this process's tile and the streaks'
// reach, also when the measured costs call for a new split (a still camera). The seeds'
// depth decides every layer's nearest fragment. The velocity and the levels are merged in
// place: after the merge only the tracing reads them (the overlay reads this piece's depth,
// shade and mask); the next seed pass clears what the merge wrote off this piece.
void HybridRenderer::gatherSeeds(bool unsteady) {
    std::vector<TileLayer> tileLayers{
        TileLayer::of(seeds_.velocity(), seeds_.velocity(), 0.0f, seeds_.clearsBackground())};
    if (tail_.enhancesTexture())  // the contrast histogram counts the whole surface's pixels of the tile
        tileLayers.push_back(TileLayer::of(seeds_.depth(), work_.wholeDepth(0, seeds_.depth())));
    if (unsteady)
        for (int j = 0; j < levels_.count(); ++j)
            tileLayers.push_back(TileLayer::ofLayer(levels_.texture(), levels_.texture(), VelocityLevels::kFormat, j));
    work_.gather(seeds_, tileLayers, guardPx(), timer_);
}

// Stage (3) into lic_: over the whole image, or (tiles) over this process's tile, whose
// I then goes back to the processes whose fragments cover each pixel of it.
void HybridRenderer::traceParticles(const FrameInput& in, bool unsteady, float speedRef) {
    const CommonParams& c = params_.common;
    TracingInput t;
    t.seedVelocity = &seeds_.velocity();
    t.pixels = work_.tileOnly().value_or(PixelRect{});
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
    const auto traced = ImageWork::Clock::now();
    if (!work_.tile().empty()) tracing_.apply(t, params_.hybrid, lic_);
    // Tiles: the tile's cost (the return reads I back, so the wait costs nothing); (3b) the
    // contrast histogram of this tile, summed over the processes; then I back to the
    // processes whose fragments cover each pixel of the tile.
    work_.finished(traced);
    tail_.measureTile(lic_.texture(), work_.wholeDepth(0, seeds_.depth()), timer_);
    work_.returnValues(lic_.texture(), timer_);
}

// The farthest a streak reads from its seed, in pixels: half the filter length in steps of
// stepPx at the seed's distance (|v| <= the reference speed), with room for steps that
// lengthen on screen where the surface turns toward the eye or lies off the axis, and for
// the bilinear velocity lookup.
int HybridRenderer::guardPx() const {
    const int half = (std::max(1, params_.hybrid.filterLength) - 1) / 2;
    return int(std::ceil(1.5f * params_.hybrid.stepPx * float(half))) + 4;
}

}  // namespace flowsurf::methods::hybrid
