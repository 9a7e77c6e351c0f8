#include "present/legend.h"

#include "present/colormap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace flowsurf::methods {

std::vector<double> niceTicks(double lo, double hi, int count) {
    std::vector<double> ticks;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) {
        if (std::isfinite(lo)) ticks.push_back(lo);
        return ticks;
    }
    const double raw = (hi - lo) / std::max(count - 1, 1);
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= raw * 0.999) { step = m * mag; break; }
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step)
        ticks.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
    // A range just over a step (-46 .. 43: step 50) would get one tick: ask for more.
    if (ticks.size() < 3 && count < 12) return niceTicks(lo, hi, count + 2);
    return ticks;
}

std::vector<double> logTicks(double lo, double hi, int count) {
    if (!(lo > 0.0) || !(hi > lo) || !std::isfinite(hi)) return niceTicks(lo, hi, count);
    const double eps = 1e-9;
    const int k0 = int(std::ceil(std::log10(lo) - eps)), k1 = int(std::floor(std::log10(hi) + eps));
    std::vector<double> ticks;
    if (k1 - k0 + 1 >= 2) {
        const int every = std::max(1, (k1 - k0 + count) / count);  // at most about count + 1 decades
        for (int k = k0; k <= k1; k += every) ticks.push_back(std::pow(10.0, k));
        return ticks;
    }
    for (int k = k0 - 1; k <= k1; ++k)
        for (double m : {1.0, 2.0, 5.0}) {
            const double t = m * std::pow(10.0, k);
            if (t >= lo * (1 - eps) && t <= hi * (1 + eps)) ticks.push_back(t);
        }
    return ticks.size() >= 2 ? ticks : niceTicks(lo, hi, count);
}

LegendScale legendScale(const CommonParams& params, glm::vec2 range, glm::vec2 dataRange) {
    LegendScale s;
    s.range = range;
    s.log = params.colorScale == ColorScale::Log && range.x > 0.0f;
    if (dataRange.x <= dataRange.y) {
        // Beyond by more than float rounding of the range's ends.
        const double tol = 1e-5 * std::max({std::abs(double(range.x)), std::abs(double(range.y)),
                                            double(range.y) - double(range.x)});
        s.below = double(dataRange.x) < double(range.x) - tol;
        s.above = double(dataRange.y) > double(range.y) + tol;
    }
    return s;
}

double legendPosition(const LegendScale& scale, double v) {
    const double lo = scale.log ? std::log10(double(scale.range.x)) : scale.range.x;
    const double hi = scale.log ? std::log10(double(scale.range.y)) : scale.range.y;
    const double x = scale.log ? std::log10(v) : v;
    return hi > lo ? (x - lo) / (hi - lo) : 0.5;
}

namespace {
std::string tickText(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}
}  // namespace

RgbImage makeLegendImage(const CommonParams& params, glm::vec2 range, const std::string& title, int imageHeight) {
    return makeLegendImage(params, legendScale(params, range, {1.0f, 0.0f}), title, imageHeight);
}

