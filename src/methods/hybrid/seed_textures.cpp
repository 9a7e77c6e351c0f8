#include "methods/hybrid/seed_textures.h"

#include <glm/gtc/type_ptr.hpp>

namespace flowsurf::methods::hybrid {

SeedTextures::SeedTextures(const core::Viewport& viewport)
    : viewport_(viewport),
      position_(GL_RGBA32F, viewport.width, viewport.height, GL_NEAREST),
      velocity_(GL_RGBA32F, viewport.width, viewport.height, GL_LINEAR),
      shade_(GL_RGBA16F, viewport.width, viewport.height, GL_NEAREST),
      depth_(GL_DEPTH_COMPONENT32F, viewport.width, viewport.height, GL_NEAREST),
      fbo_(gl::Framebuffer::create()),
      program_({{GL_VERTEX_SHADER, "hybrid/seed_textures.vert"}, {GL_FRAGMENT_SHADER, "hybrid/seed_textures.frag"}}) {
    fbo_.attach(GL_COLOR_ATTACHMENT0, position_);
    fbo_.attach(GL_COLOR_ATTACHMENT1, velocity_);
    fbo_.attach(GL_COLOR_ATTACHMENT2, shade_);
    fbo_.attach(GL_DEPTH_ATTACHMENT, depth_);
    fbo_.finish(3);
}

void SeedTextures::render(const SurfaceGpu& surface, const core::Camera& camera) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, viewport_.width, viewport_.height);
    const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
    for (int i = 0; i < 3; ++i) glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, i, zero);
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    program_.use();
    glm::mat4 view = camera.view(), viewProj = camera.projection(viewport_.aspect()) * view;
    glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniformMatrix4fv(program_.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
    surface.draw();
    glDisable(GL_DEPTH_TEST);
}

}  // namespace flowsurf::methods::hybrid
