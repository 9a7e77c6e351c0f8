#include "methods/ibfvs/edge_mask.h"

#include "core/errors.h"
#include "gpu/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstring>
#include <string>

namespace flowsurf::methods::ibfvs {

namespace {
constexpr GLsizeiptr kCaptureHeader = 16;  // the count and its padding (edge_mask.geom)
}

EdgeMask::EdgeMask()
    : program_(program({{GL_VERTEX_SHADER, "ibfvs/edge_mask.vert"},
                {GL_GEOMETRY_SHADER, "ibfvs/edge_mask.geom"},
                {GL_FRAGMENT_SHADER, "ibfvs/edge_mask.frag"}})),
      shared_(program({{GL_VERTEX_SHADER, "ibfvs/edge_mask_shared.vert"}, {GL_FRAGMENT_SHADER, "ibfvs/edge_mask.frag"}})) {}

void EdgeMask::setState(const gl::Program& p, const core::Camera& camera, const EdgeMaskStyle& style) const {
    p.use();
    glUniform4f(p.uniform("uColor"), style.color.r, style.color.g, style.color.b, style.opacity);
    glUniform1f(p.uniform("uNear"), camera.nearPlane);
    glUniform1f(p.uniform("uFar"), camera.farPlane);
    glUniform1i(p.uniform("uOrtho"), camera.orthographic());
    glUniform1f(p.uniform("uTolerance"), 0.06f);
}

void EdgeMask::apply(const SurfaceGpu& surface, const core::Camera& camera, const core::Viewport& viewport,
                     const gl::Texture2D& depth, const gl::Framebuffer& target, const EdgeMaskStyle& style,
                     ProcessGroup* group) {
    const bool shared = group && group->size() > 1;
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, viewport.width, viewport.height);
    glDisable(GL_DEPTH_TEST);  // visibility is tested in the fragment shader
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBindTextureUnit(bindings::kEdgeMaskDepth, depth.id());

    // This surface's outlines (in parallel also written to the capture buffer).
    setState(program_, camera, style);
    const glm::mat4 viewProj = camera.viewProjection(viewport.aspect());
    glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniform2f(program_.uniform("uViewport"), float(viewport.width), float(viewport.height));
    glUniform1f(program_.uniform("uWidthPx"), style.widthPx);
    glUniform1i(program_.uniform("uCapture"), shared);
    if (!capture_) capture_ = gl::Buffer(kCaptureHeader, nullptr);  // one process: bound, never written
    const uint32_t count = drawOwn(surface, shared);
    glDisable(GL_BLEND);
    if (!shared) return;

    // The other processes' outlines over this one's fragments.
    const std::vector<glm::vec4> others = exchange(*group, count);
    if (others.empty()) return;
    glEnable(GL_BLEND);
    gl::Buffer received(GLsizeiptr(others.size() * sizeof(glm::vec4)), others.data(), 0);
    setState(shared_, camera, style);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kEdgeCapture, received.id());
    if (!emptyVao_.id()) emptyVao_ = gl::VertexArray::create();
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(others.size() / 4 * 6));
    glDisable(GL_BLEND);
}

uint32_t EdgeMask::drawOwn(const SurfaceGpu& surface, bool capture) {
    const auto draw = [&] {
        if (capture) {
            const uint32_t zero = 0;
            glClearNamedBufferSubData(capture_.id(), GL_R32UI, 0, 4, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
            glUniform1ui(program_.uniform("uCapacity"), capacity_);
        }
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kEdgeCapture, capture_.id());
        surface.drawEdgesAdjacency();
    };
    draw();
    if (!capture) return 0;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    uint32_t count = 0;
    glGetNamedBufferSubData(capture_.id(), 0, 4, &count);
    if (count > capacity_) {  // the buffer was too small: grow it and capture again, drawing nothing
        capacity_ = count;
        try {
            capture_ = gl::Buffer(kCaptureHeader + GLsizeiptr(capacity_) * 4 * GLsizeiptr(sizeof(glm::vec4)), nullptr);
        } catch (const GlError& e) {
            throw GlError("edge mask: the outlines of " + std::to_string(count) + " silhouette edges: " + e.what());
        }
        glEnable(GL_RASTERIZER_DISCARD);
        draw();
        glDisable(GL_RASTERIZER_DISCARD);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    }
    return count;
}

std::vector<glm::vec4> EdgeMask::exchange(ProcessGroup& group, uint32_t count) {
    std::vector<uint8_t> bytes(size_t(count) * 4 * sizeof(glm::vec4));
    if (!bytes.empty()) glGetNamedBufferSubData(capture_.id(), kCaptureHeader, GLsizeiptr(bytes.size()), bytes.data());
    std::vector<std::vector<uint8_t>> all = allGather(group, std::move(bytes));
    all[size_t(group.rank())].clear();  // this process's own are drawn already
    std::vector<glm::vec4> others;
    for (const std::vector<uint8_t>& msg : all) {
        const size_t n = msg.size() / sizeof(glm::vec4);
        const size_t at = others.size();
        others.resize(at + n);
        if (n) std::memcpy(&others[at], msg.data(), n * sizeof(glm::vec4));
    }
    return others;
}

}  // namespace flowsurf::methods::ibfvs