RgbImage makeLegendImage(const CommonParams& params, const LegendScale& scale, const std::string& title,
                         int imageHeight) {
    // (1) layout: bar half the image high, text sized to the image, an end triangle's room
    // above and below the bar
    const glm::vec2 range = scale.range;
    const int font = std::clamp(imageHeight / 32, 10, 28), pad = font / 2;
    const int barH = std::max(32, imageHeight / 2), barW = std::max(8, font);
    const int tri = barW * 3 / 4, gap = 2;
    const std::vector<double> ticks = scale.log ? logTicks(range.x, range.y) : niceTicks(range.x, range.y);
    int labelW = 0;
    for (double t : ticks) labelW = std::max(labelW, textWidth(tickText(t), font));
    const int titleW = textWidth(title, font);
    RgbImage img;
    img.channels = 4;
    img.width = std::max(barW + pad + font / 2 + labelW, titleW) + 2 * pad;
    img.height = barH + 2 * font + 2 * pad + 2 * (tri + gap);
    img.pixels.assign(size_t(img.width) * img.height * 4, 0);
    const float lum = 0.2126f * params.background.r + 0.7152f * params.background.g + 0.0722f * params.background.b;
    const uint8_t ink = lum > 0.5f ? 20 : 235;
    const uint8_t inkRgb[3] = {ink, ink, ink};
    auto put = [&](int x, int y, glm::vec3 c) {
        if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
        uint8_t* p = &img.pixels[(size_t(y) * img.width + x) * 4];
        for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
        p[3] = 255;
    };
    // (2) title, (3) bar with a one-pixel frame, top = range.y
    drawText(img, title, pad, pad + font, font, inkRgb);
    const int barX = pad, barY = pad + font + font / 2 + tri + gap;
    for (int y = 0; y < barH; ++y) {
        const glm::vec3 c = colormapAt(params, 1.0f - float(y) / float(barH - 1));
        for (int x = 0; x < barW; ++x) put(barX + x, barY + y, c);
    }
    const glm::vec3 inkC(ink / 255.0f);
    for (int x = -1; x <= barW; ++x) { put(barX + x, barY - 1, inkC); put(barX + x, barY + barH, inkC); }
    for (int y = -1; y <= barH; ++y) { put(barX - 1, barY + y, inkC); put(barX + barW, barY + y, inkC); }
    // (4) end triangles where values are clamped: filled with the end's colour, ink outline
    auto triangle = [&](int baseY, int dir, glm::vec3 fill) {  // dir -1: apex up, +1: apex down
        for (int i = 0; i <= tri; ++i) {
            const float half = 0.5f * float(barW + 1) * float(tri - i) / float(tri);
            const int y = baseY + dir * i;
            const int x0 = int(std::lround(barX - 0.5f + 0.5f * barW - half)), x1 = int(std::lround(barX - 0.5f + 0.5f * barW + half));
            for (int x = x0; x <= x1; ++x) put(x, y, x == x0 || x == x1 || i == 0 ? inkC : fill);
        }
    };
    if (scale.above) triangle(barY - 1 - gap, -1, colormapAt(params, 1.0f));
    if (scale.below) triangle(barY + barH + gap, +1, colormapAt(params, 0.0f));
    // (5) ticks and their labels
    for (double t : ticks) {
        const double f = legendPosition(scale, t);
        const int y = barY + int(std::lround((1.0 - f) * (barH - 1)));
        for (int x = barW; x < barW + font / 2; ++x) put(barX + x, y, inkC);
        drawText(img, tickText(t), barX + barW + font / 2 + 2, y + font * 2 / 5, font, inkRgb);
    }
    return img;
}

glm::ivec2 legendOrigin(const RgbImage& legend, int width, int height) {
    return {std::max(0, width - legend.width - 8), std::max(0, (height - legend.height) / 2)};
}

std::optional<glm::ivec2> freeLegendOrigin(const std::vector<float>& depth, int width, int height, glm::ivec2 size,
                                           std::optional<glm::ivec2> keep) {
    const int w = size.x, h = size.y, margin = 8;
    if (w + 2 > width || h + 2 > height || depth.size() < size_t(width) * size_t(height)) return std::nullopt;
    // (1) summed-area table of the surface pixels; the free margins left and right of them
    std::vector<int> sat(size_t(width + 1) * size_t(height + 1), 0);
    int minX = width, maxX = -1;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const bool on = depth[size_t(y) * width + x] < 1.0f;
            if (on) { minX = std::min(minX, x); maxX = std::max(maxX, x); }
            sat[size_t(y + 1) * (width + 1) + x + 1] = int(on) + sat[size_t(y) * (width + 1) + x + 1] +
                                                        sat[size_t(y + 1) * (width + 1) + x] - sat[size_t(y) * (width + 1) + x];
        }
    auto covered = [&](int x, int y) {
        if (x < 0 || y < 0 || x + w > width || y + h > height) return true;
        const size_t W = size_t(width + 1);
        return sat[size_t(y + h) * W + x + w] - sat[size_t(y) * W + x + w] - sat[size_t(y + h) * W + x] +
                   sat[size_t(y) * W + x] != 0;
    };
    if (keep && !covered(keep->x, keep->y)) return keep;
    // (2) the free place nearest the middle of the side with more room
    const bool right = width - 1 - maxX >= minX;
    const glm::ivec2 want(right ? std::max(0, width - w - margin) : std::min(margin, width - w), (height - h) / 2);
    if (!covered(want.x, want.y)) return want;
    std::optional<glm::ivec2> best;
    long bestScore = 0;
    for (int y = 0; y + h <= height; y += 4)
        for (int x = 0; x + w <= width; x += 4) {
            const long score = long(std::abs(x - want.x)) + long(std::abs(y - want.y));
            if ((best && score >= bestScore) || covered(x, y)) continue;
            best = glm::ivec2(x, y);
            bestScore = score;
        }
    return best;
}

}  // namespace flowsurf::methods
