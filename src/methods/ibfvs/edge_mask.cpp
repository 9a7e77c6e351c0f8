#include "methods/ibfvs/edge_mask.h"

#include "methods/common/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

namespace flowsurf::methods::ibfvs {

EdgeMask::EdgeMask()
    : program_(program({{GL_VERTEX_SHADER, "ibfvs/edge_mask.vert"},
                {GL_GEOMETRY_SHADER, "ibfvs/edge_mask.geom"},
                {GL_FRAGMENT_SHADER, "ibfvs/edge_mask.frag"}})) {}

void EdgeMask::apply(const SurfaceGpu& surface, const core::Camera& camera, const core::Viewport& viewport,
                     const gl::Texture2D& depth, const gl::Framebuffer& target, const glm::vec3& color, float opacity, float widthPx) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, viewport.width, viewport.height);
    glDisable(GL_DEPTH_TEST);  // visibility is tested in the fragment shader
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    program_.use();
    glm::mat4 viewProj = camera.viewProjection(viewport.aspect());
    glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniform2f(program_.uniform("uViewport"), float(viewport.width), float(viewport.height));
    glUniform1f(program_.uniform("uWidthPx"), widthPx);
    glUniform4f(program_.uniform("uColor"), color.r, color.g, color.b, opacity);
    glUniform1f(program_.uniform("uNear"), camera.nearPlane);
    glUniform1f(program_.uniform("uFar"), camera.farPlane);
    glUniform1i(program_.uniform("uOrtho"), camera.orthographic());
    glUniform1f(program_.uniform("uTolerance"), 0.06f);
    glBindTextureUnit(0, depth.id());
    surface.drawEdgesAdjacency();
    glDisable(GL_BLEND);
}

}  // namespace flowsurf::methods::ibfvs
