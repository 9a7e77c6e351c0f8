// Hybrid step 2 for unsteady flow — the D-space velocity texture per time level [W §3]:
// one render of the frame's surface per level of methods::TimeLevels, each into a layer
// of an RGBA16F 3D texture, so that the particle tracing reads the velocity at its own
// data time with one trilinear lookup (linear in time between levels). Cost: levels x
// one surface render (grows with the triangles N).
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "params/params.h"
#include "raster/surface_gbuffer.h"
#include "raster/surface_gpu.h"
#include "raster/time_levels.h"

namespace flowsurf::methods::hybrid {

class VelocityLevels {
public:
    static constexpr GLenum kFormat = GL_RGBA16F;
    // A 3D texture of `count` velocity images (layer j: level j), linear, clamped.
    class Volume {
    public:
        Volume() = default;
        Volume(const core::Viewport& viewport, int count);
        GLuint id() const { return texture_.id(); }
        int count() const { return count_; }

    private:
        gl::Handle<gl::detail::deleteTexture> texture_;
        int count_ = 0;
    };

    VelocityLevels(const core::Viewport& viewport, bool cullBackFaces);
    // Renders every level; velocities are divided by `speedRef` (see velocity_levels.vert).
    void render(const SurfaceGpu& surface, const TimeLevels& levels, const core::Camera& camera,
                const CommonParams& params, float speedRef);
    GLuint texture() const { return volume_.id(); }
    int count() const { return volume_.count(); }

private:
    core::Viewport viewport_;
    bool cullBackFaces_;
    Volume volume_;
    gl::Texture2D depth_;
    gl::Framebuffer fbo_;
    gl::VertexArray vao_;
    gl::Program program_;
};

}  // namespace flowsurf::methods::hybrid
