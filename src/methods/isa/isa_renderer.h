// flowsurf — ISA, Image Space Advection [L §IV, doc/algorithms.md §3]: the orchestrator.
#pragma once

#include "gpu/render_targets.h"
#include "methods/display_tail.h"
#include "methods/frame.h"
#include "methods/image_space/camera_motion.h"
#include "methods/image_space/noise_injection.h"
#include "methods/isa/advection_mesh.h"
#include "methods/isa/texture_advection.h"
#include "methods/image_work.h"
#include "raster/surface_gbuffer.h"

#include <memory>
#include <optional>
#include <vector>

namespace flowsurf::methods::isa {

class IsaRenderer final : public FlowMethod {
public:
    // `group`: the processes rendering this view together, for the renderer's life (ImageWork).
    IsaRenderer(const MethodParams& params, const core::Viewport& viewport, ProcessGroup* group = nullptr);
    const char* name() const override { return nameOf(kMethodNames, Method::Isa).data(); }
    void renderFrame(const FrameInput& in) override;
    // F_a, or its contrast stretch when the texture is enhanced (what the overlay shows).
    const gl::Texture2D& flowTexture() const override { return tail_.shown(flow_.texture(current_)); }
    const gl::Texture2D& composite() const override { return composite_.texture(); }
    const gl::Texture2D& surfaceDepth() const override { return velocityImage_[vi_].depth(); }
    const gl::Texture2D& surfaceShade() const override { return velocityImage_[vi_].shade(); }
    bool lastFrameDynamic() const override { return lastDynamic_; }
    TileTraffic tileTraffic() const override { return work_.traffic(); }

private:
    bool viewChanged(const FrameInput& in) const;  // the velocity image is stale
    bool meshStale(const FrameInput& in, const MotionPlan& plan) const;
    // The stages of renderFrame (isa_renderer.cpp).
    void updateMesh(const FrameInput& in, const MotionPlan& plan, bool resplit);
    void gatherVelocity();
    void advectTexture(const FrameInput& in, const MotionPlan& plan);
    const gl::Texture2D& depthOf(int v) const;

    MethodParams params_;
    core::Viewport viewport_;
    // Two velocity images: the previous one's depth is where the source texture was
    // made, for edge detection under camera motion (translate remedy).
    SurfaceGBuffer velocityImage_[2];
    int vi_ = 0;
    gl::Texture2D frozenDepth_;  // depth at the start of a freeze
    AdvectionMesh advectionMesh_;
    TextureAdvection textureAdvection_;
    // Whole image, replicated or tiled over processes. Tiles: this process advects its own
    // tile. The velocity image merged in place over the tile plus one grid cell (the mesh
    // vertices it interpolates; nothing reads this piece's own velocity after the merge),
    // the whole surface's depth per velocity image over the same (ImageWork::wholeDepth 0
    // and 1; and, where the edge test reads it as the source depth, over the mesh's
    // footprint, pulled from its makers), and of F_a the tile and what its pixels read
    // (pulled each frame). History slots: F_a 0 and 1, then (kDepthSlot +) the whole
    // surface's depth of velocity image 0, 1 and frozenDepth_.
    static constexpr int kDepthSlot = 2;
    ImageWork work_;
    DisplayTail tail_;  // contrast, lightness, overlay with its layers
    CameraMotion motion_;
    FlowPingPong flow_;           // F_a, R32F
    ColorTarget composite_;       // RGBA8
    int current_ = 0, source_ = 0;
    // What the cached velocity image and advection mesh were made for (static case).
    bool haveCache_ = false;
    uint64_t cachedGeneration_ = 0;
    core::Camera cachedCamera_, cachedSourceCamera_;
    bool cachedAdvect_ = true;
    bool lastDynamic_ = false;
    PixelRect footprint_;  // this tile's footprint in the source F_a
    PixelRect meshVertices(const PixelRect& tile) const;
    PixelRect footprint(const PixelRect& tile) const;
    int guardPx() const;
};

}  // namespace flowsurf::methods::isa
