// flowsurf — the surface as a visibility buffer, rasterised in compute shaders: per pixel the
// depth and the id of the nearest triangle, from which SurfaceGBuffer's resolve pass rebuilds
// the same per-pixel buffers the GL rasteriser gives (a visibility buffer, Burns & Hunt 2013).
// Why: a software renderer (llvmpipe) transforms, sets up and bins every triangle on one
// thread before its raster threads start, and a CFD surface's triangles cover a few pixels
// each, so the surface pass costs per triangle; here every triangle is a compute invocation
// and all cores share them. Triangles larger than 32 pixels, or crossing the eye plane, are
// handed back to the GL rasteriser (it clips), into the same buffer.
// Inputs: SurfaceGpu's vertex and index buffers. Output: two W x H uint buffers (storage
// blocks kVisDepthBinding and kVisIdBinding, visibility.glsl). Cost: O(N + covered pixels) in two
// passes (least depth, then least id at that depth: order-independent, deterministic); the
// second runs over the triangles the first found covering a pixel centre only (on a CFD
// surface most cover none: 1M triangles at 512^2).
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "gpu/shader_limits.h"
#include "parallel/process_group.h"
#include "parallel/screen_split.h"
#include "raster/surface_gpu.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace flowsurf::methods {

// Work groups for `groups` groups of one dimension when a dispatch may have at most `maxX`
// along x (GL guarantees 65,535): (x, y) with x * y >= groups and x <= maxX, the fewest
// rows, and in them the fewest groups (fewer than y spare). visibility_raster.comp numbers
// its triangles row by row. Spare groups are not free: llvmpipe runs a group whose
// invocations all return at once through the whole shader with its lanes masked, at about a
// full group's cost (a 5M-triangle piece at 1024^2, one thread: pass 0 took ~440 ms in 2
// rows of 65,535, ~215 ms in 2 rows of 39,031).
glm::uvec2 workGroupGrid(size_t groups, size_t maxX);

// What the processes of a group settle before each rasterises its piece (VisibilityBuffer::agree).
struct RasterAgreement {
    bool compute = false;  // the visibility buffer on every process (else GL's rasteriser on every one)
    PixelRect cells;       // the occluder cells, when compute (may be empty: no footprints overlap)
};

class VisibilityBuffer {
public:
    explicit VisibilityBuffer(const core::Viewport& viewport);
    // Fills the visibility buffer with `surface` seen through `viewProj`; `cullBackFaces`
    // skips triangles that turn clockwise in the window (as GL_CULL_FACE with CCW front).
    // `clear`: the pixels whose depth and id are reset first (where the last and this
    // surface can be; elsewhere they hold none already). Its rows are cleared whole.
    void rasterize(const SurfaceGpu& surface, const glm::mat4& viewProj, bool cullBackFaces, const PixelRect& clear);
    // Collective over `group`, before rasterize: every process's footprint (what its piece
    // can cover this render) and its rule's choice of rasteriser (`compute`:
    // useComputeRaster's answer; no for a piece the vertex textures cannot hold). The group
    // rasterises with the visibility buffer only when every process chose it — the path
    // changes pixels, so it is the group's, not a piece's — and then gets the occluder cells
    // dropOccluded works on: those over the pixels where two footprints overlap (elsewhere no
    // piece can hide another's pixels). Cost: a gather of 5 floats per process.
    static RasterAgreement agree(ProcessGroup& group, const PixelRect& footprint, bool compute,
                                 const core::Viewport& viewport);
    // Collective over `group` (when agree chose the visibility buffer), between rasterize and
    // a resolve (sort-last occlusion between pieces): forgets this piece's pixels that
    // another piece hides. In each of `cells` (agree's, kVisOccluderCellPx² pixels each) every
    // process finds the farthest depth of its piece where the piece covers the whole cell;
    // the group's least of these per cell is an occluder, and a pixel of this piece strictly
    // farther than its cell's occluder is dropped (depth and id none): a nearer fragment of
    // another piece wins that pixel in every merge by depth, so the merged image is
    // unchanged while the resolve and everything after it skip the pixel. Cost: two passes
    // over this piece's part of the cells and a minimum over the group of one float per cell
    // (at most 64 KB at 1024²).
    void dropOccluded(ProcessGroup& group, const PixelRect& cells, const PixelRect& footprint);
    // Binds the vertex and triangle textures and the depth and id buffers for a resolve pass.
    void bind(const SurfaceGpu& surface) const;
    // Runs the current program (a resolve: a full-screen triangle writing gl_FragDepth) over
    // `rect` only, with the buffers bound (bind) and the depth test set to write; the GL
    // state it changes is restored (scissor and depth test off, depth function LESS).
    void drawResolve(const SurfaceGpu& surface, const PixelRect& rect) const;

private:
    void ensureCapacity(size_t triangles);

    core::Viewport viewport_;
    gl::Buffer depth_, ids_, indirect_, deferred_, deferredIds_, covering_;
    size_t deferredCapacity_ = 0;
    size_t maxDeferred_ = 1;     // deferred triangles that fit the largest storage block
    size_t coveringCapacity_ = 0;
    size_t maxCovering_ = 1;     // triangle ids that fit the largest storage block
    size_t maxGroupsX_ = 65535;  // GL_MAX_COMPUTE_WORK_GROUP_COUNT along x
    gl::Program compute_, glPass_, dispatch_, occlusion_;
    gl::Buffer occluders_;  // per cell, row by row: depth bits (visibility_occlusion.comp)
    gl::VertexArray deferredVao_, emptyVao_;
    gl::Framebuffer noAttachments_;
};

}  // namespace flowsurf::methods
