#include "methods/ibfvs/ibfvs_renderer.h"

#include "methods/common/gpu_bindings.h"
#include "methods/common/stages.h"

#include <cmath>

namespace flowsurf::methods::ibfvs {

IbfvsRenderer::IbfvsRenderer(const MethodParams& params, const core::Viewport& viewport)
    : params_(params),
      viewport_(viewport),
      shade_(GL_RGBA16F, viewport.width, viewport.height, GL_NEAREST),
      mask_(GL_R16F, viewport.width, viewport.height, GL_NEAREST),
      depth_(GL_DEPTH_COMPONENT32F, viewport.width, viewport.height, GL_NEAREST),
      polygonAdvection_(viewport, params.common,
                        {{GL_COLOR_ATTACHMENT0 + outputs::kShade, &shade_}, {GL_COLOR_ATTACHMENT0 + outputs::kMask, &mask_}, {GL_DEPTH_ATTACHMENT, &depth_}}),
      overlay_(params.common),
      contrast_(params.common, viewport),
      motion_(params.common.onCameraMove),
      flow_(viewport, {{GL_COLOR_ATTACHMENT0 + outputs::kShade, &shade_}, {GL_COLOR_ATTACHMENT0 + outputs::kMask, &mask_}, {GL_DEPTH_ATTACHMENT, &depth_}}),
      composite_(GL_RGBA8, viewport) {}

void IbfvsRenderer::pullSource(const FrameInput& in, const core::Camera& sourceCamera) {
    if (madeWith_[source_].empty()) return;
    // Tiles: the source texture where this piece's fragments read it, from the processes
    // that made it: the piece seen from the source view, plus the step (at most stepPx on
    // screen), twice for safety, and the bicubic's reach.
    timer_.begin(stageName(Stage::TileExchange));
    const int margin = int(std::ceil(2.0f * params_.common.stepPx)) + 3;
    const PixelRect wanted = projectedRect(in.surface->pieceParts(), sourceCamera.viewProjection(viewport_.aspect()),
                                           viewport_.width, viewport_.height)
                                 .grown(margin)
                                 .intersect({0, 0, viewport_.width, viewport_.height});
    tiles_->pull(*in.group, flow_.texture(source_), madeWith_[source_], wanted);
}

void IbfvsRenderer::renderFrame(const FrameInput& in) {
    const CommonParams& c = params_.common;
    timer_.beginFrame();
    if (tiledParallel(in, params_.common) && !tiles_) tiles_ = std::make_unique<ScreenTiles>(viewport_);
    if (tiles_) tiles_->beginFrame();
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
    const bool tiled = tiledParallel(in, c);
    if (tiled) pullSource(in, plan.sourceCamera);

    // (1)+(2) mesh projection t_i = T(x_i - v_i dt) and polygonal texture advection
    // into a gray background [L eq. 13, §IV-D.2, §IV-F.2], and (3) noise injection, in
    // the same draw: its fragments are exactly the surface [L eq. 9, §IV-G] (or the
    // visibility buffer's resolve, the same per pixel: CommonParams::surfaceRaster)
    timer_.begin(stageName(Stage::TextureAdvection));
    const NoiseStep noise{in.frame, plan.advect ? c.alpha : 0.0f, c.noise};
    polygonAdvection_.apply(*in.surface, in.camera, plan.sourceCamera, viewport_, dt, flow_.texture(source_),
                            flow_.texture(target), flow_.fbo(target), depth_, params_.ibfvs.flowBackground,
                            c.cullBackFaces, noise, tiled ? in.group : nullptr);
    current_ = target;
    // Parallel: the whole surface's advected texture on every process, which is also the
    // next frame's source (the texture lives in the image). Tiles: each process merges its
    // tile by depth, then every tile goes to every process; shade, mask and depth stay
    // this piece's (its own fragments are what it composites).
    if (tiled) {
        // Each tile's F_a merged by depth; the owners keep it for the next frame's pulls.
        timer_.begin(stageName(Stage::TileExchange));
        const gl::Texture2D& fa = flow_.texture(target);
        std::vector<TileLayer> layers{TileLayer::of(fa, fa, params_.ibfvs.flowBackground)};
        if (contrast_.enabled()) {  // the contrast histogram counts the whole surface's pixels of the tile
            if (!tileDepth_) tileDepth_ = gl::Texture2D(GL_DEPTH_COMPONENT32F, viewport_.width, viewport_.height, GL_NEAREST);
            layers.push_back(TileLayer::of(depth_, tileDepth_));
        }
        tiles_->distribute(*in.group, depth_, layers, 0, polygonAdvection_.footprint());
        madeWith_[target] = tiles_->tiles();
        // (3b, tiles) the contrast histogram of this tile, summed over the processes
        if (contrast_.enabled()) {
            timer_.begin(stageName(Stage::ContrastTexture));
            contrast_.measure(fa, tileDepth_, tiles_->tile(), in.group);
        }
    } else if (in.group) {
        mergeByDepth(*in.group, depth_, {&flow_.texture(target), &shade_, &mask_});
    }

    // (3b) contrast enhancement, display only: F_a stretched between its robust
    // percentiles [issue 28]; the advection goes on from F_a itself
    if (contrast_.enabled()) timer_.begin(stageName(Stage::ContrastTexture));
    if (!tiled) contrast_.measure(flow_.texture(current_), depth_);
    shown_ = &contrast_.stretch(flow_.texture(current_), depth_);
    if (overlay_.stretchesColor()) {
        timer_.begin(stageName(Stage::ContrastColour));
        overlay_.measureLightness(*shown_, depth_, shade_, mask_);
    }

    // (4) overlay [L eq. 10]
    timer_.begin(stageName(Stage::Overlay));
    overlay_.apply(*shown_, depth_, shade_, mask_, composite_.fbo(), *in.surface, in.dye,
                   piecePixels(in, c, viewport_));

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
