// ISA stage 2 — advection mesh [L §IV-D.1, eq. 12] with edge detection [L eq. 14]
// (shaders/isa/advection_mesh.glsl, one invocation per grid vertex in a compute pass or a
// full-screen fragment pass by GlPath). Inputs: velocity and depth images. Output: an
// (R+1)^2 RGBA32F texture (texcoord, edge flag) that the static case reuses. Cost grows
// with the grid M = R^2, or with the vertices asked for (a tile's).
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "parallel/screen_split.h"
#include "params/params.h"

#include <optional>

namespace flowsurf::methods::isa {

class AdvectionMesh {
public:
    AdvectionMesh(const core::Viewport& viewport, int gridRes, GlPath path);
    // `sourceCamera`/`sourceDepth`: the view and depth image the source texture was
    // made in (the current ones unless the camera moved and the remedy reprojects).
    // `vertices`: grid vertices [x0, x1) x [y0, y1) only (a tile's), the others left as they
    // were; all (R+1)^2 without.
    void compute(const gl::Texture2D& velocity, const gl::Texture2D& depth, const gl::Texture2D& sourceDepth,
                 const core::Camera& camera, const core::Camera& sourceCamera, float dt, float edgeEpsilon,
                 const std::optional<PixelRect>& vertices = std::nullopt);

    const gl::Texture2D& vertices() const { return vertices_; }
    int gridRes() const { return gridRes_; }

private:
    core::Viewport viewport_;
    int gridRes_;
    GlPath path_;
    gl::Texture2D vertices_;
    gl::Framebuffer fbo_;  // fragment path: vertices_ as the colour target
    gl::VertexArray emptyVao_;
    gl::Program program_;
};

}  // namespace flowsurf::methods::isa
