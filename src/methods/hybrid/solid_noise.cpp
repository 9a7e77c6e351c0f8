#include "methods/hybrid/solid_noise.h"

#include "gpu/shader_interface.h"

namespace flowsurf::methods::hybrid {

namespace {
constexpr int kRows = 4;   // rows along x per invocation (solid_noise.comp's ROWS)
constexpr int kGroup = 8;  // its work group: kGroup x kGroup invocations (GROUP)
}  // namespace

std::string SolidNoise::defines(int size) {
    return "#define NOISE_SIZE " + std::to_string(size) + "\n#define NOISE_CODE " + std::to_string(kCode) + "\n";
}

SolidNoise::SolidNoise(int size, bool sparse)
    : size_(size),
      sparse_(sparse),
      program_(program({{GL_COMPUTE_SHADER, "hybrid/solid_noise.comp"}},
                       defines(size) + "#define ROWS " + std::to_string(kRows) + "\n#define GROUP " +
                           std::to_string(kGroup) + "\n" +
                           (sparse ? "#define SPARSE " + std::to_string(kSparseDensity) + "\n" : ""))) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    texture_ = gl::Handle<gl::detail::deleteTexture>(id);
    glTextureStorage3D(id, 1, GL_RGBA8, size, size, size);
}

void SolidNoise::update(uint32_t frame, const core::NoiseParams& params) {
    if (valid_ && frame == frame_) return;
    program_.use();
    glUniform1ui(program_.uniform("uFrame"), frame);
    glUniform1f(program_.uniform("uPeriod"), params.period);
    glUniform1i(program_.uniform("uProfile"), int(params.profile));
    glUniform1ui(program_.uniform("uSeed"), params.seed);
    // The RGBA8 texels written as 32-bit words (same size class).
    glBindImageTexture(bindings::kSolidNoiseImage, texture_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32UI);
    // One invocation per kRows rows along x at one depth.
    glDispatchCompute(GLuint((size_ / kRows + kGroup - 1) / kGroup), GLuint((size_ + kGroup - 1) / kGroup), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    valid_ = true;
    frame_ = frame;
}

std::vector<float> SolidNoise::values() const {
    std::vector<uint8_t> codes(size_t(size_) * size_ * size_ * 4);
    glGetTextureImage(texture_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(codes.size()), codes.data());
    std::vector<float> n(codes.size() / 4);
    for (size_t i = 0; i < n.size(); ++i)
        n[i] = sparse_ ? float(codes[4 * i]) / 255.0f : 0.5f + (float(codes[4 * i]) / 255.0f - 0.5f) / kCode;
    return n;
}

}  // namespace flowsurf::methods::hybrid
