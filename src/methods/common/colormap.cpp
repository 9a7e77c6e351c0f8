#include "methods/common/colormap.h"

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
        case Colormap::None: return glm::vec3(1.0f);
    }
    return glm::vec3(1.0f);
}

gl::Texture2D makeColormapTexture(Colormap map) {
    std::vector<uint8_t> texels(256 * 4);
    for (int i = 0; i < 256; ++i) {
        glm::vec3 c = colormapAt(map, float(i) / 255.0f);
        for (int k = 0; k < 3; ++k) texels[i * 4 + k] = uint8_t(std::lround(c[k] * 255.0f));
        texels[i * 4 + 3] = 255;
    }
    gl::Texture2D tex(GL_RGBA8, 256, 1, GL_LINEAR);
    glTextureSubImage2D(tex.id(), 0, 0, 0, 256, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    return tex;
}

}  // namespace flowsurf::methods
