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

namespace {

// The legend's image: transparent, drawn in the ink that reads on the background.
struct LegendCanvas {
    RgbImage img;
    uint8_t ink = 235;
    glm::vec3 inkC{235 / 255.0f};

    LegendCanvas(const CommonParams& params, int width, int height) {
        img.channels = 4;
        img.width = width;
        img.height = height;
        img.pixels.assign(size_t(width) * height * 4, 0);
        const float lum = 0.2126f * params.background.r + 0.7152f * params.background.g + 0.0722f * params.background.b;
        ink = lum > 0.5f ? 20 : 235;
        inkC = glm::vec3(ink / 255.0f);
    }
    void put(int x, int y, glm::vec3 c) {
        if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
        uint8_t* p = &img.pixels[(size_t(y) * img.width + x) * 4];
        for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
        p[3] = 255;
    }
    void text(const std::string& t, int x, int y, int font) {
        const uint8_t rgb[3] = {ink, ink, ink};
        drawText(img, t, x, y, font, rgb);
    }
    // a one-pixel frame around the w x h box at (x, y)
    void frame(int x0, int y0, int w, int h) {
        for (int x = -1; x <= w; ++x) { put(x0 + x, y0 - 1, inkC); put(x0 + x, y0 + h, inkC); }
        for (int y = -1; y <= h; ++y) { put(x0 - 1, y0 + y, inkC); put(x0 + w, y0 + y, inkC); }
    }
};

struct LegendText {
    int font, pad;
    std::vector<double> ticks;
    int labelW = 0, titleW = 0;
};

LegendText legendText(const LegendScale& scale, const std::string& title, int imageHeight) {
    LegendText t;
    t.font = std::clamp(imageHeight / 32, 10, 28);
    t.pad = t.font / 2;
    t.ticks = scale.log ? logTicks(scale.range.x, scale.range.y) : niceTicks(scale.range.x, scale.range.y);
    for (double v : t.ticks) t.labelW = std::max(t.labelW, textWidth(tickText(v), t.font));
    t.titleW = textWidth(title, t.font);
    return t;
}

// The bar along x: the title above, the ticks and labels below, an end triangle's room at
// either end; `length` the bar's in pixels.
RgbImage horizontalLegend(const CommonParams& params, const LegendScale& scale, const std::string& title,
                          int imageHeight, int length) {
    const LegendText t = legendText(scale, title, imageHeight);
    const int font = t.font, pad = t.pad;
    const int barW = std::max(48, length), barH = std::max(8, font);
    const int tri = barH * 3 / 4, gap = 2;
    const int side = std::max(tri + gap + 1, t.labelW / 2 + 1);  // an end triangle or half a label
    LegendCanvas c(params, std::max(barW + 2 * side, t.titleW) + 2 * pad, 2 * font + font / 2 + barH + font / 2 + 2 * pad + 2);
    // (1) title, (2) bar with a one-pixel frame, left = range.x
    c.text(title, pad, pad + font, font);
    const int barX = pad + side, barY = pad + font + font / 2;
    for (int x = 0; x < barW; ++x) {
        const glm::vec3 col = colormapAt(params, float(x) / float(barW - 1));
        for (int y = 0; y < barH; ++y) c.put(barX + x, barY + y, col);
    }
    c.frame(barX, barY, barW, barH);
    // (3) end triangles where values are clamped
    auto triangle = [&](int baseX, int dir, glm::vec3 fill) {  // dir -1: apex left, +1: apex right
        for (int i = 0; i <= tri; ++i) {
            const float half = 0.5f * float(barH + 1) * float(tri - i) / float(tri);
            const int x = baseX + dir * i;
            const int y0 = int(std::lround(barY - 0.5f + 0.5f * barH - half)), y1 = int(std::lround(barY - 0.5f + 0.5f * barH + half));
            for (int y = y0; y <= y1; ++y) c.put(x, y, y == y0 || y == y1 || i == 0 ? c.inkC : fill);
        }
    };
    if (scale.below) triangle(barX - 1 - gap, -1, colormapAt(params, 0.0f));
    if (scale.above) triangle(barX + barW + gap, +1, colormapAt(params, 1.0f));
    // (4) ticks below the bar, their labels centred under them
    for (double v : t.ticks) {
        const int x = barX + int(std::lround(legendPosition(scale, v) * (barW - 1)));
        for (int y = barH; y < barH + font / 2; ++y) c.put(x, barY + y, c.inkC);
        const std::string label = tickText(v);
        c.text(label, x - textWidth(label, font) / 2, barY + barH + font / 2 + font, font);
    }
    return std::move(c.img);
}

}  // namespace

