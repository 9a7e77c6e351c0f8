#include "methods/ibfvs/ibfvs_renderer.h"

#include <cmath>

namespace flowsurf::methods::ibfvs {

IbfvsRenderer::IbfvsRenderer(const MethodParams& params, const core::Viewport& viewport)
    : params_(params),
      viewport_(viewport),
      shade_(GL_RGBA16F, viewport.width, viewport.height, GL_NEAREST),
      mask_(GL_R16F, viewport.width, viewport.height, GL_NEAREST),
      depth_(GL_DEPTH_COMPONENT32F, viewport.width, viewport.height, GL_NEAREST),
      polygonAdvection_(viewport, params.common,
                        {{GL_COLOR_ATTACHMENT1, &shade_}, {GL_COLOR_ATTACHMENT2, &mask_}, {GL_DEPTH_ATTACHMENT, &depth_}}),
      overlay_(params.common),
      contrast_(params.common, viewport),
      motion_(params.common.onCameraMove),
      flow_(viewport, {{GL_COLOR_ATTACHMENT1, &shade_}, {GL_COLOR_ATTACHMENT2, &mask_}, {GL_DEPTH_ATTACHMENT, &depth_}}),
      composite_(GL_RGBA8, viewport) {}

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
    if (tiled && !madeWith_[source_].empty()) {
        // Tiles: the source texture where this piece's fragments read it, from the processes
        // that made it: the piece seen from the source view, plus the step (at most stepPx
        // on screen), twice for safety, and the bicubic's reach.
        timer_.begin("tile exchange");
        const int margin = int(std::ceil(2.0f * c.stepPx)) + 3;
        const PixelRect wanted =
            projectedRect(in.surface->pieceBounds(), plan.sourceCamera.viewProjection(viewport_.aspect()), viewport_.width,
                          viewport_.height)
                .grown(margin)
                .intersect({0, 0, viewport_.width, viewport_.height});
        tiles_->pull(*in.group, flow_.texture(source_), madeWith_[source_], wanted);
    }

    // (1)+(2) mesh projection t_i = T(x_i - v_i dt) and polygonal texture advection
    // into a gray background [L eq. 13, §IV-D.2, §IV-F.2], and (3) noise injection, in
    // the same draw: its fragments are exactly the surface [L eq. 9, §IV-G]
    timer_.begin("texture advection");
    const NoiseStep noise{in.frame, plan.advect ? c.alpha : 0.0f, c.noise};
    polygonAdvection_.apply(*in.surface, in.camera, plan.sourceCamera, viewport_, dt, flow_.texture(source_),
                            flow_.texture(target), flow_.fbo(target), depth_, params_.ibfvs.flowBackground,
                            c.cullBackFaces, noise);
    current_ = target;
    // Parallel: the whole surface's advected texture on every process, which is also the
    // next frame's source (the texture lives in the image). Tiles: each process merges its
    // tile by depth, then every tile goes to every process; shade, mask and depth stay
    // this piece's (its own fragments are what it composites).
    if (tiled) {
        // Each tile's F_a merged by depth; the owners keep it for the next frame's pulls.
        timer_.begin("tile exchange");
        const gl::Texture2D& fa = flow_.texture(target);
        const TileLayer layers[] = {TileLayer::of(fa, fa, params_.ibfvs.flowBackground)};
        tiles_->distribute(*in.group, depth_, layers, 0, {0, 0, viewport_.width, viewport_.height});
        madeWith_[target] = tiles_->tiles();
    } else if (in.group) {
        mergeByDepth(*in.group, depth_, {&flow_.texture(target), &shade_, &mask_});
    }

    // (3b) contrast enhancement, display only: F_a stretched between its robust
    // percentiles [issue 28]; the advection goes on from F_a itself
    if (contrast_.enabled()) timer_.begin("contrast (texture)");
    shown_ = &contrast_.apply(flow_.texture(current_), depth_);
    if (overlay_.stretchesColor()) {
        timer_.begin("contrast (colour)");
        overlay_.measureLightness(*shown_, depth_, shade_, mask_);
    }

    // (4) overlay [L eq. 10]
    timer_.begin("overlay");
    overlay_.apply(*shown_, depth_, shade_, mask_, composite_.fbo(), *in.surface, in.dye,
                   piecePixels(in, c, viewport_));

    // (5) optional silhouette edge mask, display only [L §IV-E.2]
    if (params_.ibfvs.edgeMask && in.surface->hasEdges()) {
        timer_.begin("edge mask");
        edgeMask_.apply(*in.surface, in.camera, viewport_, depth_, composite_.fbo(), c.background,
                        params_.ibfvs.edgeMaskOpacity, params_.ibfvs.edgeMaskWidthPx);
    }
    timer_.endFrame();
}

}  // namespace flowsurf::methods::ibfvs
