#include "methods/image_space/noise_injection.h"

#include "gpu/gpu_bindings.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace flowsurf::methods {

namespace {
// Cells beyond each image side: swept samples reach back one step (a few pixels); farther
// ones (edge advection points) read the border cells, which gray blending hides anyway.
constexpr int kMargin = 8;
}  // namespace

NoiseInjection::NoiseInjection(const CommonParams& params, const core::Viewport& viewport)
    : mode_(params.noiseInjection),
      sweepSamples_(std::clamp(int(std::ceil(params.stepPx / params.noise.scale)), 1, 8)),
      viewport_(viewport) {}

std::string NoiseInjection::defines() const {
    if (mode_ != NoiseInjectionMode::Swept) return "";
    return "#define NOISE_SWEPT " + std::to_string(sweepSamples_) + "\n";
}

void NoiseInjection::bind(const gl::Program& program, const NoiseStep& step) const {
    const core::NoiseParams& n = step.noise;
    if (phases_.id() == 0 || n.scale != phaseScale_ || n.seed != phaseSeed_) {
        // Cells i = floor(x / s - 0.5) for x in [0, width]: -1 .. width / s.
        const int w = int(std::ceil(viewport_.width / n.scale)) + 2 + 2 * kMargin;
        const int h = int(std::ceil(viewport_.height / n.scale)) + 2 + 2 * kMargin;
        std::vector<float> phi(size_t(w) * h);
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                phi[size_t(j) * w + i] = core::hashToUnit(core::hashCell(i - kMargin, j - kMargin, n.seed));
        phases_ = gl::Texture2D(GL_R32F, w, h, GL_NEAREST);
        glTextureSubImage2D(phases_.id(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, phi.data());
        // Beyond the margin (the noise history of ISA's edge fill reaches farther
        // upstream) the cells repeat: still random, unlike a clamped constant border.
        glTextureParameteri(phases_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTextureParameteri(phases_.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
        phaseScale_ = n.scale;
        phaseSeed_ = n.seed;
    }
    glUniform1ui(program.uniform("uFrame"), step.frame);
    glUniform1f(program.uniform("uAlpha"), step.alpha);
    glUniform1f(program.uniform("uScale"), n.scale);
    glUniform1f(program.uniform("uPeriod"), n.period);
    glUniform1i(program.uniform("uProfile"), int(n.profile));
    glUniform1f(program.uniform("uPhaseMargin"), float(kMargin));
    glBindTextureUnit(bindings::kNoisePhases, phases_.id());
}

}  // namespace flowsurf::methods
