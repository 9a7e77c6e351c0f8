// ISA stage 1 — velocity image [L §IV-C.1]. The mesh rendered with P-space velocity as a
// per-vertex attribute, plus depth: only the nearest layer survives the z-test.
// Outputs: velocity RGBA32F (xyz, w=1 on surface), shade RGBA16F (eye normal, speed),
// depth DEPTH32F. Cost grows with the triangles N (dynamic case only).
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/common/surface_gpu.h"

namespace flowsurf::methods::isa {

class VelocityImage {
public:
    explicit VelocityImage(const core::Viewport& viewport);
    void render(const SurfaceGpu& surface, const core::Camera& camera);

    const gl::Texture2D& velocity() const { return velocity_; }
    const gl::Texture2D& shade() const { return shade_; }
    const gl::Texture2D& depth() const { return depth_; }

private:
    core::Viewport viewport_;
    gl::Texture2D velocity_, shade_, depth_;
    gl::Framebuffer fbo_;
    gl::Program program_;
};

}  // namespace flowsurf::methods::isa
