#include "methods/common/overlay.h"

#include "methods/common/shader_interface.h"
#include "methods/common/colormap.h"

namespace flowsurf::methods {

Overlay::Overlay(const CommonParams& params)
    : params_(params),
      program_(program({{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "common/overlay.frag"}})),
      colormap_(makeColormapTexture(params.colormap)),
      emptyVao_(gl::VertexArray::create()) {}

void Overlay::apply(const gl::Texture2D& flow, const gl::Texture2D& depth, const gl::Texture2D& shade,
                    const gl::Framebuffer& target, float speedMax) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, flow.width(), flow.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    program_.use();
    glUniform1i(program_.uniform("uScheme"), int(params_.overlay));
    glUniform1f(program_.uniform("uBeta"), params_.beta);
    glUniform1f(program_.uniform("uContrast"), params_.contrast);
    glUniform1f(program_.uniform("uSpeedMax"), speedMax);
    glUniform1i(program_.uniform("uUseColormap"), params_.colormap != Colormap::None);
    glUniform1i(program_.uniform("uLighting"), params_.lighting);
    glUniform1i(program_.uniform("uVelocityMask"), params_.velocityMask);
    glUniform3fv(program_.uniform("uBackground"), 1, &params_.background.x);
    glBindTextureUnit(0, flow.id());
    glBindTextureUnit(1, depth.id());
    glBindTextureUnit(2, shade.id());
    glBindTextureUnit(3, colormap_.id());
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace flowsurf::methods
