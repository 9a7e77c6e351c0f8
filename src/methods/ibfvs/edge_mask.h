// IBFVS edge mask [L §IV-E.2] — silhouette edges (boundary edges, and edges between a
// front- and a back-facing triangle) found per frame in a geometry shader and drawn as
// background-coloured lines with high opacity over the displayed image (RGBA8). It
// dims silhouettes for display only and is never fed back into F_a.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/common/surface_gpu.h"

#include <glm/glm.hpp>

namespace flowsurf::methods::ibfvs {

class EdgeMask {
public:
    EdgeMask();
    void apply(const SurfaceGpu& surface, const core::Camera& camera, const core::Viewport& viewport,
               const gl::Texture2D& depth, const gl::Framebuffer& target, const glm::vec3& color, float opacity, float widthPx) const;

private:
    gl::Program program_;
};

}  // namespace flowsurf::methods::ibfvs
