#include "methods/common/legend.h"

#include "methods/common/colormap.h"

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
    return ticks;
}

namespace {
std::string tickText(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}
}  // namespace

RgbImage makeLegendImage(const CommonParams& params, glm::vec2 range, const std::string& title, int imageHeight) {
    // (1) layout: bar half the image high, text sized to the image
    const int font = std::clamp(imageHeight / 32, 10, 28), pad = font / 2;
    const int barH = std::max(32, imageHeight / 2), barW = std::max(8, font);
    const std::vector<double> ticks = niceTicks(range.x, range.y);
    int labelW = 0;
    for (double t : ticks) labelW = std::max(labelW, textWidth(tickText(t), font));
    const int titleW = textWidth(title, font);
    RgbImage img;
    img.channels = 4;
    img.width = std::max(barW + pad + font / 2 + labelW, titleW) + 2 * pad;
    img.height = barH + 2 * font + 2 * pad;
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
    const int barX = pad, barY = pad + font + font / 2;
    for (int y = 0; y < barH; ++y) {
        const glm::vec3 c = colormapAt(params, 1.0f - float(y) / float(barH - 1));
        for (int x = 0; x < barW; ++x) put(barX + x, barY + y, c);
    }
    const glm::vec3 inkC(ink / 255.0f);
    for (int x = -1; x <= barW; ++x) { put(barX + x, barY - 1, inkC); put(barX + x, barY + barH, inkC); }
    for (int y = -1; y <= barH; ++y) { put(barX - 1, barY + y, inkC); put(barX + barW, barY + y, inkC); }
    // (4) ticks and their labels
    const double span = double(range.y) - double(range.x);
    for (double t : ticks) {
        const double f = span > 0.0 ? (t - range.x) / span : 0.5;
        const int y = barY + int(std::lround((1.0 - f) * (barH - 1)));
        for (int x = barW; x < barW + font / 2; ++x) put(barX + x, y, inkC);
        drawText(img, tickText(t), barX + barW + font / 2 + 2, y + font * 2 / 5, font, inkRgb);
    }
    return img;
}

glm::ivec2 legendOrigin(const RgbImage& legend, int width, int height) {
    return {std::max(0, width - legend.width - 8), std::max(0, (height - legend.height) / 2)};
}

}  // namespace flowsurf::methods
