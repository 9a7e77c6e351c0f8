#include "present/colormap.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace flowsurf::methods {

namespace {
// Published anchor colours, evenly spaced, interpolated linearly between them.
// viridis (matplotlib, van der Walt & Smith): 10 stops.
constexpr std::array<uint32_t, 10> kViridis = {0x440154, 0x482878, 0x3e4989, 0x31688e, 0x26828e,
                                              0x1f9e89, 0x35b779, 0x6ece58, 0xb5de2b, 0xfde725};
// Moreland's diverging cool-warm: blue, neutral, red.
constexpr std::array<uint32_t, 3> kCoolWarm = {0x3b4cc0, 0xdddddd, 0xb40426};
// plasma (matplotlib): 11 stops.
constexpr std::array<uint32_t, 11> kPlasma = {0x0d0887, 0x41049d, 0x6a00a8, 0x8f0da4, 0xb12a90, 0xcc4778,
                                             0xe16462, 0xf2844b, 0xfca636, 0xfcce25, 0xf0f921};

// Turbo (Mikhailov 2019): the published degree-5 polynomial fit per channel.
glm::vec3 turbo(float t) {
    const float x = std::clamp(t, 0.0f, 1.0f);
    const glm::vec4 v4(1.0f, x, x * x, x * x * x);
    const glm::vec2 v2 = glm::vec2(v4.z, v4.w) * v4.z;
    const glm::vec4 kr(0.13572138f, 4.61539260f, -42.66032258f, 132.13108234f);
    const glm::vec4 kg(0.09140261f, 2.19418839f, 4.84296658f, -14.18503333f);
    const glm::vec4 kb(0.10667330f, 12.64194608f, -60.58204836f, 110.36276771f);
    const glm::vec2 kr2(-152.94239396f, 59.28637943f), kg2(4.27729857f, 2.82956604f), kb2(-89.90310912f, 27.34824973f);
    return glm::clamp(glm::vec3(glm::dot(v4, kr) + glm::dot(v2, kr2), glm::dot(v4, kg) + glm::dot(v2, kg2),
                                glm::dot(v4, kb) + glm::dot(v2, kb2)),
                      0.0f, 1.0f);
}

// MATLAB's jet: dark blue, blue, cyan, yellow, red, dark red, piecewise linear.
glm::vec3 jet(float t) {
    const float x = std::clamp(t, 0.0f, 1.0f);
    auto ramp = [x](float centre) { return std::clamp(1.5f - 4.0f * std::abs(x - centre), 0.0f, 1.0f); };
    return {ramp(0.75f), ramp(0.5f), ramp(0.25f)};
}

glm::vec3 hexColor(uint32_t c) {
    return glm::vec3(float((c >> 16) & 255), float((c >> 8) & 255), float(c & 255)) / 255.0f;
}

template <size_t N>
glm::vec3 sample(const std::array<uint32_t, N>& stops, float t) {
    float x = std::clamp(t, 0.0f, 1.0f) * float(N - 1);
    size_t i = std::min(size_t(x), N - 2);
    return glm::mix(hexColor(stops[i]), hexColor(stops[i + 1]), x - float(i));
}
}  // namespace

glm::vec3 colormapAt(Colormap map, float t) {
    switch (map) {
        case Colormap::Viridis: return sample(kViridis, t);
        case Colormap::CoolWarm: return sample(kCoolWarm, t);
        case Colormap::Gray: return glm::vec3(std::clamp(t, 0.0f, 1.0f));
        case Colormap::Turbo: return turbo(t);
        case Colormap::Jet: return jet(t);
        case Colormap::Plasma: return sample(kPlasma, t);
        case Colormap::None: return glm::vec3(1.0f);
    }
    return glm::vec3(1.0f);
}

glm::vec3 colormapAt(const CommonParams& params, float t) {
    const auto& table = params.colormapTable;
    if (table.empty()) return colormapAt(params.colormap, t);
    float x = std::clamp(t, 0.0f, 1.0f) * float(table.size() - 1);
    size_t i = std::min(size_t(x), table.size() - 2);
    return glm::mix(table[i], table[i + 1], x - float(i));
}

gl::Texture2D makeColormapTexture(const CommonParams& params) {
    std::vector<uint8_t> texels(256 * 4);
    for (int i = 0; i < 256; ++i) {
        glm::vec3 c = colormapAt(params, float(i) / 255.0f);
        for (int k = 0; k < 3; ++k) texels[i * 4 + k] = uint8_t(std::lround(c[k] * 255.0f));
        texels[i * 4 + 3] = 255;
    }
    gl::Texture2D tex(GL_RGBA8, 256, 1, GL_LINEAR);
    glTextureSubImage2D(tex.id(), 0, 0, 0, 256, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    return tex;
}

}  // namespace flowsurf::methods
