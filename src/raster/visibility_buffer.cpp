#include "raster/visibility_buffer.h"

#include "gpu/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <vector>

namespace flowsurf::methods {

namespace {
constexpr uint32_t kNone = 0xffffffffu;
// visibility_raster.comp's Indirect block: the GL part's DrawElementsIndirectCommand (5),
// the deferred count, the covering count, the second pass's DispatchIndirectCommand (3).
constexpr size_t kIndirectWords = 10;
constexpr GLintptr kDispatchOffset = 7 * sizeof(uint32_t);
// An occluder cell no piece covers whole: beyond every depth in [0, 1] (its bits too).
constexpr float kNoOccluder = 2.0f;

glm::ivec2 occluderCells(const core::Viewport& viewport) {
    return {(viewport.width + kVisOccluderCellPx - 1) / kVisOccluderCellPx,
            (viewport.height + kVisOccluderCellPx - 1) / kVisOccluderCellPx};
}
}  // namespace

glm::uvec2 workGroupGrid(size_t groups, size_t maxX) {
    if (groups == 0) return {0, 0};
    const size_t widest = std::max<size_t>(maxX, 1);
    const size_t rows = (groups + widest - 1) / widest;
    return {GLuint((groups + rows - 1) / rows), GLuint(rows)};
}

VisibilityBuffer::VisibilityBuffer(const core::Viewport& viewport)
    : viewport_(viewport),
      depth_(GLsizeiptr(viewport.width) * viewport.height * 4, nullptr),
      ids_(GLsizeiptr(viewport.width) * viewport.height * 4, nullptr),
      indirect_(kIndirectWords * sizeof(uint32_t), nullptr),
      compute_(program({{GL_COMPUTE_SHADER, "raster/visibility_raster.comp"}})),
      glPass_(program({{GL_VERTEX_SHADER, "raster/visibility_raster_gl.vert"}, {GL_FRAGMENT_SHADER, "raster/visibility_raster_gl.frag"}})),
      dispatch_(program({{GL_COMPUTE_SHADER, "raster/visibility_dispatch.comp"}})),
      occlusion_(program({{GL_COMPUTE_SHADER, "raster/visibility_occlusion.comp"}})),
      deferredVao_(gl::VertexArray::create()),
      emptyVao_(gl::VertexArray::create()),
      noAttachments_(gl::Framebuffer::create()) {
    glNamedFramebufferParameteri(noAttachments_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, viewport.width);
    glNamedFramebufferParameteri(noAttachments_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, viewport.height);
    enableAttribute(deferredVao_.id(), surface_vertex::kPosObj);
    // The renderer's limits, once: deferred triangles (the large and the clipped ones, which
    // cannot be that many) fit the largest storage block, beyond it they are dropped; so do
    // the covering triangles' ids, beyond it the second pass runs over every triangle; work
    // groups along x may be as few as 65,535 (10M triangles need 156,250 groups of 64).
    GLint maxBlock = 0, maxGroups = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &maxGroups);
    maxDeferred_ = std::max<size_t>(size_t(std::max(maxBlock, 0)) / (3 * sizeof(uint32_t)), 1);
    maxCovering_ = std::max<size_t>(size_t(std::max(maxBlock, 0)) / sizeof(uint32_t), 1);
    maxGroupsX_ = size_t(std::max(maxGroups, 1));
    glProgramUniform1ui(dispatch_.id(), dispatch_.uniform("uMaxGroupsX"), GLuint(maxGroupsX_));  // constant
}

void VisibilityBuffer::ensureCapacity(size_t triangles) {
    // Room for every triangle, within the largest storage block.
    const size_t deferred = std::clamp<size_t>(triangles, 1, maxDeferred_);
    if (deferred > deferredCapacity_ || !deferred_) {
        deferredCapacity_ = deferred;
        deferred_ = gl::Buffer(GLsizeiptr(deferredCapacity_ * 3 * sizeof(uint32_t)), nullptr);
        deferredIds_ = gl::Buffer(GLsizeiptr(deferredCapacity_ * sizeof(uint32_t)), nullptr);
        glVertexArrayElementBuffer(deferredVao_.id(), deferred_.id());
    }
    const size_t covering = std::clamp<size_t>(triangles, 1, maxCovering_);
    if (covering > coveringCapacity_ || !covering_) {
        coveringCapacity_ = covering;
        covering_ = gl::Buffer(GLsizeiptr(coveringCapacity_ * sizeof(uint32_t)), nullptr);
    }
}

