#include "methods/ibfvs/polygon_advection.h"

#include "methods/common/shader_interface.h"
#include "methods/common/noise_injection.h"
#include "methods/common/resample.h"

#include <glm/gtc/type_ptr.hpp>

namespace flowsurf::methods::ibfvs {

PolygonAdvection::PolygonAdvection(const core::Viewport& viewport, const CommonParams& common)
    : noise_(common, viewport),
      program_(program({{GL_VERTEX_SHADER, "ibfvs/polygon_advection.vert"}, {GL_FRAGMENT_SHADER, "ibfvs/polygon_advection.frag"}},
               resampleDefine(common.resample) + noise_.defines())) {}

void PolygonAdvection::apply(const SurfaceGpu& surface, const core::Camera& camera, const core::Camera& prevCamera,
                             const core::Viewport& viewport, float dt, const gl::Texture2D& prevFlow,
                             const gl::Framebuffer& target, float flowBackground, bool cullBackFaces,
                             const NoiseStep& noise) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, viewport.width, viewport.height);
    // Gray background in F_a [L §IV-F.2]: what flows in from outside is the noise mean.
    const float bg[4] = {flowBackground, 0, 0, 1}, zero[4] = {0, 0, 0, 0}, one = 1.0f;
    glClearNamedFramebufferfv(target.id(), GL_COLOR, 0, bg);
    glClearNamedFramebufferfv(target.id(), GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(target.id(), GL_COLOR, 2, zero);
    glClearNamedFramebufferfv(target.id(), GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    if (cullBackFaces) glEnable(GL_CULL_FACE);  // cost ~ N: halve it on closed surfaces
    else glDisable(GL_CULL_FACE);                // open surfaces are seen from both sides
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    program_.use();
    glm::mat4 view = camera.view();
    glm::mat4 viewProj = camera.projection(viewport.aspect()) * view;
    glm::mat4 prevViewProj = prevCamera.viewProjection(viewport.aspect());
    glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniformMatrix4fv(program_.uniform("uPrevViewProj"), 1, GL_FALSE, glm::value_ptr(prevViewProj));
    glUniformMatrix4fv(program_.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
    glUniform1f(program_.uniform("uDt"), dt);
    noise_.bind(program_, noise);
    glBindTextureUnit(0, prevFlow.id());
    surface.draw();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
}

}  // namespace flowsurf::methods::ibfvs
