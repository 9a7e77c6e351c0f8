#include "methods/ibfvs/edge_mask.h"

#include "methods/common/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstring>

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
    std::vector<glm::vec4> others;
    if (group && group->size() > 1) others = exchange(*group, surface, camera, viewport, depth, target, style);
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, viewport.width, viewport.height);
    glDisable(GL_DEPTH_TEST);  // visibility is tested in the fragment shader
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBindTextureUnit(kEdgeMaskDepthUnit, depth.id());
    if (group && group->size() > 1) {
        // Own outlines were drawn while captured (exchange); the others' now.
        if (!others.empty()) {
            gl::Buffer received(GLsizeiptr(others.size() * sizeof(glm::vec4)), others.data(), 0);
            setState(shared_, camera, style);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeCaptureBinding, received.id());
            if (!emptyVao_.id()) emptyVao_ = gl::VertexArray::create();
            glBindVertexArray(emptyVao_.id());
            glDrawArrays(GL_TRIANGLES, 0, GLsizei(others.size() / 4 * 6));
        }
    } else {
        setState(program_, camera, style);
        const glm::mat4 viewProj = camera.viewProjection(viewport.aspect());
        glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
        glUniform2f(program_.uniform("uViewport"), float(viewport.width), float(viewport.height));
        glUniform1f(program_.uniform("uWidthPx"), style.widthPx);
        glUniform1i(program_.uniform("uCapture"), 0);
        if (!capture_) capture_ = gl::Buffer(kCaptureHeader, nullptr);  // bound, never written
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeCaptureBinding, capture_.id());
        surface.drawEdgesAdjacency();
    }
    glDisable(GL_BLEND);
}

std::vector<glm::vec4> EdgeMask::exchange(ProcessGroup& group, const SurfaceGpu& surface, const core::Camera& camera,
                                          const core::Viewport& viewport, const gl::Texture2D& depth,
                                          const gl::Framebuffer& target, const EdgeMaskStyle& style) {
    // Draw this piece's outlines, capturing their quads; again with a larger buffer if
    // they did not fit (the first draw's lines are then drawn twice: redo from a copy).
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, viewport.width, viewport.height);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBindTextureUnit(kEdgeMaskDepthUnit, depth.id());
    setState(program_, camera, style);
    const glm::mat4 viewProj = camera.viewProjection(viewport.aspect());
    glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniform2f(program_.uniform("uViewport"), float(viewport.width), float(viewport.height));
    glUniform1f(program_.uniform("uWidthPx"), style.widthPx);
    glUniform1i(program_.uniform("uCapture"), 1);
    uint32_t count = 0;
    // Count first (nothing drawn: rasterizer discard), then draw and capture with room for all.
    for (int attempt = 0; attempt < 2; ++attempt) {
        const GLuint capacity = attempt == 0 ? capacity_ : std::max<GLuint>(count, 1);
        if (!capture_ || capacity > capacity_ || attempt == 1) {
            capacity_ = std::max(capacity, capacity_);
            capture_ = gl::Buffer(kCaptureHeader + GLsizeiptr(capacity_) * 4 * GLsizeiptr(sizeof(glm::vec4)), nullptr);
        }
        const uint32_t zero = 0;
        glClearNamedBufferSubData(capture_.id(), GL_R32UI, 0, 4, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeCaptureBinding, capture_.id());
        glUniform1ui(program_.uniform("uCapacity"), capacity_);
        glEnable(GL_RASTERIZER_DISCARD);
        surface.drawEdgesAdjacency();
        glDisable(GL_RASTERIZER_DISCARD);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        glGetNamedBufferSubData(capture_.id(), 0, 4, &count);
        if (count <= capacity_) break;
    }
    std::vector<glm::vec4> mine(size_t(count) * 4);
    if (count)
        glGetNamedBufferSubData(capture_.id(), kCaptureHeader, GLsizeiptr(mine.size() * sizeof(glm::vec4)), mine.data());
    // This piece's own outlines, as in one process.
    glUniform1i(program_.uniform("uCapture"), 0);
    surface.drawEdgesAdjacency();
    glDisable(GL_BLEND);

    std::vector<uint8_t> bytes(mine.size() * sizeof(glm::vec4));
    if (!bytes.empty()) std::memcpy(bytes.data(), mine.data(), bytes.size());
    std::vector<std::vector<uint8_t>> sends(size_t(group.size()), bytes);
    sends[size_t(group.rank())].clear();
    std::vector<glm::vec4> others;
    for (const std::vector<uint8_t>& msg : group.exchange(sends)) {
        const size_t n = msg.size() / sizeof(glm::vec4);
        const size_t at = others.size();
        others.resize(at + n);
        if (n) std::memcpy(&others[at], msg.data(), n * sizeof(glm::vec4));
    }
    return others;
}

}  // namespace flowsurf::methods::ibfvs
