#include "methods/hybrid/particle_tracing.h"

#include "core/noise.h"
#include "gpu/shader_interface.h"
#include "methods/hybrid/solid_noise.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace flowsurf::methods::hybrid {

namespace {
// Compute work group: 8 x 8 pixels (llvmpipe runs 8 invocations per SIMD batch).
constexpr int kLocalX = 8, kLocalY = 8;
// Oriented LIC: I of the dark ground and of a full drop head, the noise mean -+ this: the
// overlay's default contrast (2.5 about the mean) shows them near black and white.
constexpr float kDropSpread = 0.18f;
}  // namespace

ParticleTracing::ParticleTracing(const HybridParams& params, GlPath path)
    : compute_(path == GlPath::Compute),
      defines_("#define KERNEL " + std::to_string(int(params.kernel)) + "\n#define INTEGRATOR " +
               std::to_string(int(params.integrator)) + "\n#define LOCAL_X " + std::to_string(kLocalX) +
               "\n#define LOCAL_Y " + std::to_string(kLocalY) + "\n" + SolidNoise::defines(params.noiseSize) +
               (params.oriented ? "#define ORIENTED 1\n#define DROP_SPREAD " + std::to_string(kDropSpread) + "\n"
                                : "")),
      emptyVao_(gl::VertexArray::create()) {
    programFor(false, false);  // the common variant, so that a shader error shows at construction
}

