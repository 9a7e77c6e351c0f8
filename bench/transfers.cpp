#include "transfers.h"

#include "gl/objects.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace flowsurf::bench {

namespace {

struct LayerFormat {
    const char* name;
    GLenum internal, format, type;
    int bytesPerPixel;
};
constexpr LayerFormat kLayers[] = {
    {"RGBA32F", GL_RGBA32F, GL_RGBA, GL_FLOAT, 16},
    {"DEPTH32F", GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, 4},
    {"R32F", GL_R32F, GL_RED, GL_FLOAT, 4},
};

template <class F>
double medianMs(int repeats, F&& once) {
    std::vector<double> ms;
    once();  // warm-up: allocations, first-use paths
    for (int i = 0; i < repeats; ++i) {
        glFinish();
        const auto t0 = std::chrono::steady_clock::now();
        once();
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::nth_element(ms.begin(), ms.begin() + ptrdiff_t(ms.size() / 2), ms.end());
    return ms[ms.size() / 2];
}

}  // namespace

void runTransfers(const std::vector<core::Viewport>& sizes, int repeats) {
    std::printf("\nhost transfers (median of %d; GB/s = 1e9 bytes/s)\n", repeats);
    std::printf("%-11s %-9s %10s %12s %10s %12s %10s\n", "image", "layer", "MB", "read-back ms", "GB/s",
                "upload ms", "GB/s");
    for (const core::Viewport& v : sizes) {
        for (const LayerFormat& f : kLayers) {
            gl::Texture2D texture(f.internal, v.width, v.height, GL_NEAREST);
            const size_t bytes = size_t(v.width) * size_t(v.height) * size_t(f.bytesPerPixel);
            std::vector<unsigned char> host(bytes, 0);
            const double readMs = medianMs(repeats, [&] {
                glGetTextureSubImage(texture.id(), 0, 0, 0, 0, v.width, v.height, 1, f.format, f.type,
                                     GLsizei(bytes), host.data());
            });
            const double uploadMs = medianMs(repeats, [&] {
                glTextureSubImage2D(texture.id(), 0, 0, 0, v.width, v.height, f.format, f.type, host.data());
            });
            const double mb = double(bytes) / 1e6;
            char image[24];
            std::snprintf(image, sizeof image, "%dx%d", v.width, v.height);
            std::printf("%-11s %-9s %10.1f %12.3f %10.2f %12.3f %10.2f\n", image, f.name, mb, readMs,
                        mb / readMs, uploadMs, mb / uploadMs);
        }
    }
}

}  // namespace flowsurf::bench
