#include "methods/hybrid/velocity_levels.h"

#include "gpu/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace flowsurf::methods::hybrid {

VelocityLevels::VelocityLevels(const core::Viewport& viewport, bool cullBackFaces)
    : viewport_(viewport),
      cullBackFaces_(cullBackFaces),
      depth_(GL_DEPTH_COMPONENT32F, viewport.width, viewport.height, GL_NEAREST),
      fbo_(gl::Framebuffer::create()),
      vao_(gl::VertexArray::create()),
      program_(program({{GL_VERTEX_SHADER, "hybrid/velocity_levels.vert"}, {GL_FRAGMENT_SHADER, "hybrid/velocity_levels.frag"}})) {
    fbo_.attach(GL_DEPTH_ATTACHMENT, depth_);
    // One draw buffer, so the output's location is 0; a layer of the 3D texture is attached
    // to it per level.
    static_assert(outputs::kLevelVelocity.point == 0, "the only draw buffer is location 0");
    const GLenum buffer = GL_COLOR_ATTACHMENT0 + outputs::kLevelVelocity;
    glNamedFramebufferDrawBuffers(fbo_.id(), 1, &buffer);
    // Position and normal from the surface's interleaved vertices; the two raw fields of a
    // level (bound per level).
    for (const VertexAttribute& a : {surface_vertex::kPosObj, surface_vertex::kNormalObj, kLevelFieldA, kLevelFieldB})
        enableAttribute(vao_.id(), a);
}

VelocityLevels::Volume::Volume(const core::Viewport& viewport, int count) : count_(count) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    texture_ = gl::Handle<gl::detail::deleteTexture>(id);
    glTextureStorage3D(id, 1, kFormat, viewport.width, viewport.height, std::max(count, 1));
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTextureParameteri(id, wrap, GL_CLAMP_TO_EDGE);
}

void VelocityLevels::render(const SurfaceGpu& surface, const TimeLevels& levels, const core::Camera& camera,
                            const CommonParams& params, float speedRef) {
    const int count = int(levels.levels.size());
    if (count != volume_.count()) volume_ = Volume(viewport_, count);
    GLuint vao = vao_.id();
    glVertexArrayVertexBuffer(vao, surface_vertex::kBuffer, surface.vertexBuffer(), 0, surface_vertex::kStride);
    glVertexArrayElementBuffer(vao, surface.indexBuffer());
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, viewport_.width, viewport_.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    if (cullBackFaces_) glEnable(GL_CULL_FACE);
    else glDisable(GL_CULL_FACE);
    program_.use();
    glm::mat4 viewProj = camera.viewProjection(viewport_.aspect());
    glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniform4fv(program_.uniform("uLayerDepthRow"), 1, glm::value_ptr(layerDepthRow(camera)));
    glUniform1i(program_.uniform("uNormalize"), params.normalize);
    glUniform1f(program_.uniform("uClampSpeed"), surface.clampSpeed());
    glUniform1f(program_.uniform("uInvSpeedRef"), 1.0f / std::max(speedRef, 1e-30f));
    const GLint weight = program_.uniform("uWeight");
    const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
    for (int j = 0; j < count; ++j) {
        const TimeLevel& level = levels.levels[size_t(j)];
        glNamedFramebufferTextureLayer(fbo_.id(), GL_COLOR_ATTACHMENT0 + outputs::kLevelVelocity, volume_.id(), 0, j);
        glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, outputs::kLevelVelocity, zero);
        glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
        glVertexArrayVertexBuffer(vao, kLevelFieldA.buffer, level.fieldA, 0, kLevelFieldA.components * sizeof(float));
        glVertexArrayVertexBuffer(vao, kLevelFieldB.buffer, level.fieldB, 0, kLevelFieldB.components * sizeof(float));
        glUniform1f(weight, level.weight);
        glBindVertexArray(vao);
        glDrawElements(GL_TRIANGLES, GLsizei(surface.triangleCount() * 3), GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
}

}  // namespace flowsurf::methods::hybrid