const gl::Program& ParticleTracing::programFor(bool unsteady, bool lineField) {
    gl::Program& p = programs_[unsteady][lineField];
    if (p) return p;
    const std::string defines =
        defines_ + (unsteady ? "#define UNSTEADY 1\n" : "") + "#define LINE_FIELD " + (lineField ? "1\n" : "0\n");
    if (compute_) p = program({{GL_COMPUTE_SHADER, "hybrid/particle_tracing.comp"}}, defines);
    else
        p = program({{GL_VERTEX_SHADER, "gpu/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "hybrid/particle_tracing.frag"}},
                    defines);
    return p;
}

void ParticleTracing::apply(const TracingInput& in, const HybridParams& params, const ColorTarget& target) {
    const bool unsteady = in.velocityLevels != 0 && in.levelTimes.size() >= 2;
    const gl::Program& program = programFor(unsteady, in.lineField);
    program.use();
    setUniforms(program, in, params);
    const PixelRect r = in.pixels.empty() ? PixelRect{0, 0, in.viewport.width, in.viewport.height} : in.pixels;
    if (compute_) {
        // Every pixel is written (the background with the noise mean): no clear.
        glUniform2i(program.uniform("uOrigin"), r.x0, r.y0);
        glUniform2i(program.uniform("uEnd"), r.x1, r.y1);
        glBindImageTexture(bindings::kLicImage, target.texture().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
        glDispatchCompute(GLuint((r.width() + kLocalX - 1) / kLocalX), GLuint((r.height() + kLocalY - 1) / kLocalY), 1);
        // The overlay samples I; tests and read-back fetch it.
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
        return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target.fbo().id());
    glViewport(0, 0, in.viewport.width, in.viewport.height);
    const bool part = !in.pixels.empty();
    if (part) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(r.x0, r.y0, r.width(), r.height());
    }
    const float gray[4] = {core::kNoiseMean, 0, 0, 1};
    glClearNamedFramebufferfv(target.fbo().id(), GL_COLOR, 0, gray);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (part) glDisable(GL_SCISSOR_TEST);
}

void ParticleTracing::setUniforms(const gl::Program& program, const TracingInput& in, const HybridParams& params) const {
    const core::Camera& cam = in.camera;
    // Clip coordinates to image texture coordinates after the divide: x, y -> (x + w) / 2.
    glm::mat4 toTexture(1.0f);
    toTexture[3] = glm::vec4(0.5f, 0.5f, 0.0f, 1.0f);
    toTexture[0][0] = toTexture[1][1] = 0.5f;
    const glm::mat4 texFromObj = toTexture * cam.viewProjection(in.viewport.aspect());
    glUniformMatrix4fv(program.uniform("uTexFromObj"), 1, GL_FALSE, glm::value_ptr(texFromObj));
    glUniform3fv(program.uniform("uEye"), 1, glm::value_ptr(cam.eye));
    glUniform1i(program.uniform("uOrtho"), cam.orthographic());
    glUniform4fv(program.uniform("uLayerDepthRow"), 1, glm::value_ptr(layerDepthRow(cam)));
    glUniform1i(program.uniform("uFilterLength"), std::max(1, params.filterLength));
    // Size of a pixel in P-space: at distance d (perspective) it is d * pixelPerDist.
    const float pixelPerDist = 2.0f * std::tan(glm::radians(cam.fovDeg) * 0.5f) / float(in.viewport.height);
    const float pixelOrtho = cam.orthographic() ? cam.orthoHeight / float(in.viewport.height) : 0.0f;
    const float speed = std::max(in.speedRef, 1e-30f);
    glUniform1f(program.uniform("uStepPerDist"), in.stepPx * pixelPerDist / speed);
    glUniform1f(program.uniform("uStepOrtho"), in.stepPx * pixelOrtho / speed);
    // Texture coordinates per P-space unit so that one texel spans half the noise scale:
    // the blur and the lower octave make features about four texels wide. Oriented LIC's
    // drops: one texel spans the noise scale, so a drop (about two texels) spans more
    // integration steps than one and its streak is not dotted at the step spacing.
    const float texel = (params.oriented ? 1.0f : 2.0f) / float(in.noiseSize);
    glUniform1f(program.uniform("uFreqAtUnit"), cam.orthographic() ? texel / (in.noiseScalePx * pixelOrtho)
                                                                    : texel / (in.noiseScalePx * pixelPerDist));
    glUniform1f(program.uniform("uDepthTolerance"), params.depthTolerance);  // a fraction of the range, as w
    if (params.oriented) {
        // A lone drop of the finer octave: two texels (blur and trilinear tent) of the noise
        // scale through its centre, about 0.7 of that where the surface cuts it off-centre,
        // in steps of stepPx; a typical head then shows near white.
        const float dropSamples = std::max(1.0f, 1.4f * in.noiseScalePx / in.stepPx);
        glUniform1f(program.uniform("uInvDropSamples"), 1.0f / dropSamples);
    }
    // The pixel rays (seedPosition in particle_tracing.glsl): the view's basis, scaled to
    // the image's half extent at unit distance (perspective) or in object units (ortho).
    const glm::vec3 forward = glm::normalize(cam.target - cam.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, cam.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float halfHeight = cam.orthographic() ? 0.5f * cam.orthoHeight : std::tan(glm::radians(cam.fovDeg) * 0.5f);
    const float halfWidth = halfHeight * in.viewport.aspect();
    glUniform3fv(program.uniform("uForward"), 1, glm::value_ptr(forward));
    glUniform3fv(program.uniform("uRayRight"), 1, glm::value_ptr(right * halfWidth));
    glUniform3fv(program.uniform("uRayUp"), 1, glm::value_ptr(up * halfHeight));
    glBindTextureUnit(bindings::kLicSeedVelocity, in.seedVelocity->id());
    const bool unsteady = in.velocityLevels != 0 && in.levelTimes.size() >= 2;
    if (unsteady) {
        glBindTextureUnit(bindings::kLicVelocity, in.velocityLevels);
        glUniform1i(program.uniform("uLevelCount"), GLint(in.levelTimes.size()));
        glUniform1fv(program.uniform("uLevelTime"), GLsizei(in.levelTimes.size()), in.levelTimes.data());
        glUniform1f(program.uniform("uTimePerStep"), in.timePerStep);
        glUniform1f(program.uniform("uVelocityScale"), speed);
    } else {
        glBindTextureUnit(bindings::kLicVelocity, in.seedVelocity->id());
    }
    glBindImageTexture(bindings::kLicNoise, in.noise, 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA8);
}

}  // namespace flowsurf::methods::hybrid
