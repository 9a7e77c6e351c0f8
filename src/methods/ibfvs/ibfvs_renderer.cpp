#include "methods/ibfvs/ibfvs_renderer.h"

#include "gpu/gpu_bindings.h"
#include "methods/stages.h"

namespace flowsurf::methods::ibfvs {

IbfvsRenderer::IbfvsRenderer(const MethodParams& params, const core::Viewport& viewport)
    : params_(params),
      viewport_(viewport),
      shade_(GL_RGBA16F, viewport.width, viewport.height, GL_NEAREST),
      mask_(GL_R16F, viewport.width, viewport.height, GL_NEAREST),
      depth_(GL_DEPTH_COMPONENT32F, viewport.width, viewport.height, GL_NEAREST),
      polygonAdvection_(viewport, params.common,
                        {{GL_COLOR_ATTACHMENT0 + outputs::kShade, &shade_}, {GL_COLOR_ATTACHMENT0 + outputs::kMask, &mask_}, {GL_DEPTH_ATTACHMENT, &depth_}}),
      tail_(params.common, viewport),
      motion_(params.common.onCameraMove),
      flow_(viewport, {{GL_COLOR_ATTACHMENT0 + outputs::kShade, &shade_}, {GL_COLOR_ATTACHMENT0 + outputs::kMask, &mask_}, {GL_DEPTH_ATTACHMENT, &depth_}}),
      composite_(GL_RGBA8, viewport),
      work_(viewport, params.common, 2) {}  // F_a ping-pong

// Tiles: after every process drew its piece's texture coordinates, the whole surface's
// coordinates and depth over this tile, then the per-pixel pass on the tile from the part of
// the source F_a it reads (from the processes that made it); the tile's F_a is kept for the
// next frame's pulls and returned to the processes whose pieces cover its pixels. `drawMs`:
// what drawing this piece took, for the balance.
void IbfvsRenderer::advectTile(const FrameInput& in, const NoiseStep& noise, int target, float drawMs) {
    if (!tileDepth_) tileDepth_ = gl::Texture2D(GL_DEPTH_COMPONENT32F, viewport_.width, viewport_.height, GL_NEAREST);
    // The pass reads the coordinates where the merged depth is < 1 only: this piece's own
    // stand for the background, and the merge goes into them (nothing reads them after).
    const gl::Texture2D& texcoord = polygonAdvection_.texcoord();
    const TileLayer layers[] = {TileLayer::of(texcoord, texcoord, 0.0f, true), TileLayer::of(depth_, tileDepth_)};
    work_.distribute(depth_, layers, 0, polygonAdvection_.footprint(), timer_);

    timer_.begin(stageName(Stage::TextureAdvection));
    const PixelRect tile = work_.tile();
    work_.pull(source_, flow_.texture(source_), polygonAdvection_.readRegion(tileDepth_, tile), timer_,
               Stage::TextureAdvection);
    const auto advected = ScreenTiles::Clock::now();
    polygonAdvection_.advect(flow_.texture(source_), flow_.texture(target), tileDepth_, params_.ibfvs.flowBackground,
                             noise, tile);
    work_.reportCost(ScreenTiles::finishedMs(advected), drawMs);
    work_.made(target);
    // (3b, tiles) the contrast histogram of this tile, summed over the processes
    tail_.measureTile(flow_.texture(target), tileDepth_, tile, *in.group, timer_);
    // F_a at this piece's own pixels (what its overlay shows) from their tiles' owners.
    work_.returnValues(flow_.texture(target), timer_);
}

void IbfvsRenderer::renderFrame(const FrameInput& in) {
    const CommonParams& c = params_.common;
    timer_.beginFrame();
    work_.beginFrame(in);
    checkContrastParallel(in, c);
    // Static and dynamic cases run the same stages [L Table II: IBFVS cost ~ N in both].
    lastDynamic_ = in.surface->generation() != lastGeneration_ || !core::sameCamera(in.camera, lastCamera_);
    lastGeneration_ = in.surface->generation();
    lastCamera_ = in.camera;

    // Interaction remedy [L §IV-I]: which view the source texture was made in.
    const MotionPlan plan = motion_.plan(in.camera);
    if (plan.advect || plan.freezeStarts) source_ = current_;
    const int target = 1 - source_;
    const float dt = plan.advect ? dtForStep(in, viewport_, c.stepPx) : 0.0f;

    // (1)+(2) mesh projection t_i = T(x_i - v_i dt) and polygonal texture advection
    // into a gray background [L eq. 13, §IV-D.2, §IV-F.2], and (3) noise injection, in
    // the same draw: its fragments are exactly the surface [L eq. 9, §IV-G] (or the
    // visibility buffer's resolve, the same per pixel: CommonParams::surfaceRaster).
    // Tiles: the draw interpolates t, and (2)+(3) run per pixel on each tile.
    timer_.begin(stageName(Stage::TextureAdvection));
    const NoiseStep noise{in.frame, plan.advect ? c.alpha : 0.0f, c.noise};
    const auto drawn = ScreenTiles::Clock::now();
    polygonAdvection_.apply(*in.surface, in.camera, plan.sourceCamera, viewport_, dt, flow_.texture(source_),
                            flow_.texture(target), flow_.fbo(target), depth_, params_.ibfvs.flowBackground,
                            c.cullBackFaces, noise, work_.tiledGroup());
    current_ = target;
    // Parallel, replicated: the whole surface's advected texture on every process, which is
    // also the next frame's source (the texture lives in the image).
    // Tiles: with the draw's cost, which no split moves (ScreenTiles::reportCost).
    if (work_.tiled()) advectTile(in, noise, target, ScreenTiles::finishedMs(drawn));
    else work_.mergeReplicated(depth_, {&flow_.texture(target), &shade_, &mask_});

    // (3b) contrast enhancement, display only [doc/contrast.md]: the advection goes on
    // from F_a itself, and (4) overlay [L eq. 10]
    tail_.show(in, flow_.texture(current_), {depth_, shade_, mask_}, composite_.fbo(), timer_);

    // (5) optional silhouette edge mask, display only [L §IV-E.2]
    // In parallel every process takes part (an empty piece receives the others' outlines).
    if (params_.ibfvs.edgeMask && (in.surface->hasEdges() || (in.group && in.group->size() > 1))) {
        timer_.begin(stageName(Stage::EdgeMask));
        edgeMask_.apply(*in.surface, in.camera, viewport_, depth_, composite_.fbo(),
                        {c.background, params_.ibfvs.edgeMaskOpacity, params_.ibfvs.edgeMaskWidthPx}, in.group);
    }
    timer_.endFrame();
}

}  // namespace flowsurf::methods::ibfvs
