// How far apart two rasterisers' per-pixel values of the same triangles may be (the GL draw
// and the compute raster's visibility buffer). GL leaves the sub-pixel precision to the
// implementation (GL_SUBPIXEL_BITS, at least 4): a driver snaps vertices to its grid and may
// set up the interpolation from the snapped positions, so at a pixel the two differ by what
// the value changes over a fraction of a pixel — nothing on a flat region, much near a
// silhouette, where depth and normals turn fast. The measure is that fraction: per pixel both
// cover, the difference beyond rounding over the reference's change per pixel towards its
// covered 4-neighbours; the largest over the image is the sub-pixel shift that explains every
// difference. What a real error does (half a pixel off, a wrong attribute or vertex) needs a
// shift of ≥ 0.1 px or none explains it (infinity).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace flowsurf::test {

// GL's coarsest allowed vertex grid (4 sub-pixel bits): a shift up to this is a difference of
// rasterisers, not of results.
inline constexpr float kRasterShiftPx = 1.0f / 16.0f;

// Per pixel: the reference and the other rasteriser both cover it.
inline std::vector<char> bothCover(const std::vector<float>& depthA, const std::vector<float>& depthB) {
    std::vector<char> both(depthA.size());
    for (size_t i = 0; i < both.size(); ++i) both[i] = depthA[i] < 1.0f && depthB[i] < 1.0f;
    return both;
}

// The sub-pixel shift that explains every difference of one channel (`channel` of
// `components` per pixel) beyond `rounding`; NaN equals NaN (an unset value in both).
inline float explainingShiftPx(const std::vector<float>& reference, const std::vector<float>& other, int components,
                               int channel, const std::vector<char>& covered, int width, int height, float rounding) {
    auto at = [&](const std::vector<float>& v, int x, int y) {
        return v[(size_t(y) * size_t(width) + size_t(x)) * size_t(components) + size_t(channel)];
    };
    float worst = 0.0f;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (!covered[size_t(y) * size_t(width) + size_t(x)]) continue;
            const float a = at(reference, x, y), b = at(other, x, y);
            if (std::isnan(a) || std::isnan(b)) {
                if (std::isnan(a) != std::isnan(b)) return std::numeric_limits<float>::infinity();
                continue;
            }
            const float excess = std::abs(a - b) - rounding;
            if (excess <= 0.0f) continue;
            float slope = 0.0f;
            const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
            for (int k = 0; k < 4; ++k) {
                if (nx[k] < 0 || ny[k] < 0 || nx[k] >= width || ny[k] >= height) continue;
                if (!covered[size_t(ny[k]) * size_t(width) + size_t(nx[k])]) continue;
                const float n = at(reference, nx[k], ny[k]);
                if (!std::isnan(n)) slope = std::max(slope, std::abs(n - a));
            }
            worst = std::max(worst, slope > 0.0f ? excess / slope : std::numeric_limits<float>::infinity());
        }
    return worst;
}

}  // namespace flowsurf::test
