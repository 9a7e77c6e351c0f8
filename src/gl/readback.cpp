#include "gl/readback.h"

#include <algorithm>
#include <cmath>

namespace flowsurf::gl {

void waitForRendering() { glFinish(); }

std::vector<float> readRgbaFloat(const Texture2D& t) {
    std::vector<float> px(size_t(t.width()) * t.height() * 4);
    waitForRendering();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(t.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(px.size() * sizeof(float)), px.data());
    return px;
}

std::vector<float> readChannel(const Texture2D& t, int channel) {
    std::vector<float> rgba = readRgbaFloat(t), out(size_t(t.width()) * t.height());
    for (size_t i = 0; i < out.size(); ++i) out[i] = rgba[i * 4 + channel];
    return out;
}

std::vector<uint8_t> readRgb8TopDown(const Texture2D& t) {
    const int w = t.width(), h = t.height();
    std::vector<uint8_t> rgb(size_t(w) * h * 3), flipped(rgb.size());
    waitForRendering();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(t.id(), 0, GL_RGB, GL_UNSIGNED_BYTE, GLsizei(rgb.size()), rgb.data());
    for (int y = 0; y < h; ++y)
        std::copy_n(&rgb[size_t(h - 1 - y) * w * 3], size_t(w) * 3, &flipped[size_t(y) * w * 3]);
    return flipped;
}

std::vector<uint16_t> readGray16TopDown(const Texture2D& t) {
    const int w = t.width(), h = t.height();
    std::vector<float> g = readChannel(t, 0);
    std::vector<uint16_t> out(g.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float v = std::clamp(g[size_t(h - 1 - y) * w + x], 0.0f, 1.0f);
            out[size_t(y) * w + x] = uint16_t(std::lround(v * 65535.0f));
        }
    return out;
}

std::vector<float> readDepth(const Texture2D& t) {
    std::vector<float> d(size_t(t.width()) * t.height());
    waitForRendering();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(t.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(d.size() * sizeof(float)), d.data());
    return d;
}

}  // namespace flowsurf::gl
