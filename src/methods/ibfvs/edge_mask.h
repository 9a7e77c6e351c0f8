// IBFVS edge mask [L §IV-E.2] — silhouette edges (boundary edges, and edges between a
// front- and a back-facing triangle) found per frame in a geometry shader and drawn as
// background-coloured lines with high opacity over the displayed image (RGBA8). It
// dims silhouettes for display only and is never fed back into F_a.
// Parallel (a ProcessGroup of several processes, each with a piece): the geometry shader
// also writes its outline quads (clip space) to a buffer, the processes exchange them, and
// each draws the others' over its own fragments too — every line is the same colour and
// opacity, so what a pixel shows depends only on how many lines cover it, not on their
// order: each process's own pixels get the one-process image. Seams of the partition are
// not outlines (SurfaceGpu with piece_seams.h).
// Cost: one draw of the edges (GL_LINES_ADJACENCY); in parallel a read-back of the quads
// (64 B each; a second, rasterizer-discarded draw when the buffer had to grow), their
// exchange to every process, and one draw of the received ones.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "parallel/process_group.h"
#include "raster/surface_gpu.h"

#include <glm/glm.hpp>

#include <vector>

namespace flowsurf::methods::ibfvs {

struct EdgeMaskStyle {
    glm::vec3 color{0.0f};
    float opacity = 0.85f;
    float widthPx = 2.0f;
};

class EdgeMask {
public:
    EdgeMask();
    // `group`: the processes drawing the same view (null or one: this surface alone).
    void apply(const SurfaceGpu& surface, const core::Camera& camera, const core::Viewport& viewport,
               const gl::Texture2D& depth, const gl::Framebuffer& target, const EdgeMaskStyle& style,
               ProcessGroup* group = nullptr);

private:
    void setState(const gl::Program& p, const core::Camera& camera, const EdgeMaskStyle& style) const;
    // Draws this surface's outlines (program_ in use); with `capture` also into capture_,
    // grown and captured again when too small. Returns the quads captured.
    uint32_t drawOwn(const SurfaceGpu& surface, bool capture);
    // Collective: the `count` captured quads to every other process; returns theirs.
    std::vector<glm::vec4> exchange(ProcessGroup& group, uint32_t count);

    gl::Program program_, shared_;
    gl::VertexArray emptyVao_;
    gl::Buffer capture_;
    GLuint capacity_ = 0;  // quads capture_ holds
};

}  // namespace flowsurf::methods::ibfvs