RgbImage makeLegendImage(const CommonParams& params, const LegendScale& scale, const std::string& title,
                         int imageHeight, LegendLayout layout) {
    if (layout == LegendLayout::Horizontal) return horizontalLegend(params, scale, title, imageHeight, imageHeight * 2 / 3);
    // (1) layout: bar half the image high, text sized to the image, an end triangle's room
    // above and below the bar
    const LegendText t = legendText(scale, title, imageHeight);
    const int font = t.font, pad = t.pad;
    const int barH = std::max(32, imageHeight / 2), barW = std::max(8, font);
    const int tri = barW * 3 / 4, gap = 2;
    LegendCanvas c(params, std::max(barW + pad + font / 2 + t.labelW, t.titleW) + 2 * pad,
                   barH + 2 * font + 2 * pad + 2 * (tri + gap));
    // (2) title, (3) bar with a one-pixel frame, top = range.y
    c.text(title, pad, pad + font, font);
    const int barX = pad, barY = pad + font + font / 2 + tri + gap;
    for (int y = 0; y < barH; ++y) {
        const glm::vec3 col = colormapAt(params, 1.0f - float(y) / float(barH - 1));
        for (int x = 0; x < barW; ++x) c.put(barX + x, barY + y, col);
    }
    c.frame(barX, barY, barW, barH);
    // (4) end triangles where values are clamped: filled with the end's colour, ink outline
    auto triangle = [&](int baseY, int dir, glm::vec3 fill) {  // dir -1: apex up, +1: apex down
        for (int i = 0; i <= tri; ++i) {
            const float half = 0.5f * float(barW + 1) * float(tri - i) / float(tri);
            const int y = baseY + dir * i;
            const int x0 = int(std::lround(barX - 0.5f + 0.5f * barW - half)), x1 = int(std::lround(barX - 0.5f + 0.5f * barW + half));
            for (int x = x0; x <= x1; ++x) c.put(x, y, x == x0 || x == x1 || i == 0 ? c.inkC : fill);
        }
    };
    if (scale.above) triangle(barY - 1 - gap, -1, colormapAt(params, 1.0f));
    if (scale.below) triangle(barY + barH + gap, +1, colormapAt(params, 0.0f));
    // (5) ticks and their labels
    for (double v : t.ticks) {
        const double f = legendPosition(scale, v);
        const int y = barY + int(std::lround((1.0 - f) * (barH - 1)));
        for (int x = barW; x < barW + font / 2; ++x) c.put(barX + x, y, c.inkC);
        c.text(tickText(v), barX + barW + font / 2 + 2, y + font * 2 / 5, font);
    }
    return std::move(c.img);
}

glm::ivec2 legendOrigin(const RgbImage& legend, int width, int height) {
    return {std::max(0, width - legend.width - 8), std::max(0, (height - legend.height) / 2)};
}

std::optional<glm::ivec2> freeLegendOrigin(const std::vector<float>& depth, int width, int height, glm::ivec2 size,
                                           std::optional<glm::ivec2> keep, LegendLayout layout) {
    const int w = size.x, h = size.y, margin = 8;
    if (w + 2 > width || h + 2 > height || depth.size() < size_t(width) * size_t(height)) return std::nullopt;
    // (1) summed-area table of the surface pixels; the free margins left and right of them
    std::vector<int> sat(size_t(width + 1) * size_t(height + 1), 0);
    int minX = width, maxX = -1, minY = height, maxY = -1;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const bool on = depth[size_t(y) * width + x] < 1.0f;
            if (on) {
                minX = std::min(minX, x);
                maxX = std::max(maxX, x);
                minY = std::min(minY, y);
                maxY = std::max(maxY, y);
            }
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
    glm::ivec2 want;
    if (layout == LegendLayout::Vertical) {
        const bool right = width - 1 - maxX >= minX;
        want = {right ? std::max(0, width - w - margin) : std::min(margin, width - w), (height - h) / 2};
    } else {
        const bool bottom = minY >= height - 1 - maxY;  // GL rows: y = 0 is the bottom
        want = {(width - w) / 2, bottom ? std::min(margin, height - h) : std::max(0, height - h - margin)};
    }
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
