#include "quality/structure_tensor.h"

#include <glm/gtc/constants.hpp>
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace flowsurf::quality {

namespace {

struct Tensor {
    double xx = 0, xy = 0, yy = 0;
};

int radiusFor(float sigmaPx) { return int(std::ceil(2.5f * sigmaPx)); }

// Gradient products at (x, y), or zero where a central difference would leave the surface.
Tensor gradientProducts(const SurfaceImage& r, int x, int y) {
    if (x < 1 || y < 1 || x >= r.width - 1 || y >= r.height - 1) return {};
    if (!r.onSurface(x - 1, y) || !r.onSurface(x + 1, y) || !r.onSurface(x, y - 1) || !r.onSurface(x, y + 1))
        return {};
    const double gx = 0.5 * (r.f(x + 1, y) - r.f(x - 1, y));
    const double gy = 0.5 * (r.f(x, y + 1) - r.f(x, y - 1));
    return {gx * gx, gx * gy, gy * gy};
}

Streak fromTensor(const Tensor& j) {
    // Dominant gradient angle; streaks run perpendicular to it.
    const double gradAngle = 0.5 * std::atan2(2 * j.xy, j.xx - j.yy);
    double a = std::fmod(gradAngle + glm::half_pi<double>() + glm::two_pi<double>(), glm::pi<double>());
    const double trace = j.xx + j.yy;
    const double diff = std::sqrt((j.xx - j.yy) * (j.xx - j.yy) + 4 * j.xy * j.xy);
    return {float(a), trace > 1e-20 ? float(std::min(1.0, diff / trace)) : 0.0f};
}

}  // namespace

Streak streakAt(const SurfaceImage& r, int x, int y, float sigmaPx) {
    const int rad = radiusFor(sigmaPx);
    Tensor j;
    for (int dy = -rad; dy <= rad; ++dy)
        for (int dx = -rad; dx <= rad; ++dx) {
            const Tensor g = gradientProducts(r, x + dx, y + dy);
            const double w = std::exp(-(dx * dx + dy * dy) / (2.0 * sigmaPx * sigmaPx));
            j.xx += w * g.xx;
            j.xy += w * g.xy;
            j.yy += w * g.yy;
        }
    return fromTensor(j);
}

std::vector<Streak> streakField(const SurfaceImage& r, float sigmaPx) {
    const int w = r.width, h = r.height, rad = radiusFor(sigmaPx);
    std::vector<double> kernel(size_t(2 * rad + 1));
    for (int i = -rad; i <= rad; ++i) kernel[size_t(i + rad)] = std::exp(-(i * i) / (2.0 * sigmaPx * sigmaPx));
    std::vector<Tensor> g(size_t(w) * h), rows(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) g[size_t(y) * w + x] = gradientProducts(r, x, y);
    // exp(-(dx^2 + dy^2) / 2s^2) = exp(-dx^2 / 2s^2) exp(-dy^2 / 2s^2): rows, then columns.
    auto blur = [&](const std::vector<Tensor>& in, std::vector<Tensor>& out, int stepX, int stepY) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                Tensor s;
                for (int i = -rad; i <= rad; ++i) {
                    const int px = x + i * stepX, py = y + i * stepY;
                    if (px < 0 || py < 0 || px >= w || py >= h) continue;
                    const Tensor& t = in[size_t(py) * w + px];
                    const double k = kernel[size_t(i + rad)];
                    s.xx += k * t.xx;
                    s.xy += k * t.xy;
                    s.yy += k * t.yy;
                }
                out[size_t(y) * w + x] = s;
            }
    };
    blur(g, rows, 1, 0);
    blur(rows, g, 0, 1);
    std::vector<Streak> out(g.size());
    std::transform(g.begin(), g.end(), out.begin(), fromTensor);
    return out;
}

float orientationErrorDeg(float a, float b) {
    float d = std::fmod(std::abs(a - b), glm::pi<float>());
    d = std::min(d, glm::pi<float>() - d);
    return glm::degrees(d);
}

}  // namespace flowsurf::quality
