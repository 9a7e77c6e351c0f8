#include "methods/ibfvs/ibfvs_renderer.h"

#include "gpu/gpu_bindings.h"
#include "methods/stages.h"

namespace flowsurf::methods::ibfvs {

IbfvsRenderer::IbfvsRenderer(const MethodParams& params, const core::Viewport& viewport, ProcessGroup* group)
    : params_(params),
      viewport_(viewport),
      shade_(GL_RGBA16F, viewport.width, viewport.height, GL_NEAREST),
      mask_(GL_R16F, viewport.width, viewport.height, GL_NEAREST),
      depth_(GL_DEPTH_COMPONENT32F, viewport.width, viewport.height, GL_NEAREST),
      polygonAdvection_(viewport, params.common,
                        {{GL_COLOR_ATTACHMENT0 + outputs::kShade, &shade_}, {GL_COLOR_ATTACHMENT0 + outputs::kMask, &mask_}, {GL_DEPTH_ATTACHMENT, &depth_}}),
      work_(viewport, params.common, group, 2, 1),  // F_a ping-pong; the tile's depth
      tail_(params.common, viewport, work_),
      motion_(params.common.onCameraMove),
      flow_(viewport, {{GL_COLOR_ATTACHMENT0 + outputs::kShade, &shade_}, {GL_COLOR_ATTACHMENT0 + outputs::kMask, &mask_}, {GL_DEPTH_ATTACHMENT, &depth_}}),
      composite_(GL_RGBA8, viewport) {}

// Replicated: the whole surface's advected texture, shade and mask on every process; the
// texture is also the next frame's source (it lives in the image). Tiles: the whole
// surface's texture coordinates and depth over this tile, where (2)+(3) run per pixel.
void IbfvsRenderer::gatherDrawn(int target) {
    // The per-pixel pass reads the coordinates where the whole surface's depth is < 1 only:
    // this piece's own stand for the background, and the tile's merge goes into them
    // (nothing reads them after).
    const gl::Texture2D& texcoord = polygonAdvection_.texcoord();
    const TileLayer tileLayers[] = {TileLayer::of(texcoord, texcoord, 0.0f, true),
                                    TileLayer::of(depth_, work_.wholeDepth(0, depth_))};
    work_.gather(depth_, polygonAdvection_.footprint(), {&flow_.texture(target), &shade_, &mask_}, tileLayers, 0,
                 timer_);
}

// Tiles: the per-pixel pass on the tile from the part of the source F_a it reads (from the
// processes that made it); the tile's F_a is kept for the next frame's pulls and returned to
// the processes whose pieces cover its pixels. `drawMs`: what drawing this piece took, for
// the balance.
void IbfvsRenderer::advectTile(const NoiseStep& noise, int target, float drawMs) {
    timer_.begin(stageName(Stage::TextureAdvection));
    const PixelRect tile = work_.tile();
    const gl::Texture2D& depth = work_.wholeDepth(0, depth_);
    work_.pull(source_, flow_.texture(source_), polygonAdvection_.readRegion(depth, tile), timer_,
               Stage::TextureAdvection);
    const auto advected = ImageWork::Clock::now();
    polygonAdvection_.advect(flow_.texture(source_), flow_.texture(target), depth, params_.ibfvs.flowBackground, noise,
                             tile);
    work_.finished(advected, drawMs);
    work_.made(target);
    // (3b, tiles) the contrast histogram of this tile, summed over the processes
    tail_.measureTile(flow_.texture(target), depth, timer_);
    // F_a at this piece's own pixels (what its overlay shows) from their tiles' owners.
    work_.returnValues(flow_.texture(target), timer_);
}

void IbfvsRenderer::renderFrame(const FrameInput& in) {
    const CommonParams& c = params_.common;
    timer_.beginFrame();
    work_.beginFrame();
    // Static and dynamic cases run the same stages [L Table II: IBFVS cost ~ N in both].
    lastDynamic_ = in.surface->generation() != lastGeneration_ || !core::sameCamera(in.camera, lastCamera_);
    lastGeneration_ = in.surface->generation();
    lastCamera_ = in.camera;

    // Interaction remedy [L §IV-I]: which view the source texture was made in.
    const MotionPlan plan = motion_.plan(in.camera);
    if (plan.advect || plan.freezeStarts) source_ = current_;
    const int target = 1 - source_;
    const float dt = plan.advect ? dtForStep(in, viewport_, c.stepPx, work_.group()) : 0.0f;

    // (1)+(2) mesh projection t_i = T(x_i - v_i dt) and polygonal texture advection
    // into a gray background [L eq. 13, §IV-D.2, §IV-F.2], and (3) noise injection, in
    // the same draw: its fragments are exactly the surface [L eq. 9, §IV-G] (or the
    // visibility buffer's resolve, the same per pixel: CommonParams::surfaceRaster).
    // Tiles: the draw interpolates t, and (2)+(3) run per pixel on each tile, with the
    // draw's cost, which no split moves (ScreenTiles::reportCost).
    timer_.begin(stageName(Stage::TextureAdvection));
    const NoiseStep noise{in.frame, plan.advect ? c.alpha : 0.0f, c.noise};
    const auto drawn = ImageWork::Clock::now();
    polygonAdvection_.apply(*in.surface, in.camera, plan.sourceCamera, viewport_, dt, flow_.texture(source_),
                            flow_.texture(target), flow_.fbo(target), depth_, params_.ibfvs.flowBackground,
                            c.cullBackFaces, noise, work_.occluders());
    current_ = target;
    const float drawMs = work_.costSince(drawn);
    gatherDrawn(target);
    if (work_.tiled()) advectTile(noise, target, drawMs);

    // (3b) contrast enhancement, display only [doc/contrast.md]: the advection goes on
    // from F_a itself, and (4) overlay [L eq. 10]
    tail_.show(in, flow_.texture(current_), {depth_, shade_, mask_}, composite_.fbo(), timer_);

    // (5) optional silhouette edge mask, display only [L §IV-E.2]
    // In parallel every process takes part (an empty piece receives the others' outlines).
    ProcessGroup* group = work_.group();
    if (params_.ibfvs.edgeMask && (in.surface->hasEdges() || (group && group->size() > 1))) {
        timer_.begin(stageName(Stage::EdgeMask));
        edgeMask_.apply(*in.surface, in.camera, viewport_, depth_, composite_.fbo(),
                        {c.background, params_.ibfvs.edgeMaskOpacity, params_.ibfvs.edgeMaskWidthPx}, group);
    }
    timer_.endFrame();
}

}  // namespace flowsurf::methods::ibfvs
