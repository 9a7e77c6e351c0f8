#include "methods/hybrid/particle_tracing.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace flowsurf::methods::hybrid {

ParticleTracing::ParticleTracing()
    : program_({{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "hybrid/particle_tracing.frag"}}),
      emptyVao_(gl::VertexArray::create()) {}

void ParticleTracing::apply(const TracingInput& in, const HybridParams& params, const gl::Framebuffer& target) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, in.viewport.width, in.viewport.height);
    const float gray[4] = {0.5f, 0, 0, 1};
    glClearNamedFramebufferfv(target.id(), GL_COLOR, 0, gray);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    program_.use();
    const core::Camera& cam = in.camera;
    glm::mat4 viewProj = cam.viewProjection(in.viewport.aspect());
    glUniformMatrix4fv(program_.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniform3fv(program_.uniform("uEye"), 1, glm::value_ptr(cam.eye));
    glUniform1i(program_.uniform("uOrtho"), cam.orthographic());
    glUniform1f(program_.uniform("uNear"), cam.nearPlane);
    glUniform1f(program_.uniform("uFar"), cam.farPlane);
    glUniform1i(program_.uniform("uHalfLength"), std::max(0, (params.filterLength - 1) / 2));
    glUniform1i(program_.uniform("uKernel"), int(params.kernel));
    glUniform1i(program_.uniform("uIntegrator"), int(params.integrator));
    // Size of a pixel in P-space: at distance d (perspective) it is d * pixelPerDist.
    const float pixelPerDist = 2.0f * std::tan(glm::radians(cam.fovDeg) * 0.5f) / float(in.viewport.height);
    const float pixelOrtho = cam.orthographic() ? cam.orthoHeight / float(in.viewport.height) : 0.0f;
    const float speed = std::max(in.speedRef, 1e-30f);
    glUniform1f(program_.uniform("uStepPerDist"), in.stepPx * pixelPerDist / speed);
    glUniform1f(program_.uniform("uStepOrtho"), in.stepPx * pixelOrtho / speed);
    // Texture coordinates per P-space unit so that one texel spans half the noise scale:
    // the blur and the lower octave make features about four texels wide.
    const float texel = 2.0f / float(in.noiseSize);
    glUniform1f(program_.uniform("uFreqAtUnit"), cam.orthographic() ? texel / (in.noiseScalePx * pixelOrtho)
                                                                    : texel / (in.noiseScalePx * pixelPerDist));
    glUniform1f(program_.uniform("uDepthTolerance"), params.depthTolerance * (cam.farPlane - cam.nearPlane));
    glBindTextureUnit(0, in.seeds->position().id());
    glBindTextureUnit(1, in.seeds->velocity().id());
    glBindTextureUnit(2, in.seeds->depth().id());
    glBindTextureUnit(3, in.noise);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace flowsurf::methods::hybrid
