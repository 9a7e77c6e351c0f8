// flowsurf — IBFVS, Image Based Flow Visualization for curved Surfaces [L §IV,
// doc/algorithms.md §4]: the orchestrator.
#pragma once

#include "gpu/render_targets.h"
#include "methods/display_tail.h"
#include "methods/frame.h"
#include "methods/ibfvs/edge_mask.h"
#include "methods/ibfvs/polygon_advection.h"
#include "methods/image_space/camera_motion.h"
#include "methods/image_space/noise_injection.h"
#include "methods/image_work.h"

#include <memory>
#include <vector>

namespace flowsurf::methods::ibfvs {

class IbfvsRenderer final : public FlowMethod {
public:
    // `group`: the processes rendering this view together, for the renderer's life (ImageWork).
    IbfvsRenderer(const MethodParams& params, const core::Viewport& viewport, ProcessGroup* group = nullptr);
    const char* name() const override { return nameOf(kMethodNames, Method::Ibfvs).data(); }
    void renderFrame(const FrameInput& in) override;
    // F_a, or its contrast stretch when the texture is enhanced (what the overlay shows).
    const gl::Texture2D& flowTexture() const override { return tail_.shown(flow_.texture(current_)); }
    const gl::Texture2D& composite() const override { return composite_.texture(); }
    const gl::Texture2D& surfaceDepth() const override { return depth_; }
    const gl::Texture2D& surfaceShade() const override { return shade_; }
    bool lastFrameDynamic() const override { return lastDynamic_; }
    TileTraffic tileTraffic() const override { return work_.traffic(); }

private:
    // The whole surface's buffers where this process's per-pixel work runs, after the draw
    // of its piece (target: the F_a written).
    void gatherDrawn(int target);
    // Tiles: stages (2)+(3) on this process's tile (target: the F_a written; drawMs: what
    // the draw took).
    void advectTile(const NoiseStep& noise, int target, float drawMs);

    MethodParams params_;
    core::Viewport viewport_;
    gl::Texture2D shade_, mask_, depth_;  // written by the advection draw
    PolygonAdvection polygonAdvection_;
    // Whole image, replicated or tiled over processes; tiles: the whole surface's depth over
    // the tile in ImageWork::wholeDepth 0.
    ImageWork work_;
    DisplayTail tail_;  // contrast, lightness, overlay with its layers
    EdgeMask edgeMask_;
    CameraMotion motion_;
    FlowPingPong flow_;            // F_a, R32F (+ shade + mask + depth: the advection draw)
    ColorTarget composite_;        // RGBA8
    int current_ = 0, source_ = 0;
    uint64_t lastGeneration_ = 0;
    core::Camera lastCamera_;
    bool lastDynamic_ = false;
};

}  // namespace flowsurf::methods::ibfvs
