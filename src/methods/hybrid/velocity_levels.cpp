#include "methods/hybrid/velocity_levels.h"

#include "methods/common/shader_interface.h"

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
    const GLenum buffer = GL_COLOR_ATTACHMENT0;  // a layer of the 3D texture, per level
    glNamedFramebufferDrawBuffers(fbo_.id(), 1, &buffer);
    // 0, 1: position and normal from the surface's interleaved vertices; 2, 3: the two
    // raw fields of a level (bound per level).
    GLuint vao = vao_.id();
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, 3, GL_FLOAT, GL_FALSE, a == 1 ? 3 * sizeof(float) : 0);
        glVertexArrayAttribBinding(vao, a, a < 2 ? 0 : a - 1);
    }
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
    glVertexArrayVertexBuffer(vao, 0, surface.vertexBuffer(), 0, SurfaceGpu::kVertexStride);
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
        glNamedFramebufferTextureLayer(fbo_.id(), GL_COLOR_ATTACHMENT0, volume_.id(), 0, j);
        glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, zero);
        glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
        glVertexArrayVertexBuffer(vao, 1, level.fieldA, 0, sizeof(float) * 3);
        glVertexArrayVertexBuffer(vao, 2, level.fieldB, 0, sizeof(float) * 3);
        glUniform1f(weight, level.weight);
        glBindVertexArray(vao);
        glDrawElements(GL_TRIANGLES, GLsizei(surface.triangleCount() * 3), GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
}

}  // namespace flowsurf::methods::hybrid
