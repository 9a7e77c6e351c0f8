#include "methods/ibfvs/polygon_advection.h"

#include "methods/common/gl_path.h"
#include "methods/common/noise_injection.h"
#include "methods/common/resample.h"
#include "methods/common/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

namespace flowsurf::methods::ibfvs {

PolygonAdvection::PolygonAdvection(const core::Viewport& viewport, const CommonParams& common,
                                   std::initializer_list<FlowPingPong::Attachment> shared)
    : noise_(common, viewport),
      path_(resolveGlPath(common.glPath)),
      program_(program({{GL_VERTEX_SHADER, "ibfvs/polygon_advection.vert"}, {GL_FRAGMENT_SHADER, "ibfvs/polygon_advection.frag"}},
                       resampleDefine(common.resample) + noise_.defines() +
                           (path_ == GlPath::Compute ? "#define ADVECT_IN_COMPUTE 1\n" : ""))) {
    if (path_ != GlPath::Compute) return;
    advectProgram_ = program({{GL_COMPUTE_SHADER, "ibfvs/polygon_advection.comp"}},
                             resampleDefine(common.resample) + noise_.defines());
    texcoord_ = gl::Texture2D(GL_RG32F, viewport.width, viewport.height, GL_NEAREST);
    texcoordFbo_ = gl::Framebuffer::create();
    texcoordFbo_.attach(GL_COLOR_ATTACHMENT0 + outputs::kFlow, texcoord_);
    int colors = 1;
    for (const auto& [attachment, texture] : shared) {
        texcoordFbo_.attach(attachment, *texture);
        colors += attachment >= GL_COLOR_ATTACHMENT0 && attachment <= GL_COLOR_ATTACHMENT15;
    }
    texcoordFbo_.finish(colors);
}

void PolygonAdvection::apply(const SurfaceGpu& surface, const core::Camera& camera, const core::Camera& prevCamera,
                             const core::Viewport& viewport, float dt, const gl::Texture2D& prevFlow,
                             const gl::Texture2D& nextFlow, const gl::Framebuffer& nextFlowFbo,
                             const gl::Texture2D& depth, float flowBackground, bool cullBackFaces,
                             const NoiseStep& noise) const {
    program_.use();
    if (path_ != GlPath::Compute) {
        noise_.bind(program_, noise);
        glBindTextureUnit(bindings::kIbfvsPrevFlow, prevFlow.id());
        draw(surface, camera, prevCamera, viewport, dt, nextFlowFbo, flowBackground, cullBackFaces);
        return;
    }
    draw(surface, camera, prevCamera, viewport, dt, texcoordFbo_, flowBackground, cullBackFaces);
    advectProgram_.use();
    noise_.bind(advectProgram_, noise);
    glUniform1f(advectProgram_.uniform("uFlowBackground"), flowBackground);
    glBindTextureUnit(bindings::kIbfvsPrevFlow, prevFlow.id());
    glBindTextureUnit(bindings::kIbfvsTexcoord, texcoord_.id());
    glBindTextureUnit(bindings::kIbfvsDepth, depth.id());
    glBindImageTexture(bindings::kIbfvsNextFlow, nextFlow.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    dispatchPerPixel(viewport.width, viewport.height);
}

void PolygonAdvection::draw(const SurfaceGpu& surface, const core::Camera& camera, const core::Camera& prevCamera,
                            const core::Viewport& viewport, float dt, const gl::Framebuffer& target,
                            float flowBackground, bool cullBackFaces) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, viewport.width, viewport.height);
    // Gray background in F_a [L §IV-F.2]: what flows in from outside is the noise mean.
    const float bg[4] = {flowBackground, 0, 0, 1}, zero[4] = {0, 0, 0, 0}, one = 1.0f;
    glClearNamedFramebufferfv(target.id(), GL_COLOR, outputs::kFlow, bg);
    glClearNamedFramebufferfv(target.id(), GL_COLOR, outputs::kShade, zero);
    glClearNamedFramebufferfv(target.id(), GL_COLOR, outputs::kMask, zero);
    glClearNamedFramebufferfv(target.id(), GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    if (cullBackFaces) glEnable(GL_CULL_FACE);  // cost ~ N: halve it on closed surfaces
    else glDisable(GL_CULL_FACE);                // open surfaces are seen from both sides
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glm::mat4 view = camera.view();
    glm::mat4 viewProj = camera.projection(viewport.aspect()) * view;
    glm::mat4 prevViewProj = prevCamera.viewProjection(viewport.aspect());
    glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniformMatrix4fv(program_.uniform("uPrevViewProj"), 1, GL_FALSE, glm::value_ptr(prevViewProj));
    glUniformMatrix4fv(program_.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
    glUniform1f(program_.uniform("uDt"), dt);
    surface.draw();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
}

}  // namespace flowsurf::methods::ibfvs
