#include "methods/common/noise_injection.h"

namespace flowsurf::methods {

NoiseInjection::NoiseInjection(NoiseInjectionMode mode)
    : program_({{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "common/noise_injection.frag"}},
               mode == NoiseInjectionMode::Swept ? "#define NOISE_SWEPT 1\n" : ""),
      emptyVao_(gl::VertexArray::create()) {}

void NoiseInjection::apply(const gl::Framebuffer& flowFbo, const gl::Texture2D& depth, const gl::Texture2D& motion,
                           uint32_t frame, float alpha, const core::NoiseParams& noise) const {
    glBindFramebuffer(GL_FRAMEBUFFER, flowFbo.id());
    glViewport(0, 0, depth.width(), depth.height());
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendColor(0, 0, 0, alpha);
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    program_.use();
    glUniform1ui(program_.uniform("uFrame"), frame);
    glUniform1f(program_.uniform("uScale"), noise.scale);
    glUniform1f(program_.uniform("uPeriod"), noise.period);
    glUniform1i(program_.uniform("uProfile"), noise.profile == core::NoiseProfile::Square ? 0 : 1);
    glUniform1ui(program_.uniform("uSeed"), noise.seed);
    glBindTextureUnit(0, depth.id());
    glBindTextureUnit(1, motion.id());
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_BLEND);
}

}  // namespace flowsurf::methods