void VisibilityBuffer::bind(const SurfaceGpu& surface) const {
    glBindTextureUnit(bindings::kVisVertex, surface.vertexTexture().id());
    glBindTextureUnit(bindings::kVisTriangle, surface.triangleTexture().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kVisDepth, depth_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kVisId, ids_.id());
}

void VisibilityBuffer::rasterize(const SurfaceGpu& surface, const glm::mat4& viewProj, bool cullBackFaces,
                                 const PixelRect& clear) {
    const size_t triangles = surface.triangleCount();
    ensureCapacity(triangles);
    // The second pass over the covering triangles only, when every triangle's id fits.
    const bool compacted = triangles <= coveringCapacity_;
    const uint32_t none = kNone;
    if (!clear.empty()) {  // pixels row by row from the bottom: the clear's rows are one range
        const GLintptr from = GLintptr(clear.y0) * viewport_.width * GLintptr(sizeof(uint32_t));
        const GLsizeiptr bytes = GLsizeiptr(clear.height()) * viewport_.width * GLsizeiptr(sizeof(uint32_t));
        glClearNamedBufferSubData(depth_.id(), GL_R32UI, from, bytes, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
        glClearNamedBufferSubData(ids_.id(), GL_R32UI, from, bytes, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
    }
    const std::array<uint32_t, kIndirectWords> command{0, 1, 0, 0, 0, 0, 0, 0, 0, 1};  // see kIndirectWords
    glNamedBufferSubData(indirect_.id(), 0, sizeof(command), command.data());
    bind(surface);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kVisIndirect, indirect_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kVisDeferred, deferred_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kVisDeferredId, deferredIds_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kVisCovering, covering_.id());
    glVertexArrayVertexBuffer(deferredVao_.id(), surface_vertex::kBuffer, surface.vertexBuffer(), 0, surface_vertex::kStride);

    for (const gl::Program* p : {&compute_, &glPass_}) {
        glProgramUniformMatrix4fv(p->id(), p->uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
        glProgramUniform2i(p->id(), p->uniform("uSize"), viewport_.width, viewport_.height);
    }
    glProgramUniform1ui(compute_.id(), compute_.uniform("uTriangleCount"), GLuint(triangles));
    glProgramUniform1ui(compute_.id(), compute_.uniform("uDeferredCapacity"), GLuint(deferredCapacity_));
    glProgramUniform1i(compute_.id(), compute_.uniform("uCullBack"), cullBackFaces ? 1 : 0);
    glProgramUniform1i(compute_.id(), compute_.uniform("uCompacted"), compacted ? 1 : 0);

    glBindFramebuffer(GL_FRAMEBUFFER, noAttachments_.id());
    glViewport(0, 0, viewport_.width, viewport_.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    if (cullBackFaces) glEnable(GL_CULL_FACE);
    else glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    const glm::uvec2 grid = workGroupGrid((triangles + kVisRasterGroup - 1) / kVisRasterGroup, maxGroupsX_);
    for (int pass = 0; pass < 2; ++pass) {
        compute_.use();
        glUniform1i(compute_.uniform("uPass"), pass);
        if (pass == 1 && compacted) {
            glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, indirect_.id());
            glDispatchComputeIndirect(kDispatchOffset);
            glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
        } else if (grid.x) {
            glDispatchCompute(grid.x, grid.y, 1);
        }
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_ELEMENT_ARRAY_BARRIER_BIT);
        if (pass == 0 && compacted) {  // the second pass's work groups, from the covering count
            dispatch_.use();
            glDispatchCompute(1, 1, 1);
            glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        }
        glPass_.use();
        glUniform1i(glPass_.uniform("uPass"), pass);
        glBindVertexArray(deferredVao_.id());
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, indirect_.id());
        glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr);
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }

    glDisable(GL_CULL_FACE);
}

namespace {
// The occluder cells (kVisOccluderCellPx² pixels) that hold any pixel of `pixels`.
PixelRect cellsOver(const PixelRect& pixels) {
    if (pixels.empty()) return {};
    const int c = kVisOccluderCellPx;
    return {pixels.x0 / c, pixels.y0 / c, (pixels.x1 + c - 1) / c, (pixels.y1 + c - 1) / c};
}
}  // namespace

