#include "methods/hybrid/particle_tracing.h"

#include "methods/common/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace flowsurf::methods::hybrid {

ParticleTracing::ParticleTracing(const HybridParams& params)
    : defines_("#define KERNEL " + std::to_string(int(params.kernel)) + "\n#define INTEGRATOR " +
               std::to_string(int(params.integrator)) + "\n"),
      steady_(program({{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "hybrid/particle_tracing.frag"}},
              defines_)),
      emptyVao_(gl::VertexArray::create()) {}

void ParticleTracing::apply(const TracingInput& in, const HybridParams& params, const gl::Framebuffer& target) {
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, in.viewport.width, in.viewport.height);
    const float gray[4] = {core::kNoiseMean, 0, 0, 1};
    glClearNamedFramebufferfv(target.id(), GL_COLOR, 0, gray);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    const bool unsteady = in.velocityLevels != 0 && in.levelTimes.size() >= 2;
    if (unsteady && !unsteady_)
        unsteady_ = program({{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "hybrid/particle_tracing.frag"}},
                                defines_ + "#define UNSTEADY 1\n");
    const gl::Program& program = unsteady ? unsteady_ : steady_;
    program.use();
    const core::Camera& cam = in.camera;
    glm::mat4 viewProj = cam.viewProjection(in.viewport.aspect());
    glUniformMatrix4fv(program.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glUniform3fv(program.uniform("uEye"), 1, glm::value_ptr(cam.eye));
    glUniform1i(program.uniform("uOrtho"), cam.orthographic());
    glUniform4fv(program.uniform("uLayerDepthRow"), 1, glm::value_ptr(layerDepthRow(cam)));
    glUniform1i(program.uniform("uLineField"), in.lineField);
    glUniform1i(program.uniform("uHalfLength"), std::max(0, (params.filterLength - 1) / 2));
    // Size of a pixel in P-space: at distance d (perspective) it is d * pixelPerDist.
    const float pixelPerDist = 2.0f * std::tan(glm::radians(cam.fovDeg) * 0.5f) / float(in.viewport.height);
    const float pixelOrtho = cam.orthographic() ? cam.orthoHeight / float(in.viewport.height) : 0.0f;
    const float speed = std::max(in.speedRef, 1e-30f);
    glUniform1f(program.uniform("uStepPerDist"), in.stepPx * pixelPerDist / speed);
    glUniform1f(program.uniform("uStepOrtho"), in.stepPx * pixelOrtho / speed);
    // Texture coordinates per P-space unit so that one texel spans half the noise scale:
    // the blur and the lower octave make features about four texels wide.
    const float texel = 2.0f / float(in.noiseSize);
    glUniform1f(program.uniform("uFreqAtUnit"), cam.orthographic() ? texel / (in.noiseScalePx * pixelOrtho)
                                                                    : texel / (in.noiseScalePx * pixelPerDist));
    glUniform1f(program.uniform("uDepthTolerance"), params.depthTolerance);  // a fraction of the range, as w
    glBindTextureUnit(0, in.seeds->position().id());
    if (unsteady) {
        glBindTextureUnit(1, in.velocityLevels);
        glUniform1i(program.uniform("uLevelCount"), GLint(in.levelTimes.size()));
        glUniform1fv(program.uniform("uLevelTime"), GLsizei(in.levelTimes.size()), in.levelTimes.data());
        glUniform1f(program.uniform("uTimePerStep"), in.timePerStep);
        glUniform1f(program.uniform("uVelocityScale"), speed);
    } else {
        glBindTextureUnit(1, in.seeds->velocity().id());
    }
    glBindTextureUnit(3, in.noise);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace flowsurf::methods::hybrid
