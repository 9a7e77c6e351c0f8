#include "methods/hybrid/solid_noise.h"

#include "methods/common/shader_interface.h"

namespace flowsurf::methods::hybrid {

SolidNoise::SolidNoise(int size) : size_(size), program_(program({{GL_COMPUTE_SHADER, "hybrid/solid_noise.comp"}})) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    texture_ = gl::Handle<gl::detail::deleteTexture>(id);
    glTextureStorage3D(id, 1, GL_R32F, size, size, size);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTextureParameteri(id, wrap, GL_REPEAT);
}

void SolidNoise::update(uint32_t frame, const core::NoiseParams& params) {
    if (valid_ && frame == frame_) return;
    program_.use();
    glUniform1i(program_.uniform("uSize"), size_);
    glUniform1ui(program_.uniform("uFrame"), frame);
    glUniform1f(program_.uniform("uPeriod"), params.period);
    glUniform1i(program_.uniform("uProfile"), int(params.profile));
    glUniform1ui(program_.uniform("uSeed"), params.seed);
    glBindImageTexture(0, texture_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    GLuint groups = GLuint((size_ + 7) / 8);  // one invocation per row along x (solid_noise.comp)
    glDispatchCompute(groups, groups, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    valid_ = true;
    frame_ = frame;
}

}  // namespace flowsurf::methods::hybrid