RasterAgreement VisibilityBuffer::agree(ProcessGroup& group, const PixelRect& footprint, bool compute,
                                       const core::Viewport& viewport) {
    const PixelRect fp = footprint.intersect({0, 0, viewport.width, viewport.height});
    const float mine[5] = {float(fp.x0), float(fp.y0), float(fp.x1), float(fp.y1), compute ? 1.0f : 0.0f};  // exact in float
    const std::vector<float> all = group.gather(mine);
    RasterAgreement agreed{true, {}};
    std::vector<PixelRect> fps;
    for (size_t i = 0; i + 4 < all.size(); i += 5) {
        fps.push_back({int(all[i]), int(all[i + 1]), int(all[i + 2]), int(all[i + 3])});
        agreed.compute = agreed.compute && all[i + 4] != 0.0f;
    }
    if (!agreed.compute) return agreed;  // GL's rasteriser drops nothing: no cells
    PixelRect overlap;
    for (size_t a = 0; a < fps.size(); ++a)
        for (size_t b = a + 1; b < fps.size(); ++b)
            if (!fps[a].empty() && !fps[b].empty()) overlap = overlap.united(fps[a].intersect(fps[b]));
    agreed.cells = cellsOver(overlap);
    return agreed;
}

void VisibilityBuffer::dropOccluded(ProcessGroup& group, const PixelRect& cells, const PixelRect& footprint) {
    if (cells.empty()) return;
    const glm::ivec2 grid = occluderCells(viewport_);
    const int cellsX = grid.x, c = kVisOccluderCellPx;
    if (!occluders_) occluders_ = gl::Buffer(GLsizeiptr(size_t(grid.x) * size_t(grid.y) * 4), nullptr);
    const PixelRect fp = footprint.intersect({0, 0, viewport_.width, viewport_.height});
    // This piece's pixels in those cells, and the cells it can cover whole.
    const PixelRect pixels = fp.intersect({cells.x0 * c, cells.y0 * c, cells.x1 * c, cells.y1 * c});
    const PixelRect mine = cellsOver(pixels);
    // (1) this piece's farthest depth per cell it covers whole (none elsewhere): the rows of
    // the cells, whole rows being one range of the buffer
    const GLintptr rows = GLintptr(cells.y0) * cellsX * 4;
    const GLsizeiptr rowBytes = GLsizeiptr(cells.height()) * cellsX * 4;
    const uint32_t none = kNone;
    glClearNamedBufferSubData(occluders_.id(), GL_R32UI, rows, rowBytes, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kVisDepth, depth_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kVisId, ids_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kVisOccluder, occluders_.id());
    occlusion_.use();
    glUniform2i(occlusion_.uniform("uSize"), viewport_.width, viewport_.height);
    glUniform1i(occlusion_.uniform("uCellsX"), cellsX);
    glUniform4i(occlusion_.uniform("uFootprint"), fp.x0, fp.y0, fp.x1, fp.y1);
    const auto run = [&](int step, const PixelRect& r) {
        if (r.empty()) return;
        glUniform1i(occlusion_.uniform("uStep"), step);
        glUniform2i(occlusion_.uniform("uOrigin"), r.x0, r.y0);
        glUniform2i(occlusion_.uniform("uEnd"), r.x1, r.y1);
        glDispatchCompute(GLuint((r.width() + kPixelGroup - 1) / kPixelGroup),
                          GLuint((r.height() + kPixelGroup - 1) / kPixelGroup), 1);
    };
    run(0, mine);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<uint32_t> bits(size_t(cells.height()) * size_t(cellsX));
    glGetNamedBufferSubData(occluders_.id(), rows, rowBytes, bits.data());
    // (2) the group's nearest of them per cell
    std::vector<float> depth(cells.area());
    const auto at = [&](size_t k) -> uint32_t& {
        return bits[(k / size_t(cells.width())) * size_t(cellsX) + size_t(cells.x0) + k % size_t(cells.width())];
    };
    for (size_t k = 0; k < depth.size(); ++k) depth[k] = at(k) == kNone ? kNoOccluder : std::bit_cast<float>(at(k));
    group.minInPlace(depth);
    if (pixels.empty()) return;
    for (size_t k = 0; k < depth.size(); ++k) at(k) = std::bit_cast<uint32_t>(depth[k]);
    glNamedBufferSubData(occluders_.id(), rows, rowBytes, bits.data());
    // (3) this piece's pixels behind them dropped
    run(1, pixels);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void VisibilityBuffer::drawResolve(const SurfaceGpu& surface, const PixelRect& rect) const {
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x0, rect.y0, rect.width(), rect.height());
    glEnable(GL_DEPTH_TEST);  // to write gl_FragDepth
    glDepthFunc(GL_ALWAYS);
    glDisable(GL_BLEND);
    bind(surface);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
}

}  // namespace flowsurf::methods
