// Hybrid step 1 — seed textures [W §4]: one render of the surface. Outputs: P-space
// position RGBA32F (w = 1 on the surface), tangential P-space velocity RGBA32F (linear
// filtering: the D-space velocity texture of eq. 3), shade RGBA16F, depth DEPTH32F.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/common/surface_gpu.h"

namespace flowsurf::methods::hybrid {

class SeedTextures {
public:
    explicit SeedTextures(const core::Viewport& viewport);
    void render(const SurfaceGpu& surface, const core::Camera& camera);
    const gl::Texture2D& position() const { return position_; }
    const gl::Texture2D& velocity() const { return velocity_; }
    const gl::Texture2D& shade() const { return shade_; }
    const gl::Texture2D& depth() const { return depth_; }

private:
    core::Viewport viewport_;
    gl::Texture2D position_, velocity_, shade_, depth_;
    gl::Framebuffer fbo_;
    gl::Program program_;
};

}  // namespace flowsurf::methods::hybrid
