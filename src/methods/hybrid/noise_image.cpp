#include "methods/hybrid/noise_image.h"

#include "methods/common/shader_interface.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace flowsurf::methods::hybrid {

namespace {
constexpr int kLocal = 8;  // work group: 8 x 8 pixels (noise_image.comp)
}  // namespace

NoiseImage::NoiseImage(const core::Viewport& viewport)
    : viewport_(viewport),
      image_(GL_R32F, 2 * viewport.width, 2 * viewport.height, GL_LINEAR),
      program_(program({{GL_COMPUTE_SHADER, "hybrid/noise_image.comp"}})) {}

void NoiseImage::render(const SurfaceGBuffer& seeds, GLuint noise, int noiseSize, const core::Camera& camera,
                        float noiseScalePx, float depthTolerance) {
    program_.use();
    glUniform3fv(program_.uniform("uEye"), 1, glm::value_ptr(camera.eye));
    glUniform1i(program_.uniform("uOrtho"), camera.orthographic());
    // Size of a pixel in P-space: at distance d (perspective) it is d * pixelPerDist.
    const float pixelPerDist = 2.0f * std::tan(glm::radians(camera.fovDeg) * 0.5f) / float(viewport_.height);
    const float pixelOrtho = camera.orthographic() ? camera.orthoHeight / float(viewport_.height) : 0.0f;
    // Texture coordinates per P-space unit so that one texel spans half the noise scale:
    // the blur and the lower octave make features about four texels wide.
    const float texel = 2.0f / float(noiseSize);
    glUniform1f(program_.uniform("uFreqAtUnit"), camera.orthographic() ? texel / (noiseScalePx * pixelOrtho)
                                                                       : texel / (noiseScalePx * pixelPerDist));
    glUniform4fv(program_.uniform("uLayerDepthRow"), 1, glm::value_ptr(layerDepthRow(camera)));
    glUniform1f(program_.uniform("uDepthTolerance"), depthTolerance);
    glBindTextureUnit(0, seeds.position().id());
    glBindTextureUnit(3, noise);
    glBindImageTexture(0, image_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glDispatchCompute(GLuint((viewport_.width + kLocal - 1) / kLocal), GLuint((viewport_.height + kLocal - 1) / kLocal), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the particle tracing samples it
}

}  // namespace flowsurf::methods::hybrid
