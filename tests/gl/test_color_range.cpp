// Robust colour ranges on rendered images [docs/cfd.md, colour ranges]: a sphere coloured by its height with
// 0.1 % and 5 % outliers, and by a four-decade scalar. The measure of structure is the
// spread of hues over the surface pixels (viridis runs from purple, hue ~285 deg, to
// yellow, ~55 deg, monotonically; lighting and the texture change brightness, not hue).
#include "core/builtin_scenes.h"
#include "gl_test_util.h"
#include "methods/make_renderer.h"
#include "present/legend.h"
#include "raster/surface_gpu.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace flowsurf;

namespace {

float hash01(uint32_t i) {
    i ^= i >> 16; i *= 0x7feb352dU; i ^= i >> 15; i *= 0x846ca68bU; i ^= i >> 16;
    return float(i >> 8) / float(1u << 24);
}

// builtin:sphere with point scalar "s" = f(height): the height itself with `outliers` of
// the vertices at +-1e6, or 10^(2 (y + 1)) (1 .. 1e4, uniform in log over the area).
core::SurfaceMesh sphereWith(double outliers, bool decades) {
    core::SurfaceMesh m = core::makeBuiltin("builtin:sphere").steps.front().mesh;
    core::ScalarField s{"s", {}};
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const float y = m.positions[i].y;
        float v = decades ? std::pow(10.0f, 2.0f * (y + 1.0f)) : y;
        if (hash01(uint32_t(i)) < outliers) v = hash01(uint32_t(i) + 99991u) < 0.5f ? -1e6f : 1e6f;
        s.values.push_back(v);
    }
    m.scalars.push_back(s);
    return m;
}

struct Colored {
    double dominant = 1.0;  // share of the surface pixels in the most common 30-degree hue bin
    glm::vec2 range, dataRange;
};

Colored renderColored(const core::SurfaceMesh& mesh, const std::string& range, const std::string& scale = "linear") {
    methods::MethodParams p = test::testParams();
    p.common.colorBy = std::string("s");  // not = "s": GCC 12 -O2 gives a false -Wrestrict
    p.common.colorRangeAuto = range == "auto";
    p.common.colorRangeMode = range == "data" ? methods::RangeMode::Data : methods::RangeMode::Robust;
    p.common.colorScale = scale == "log" ? methods::ColorScale::Log : methods::ColorScale::Linear;
    const core::Viewport vp{160, 160};
    methods::SurfaceGpu surface(mesh, "velocity", p.common);
    auto m = methods::makeMethod("isa", p, vp);
    for (int k = 0; k <= 2; ++k) m->renderFrame({&surface, test::orthoFront(2.2f), uint32_t(k)});
    const test::Rendered r = test::readBack(*m, vp);
    std::vector<double> hues;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            if (!r.onSurface(x, vp.height - 1 - y)) continue;
            const uint8_t* c = &r.rgb[(size_t(y) * vp.width + x) * 3];
            const double R = c[0], G = c[1], B = c[2];
            const double mx = std::max({R, G, B}), mn = std::min({R, G, B}), d = mx - mn;
            if (mx < 8.0 || d < 0.15 * mx) continue;  // too dark or too gray for a hue
            double h = mx == R ? std::fmod((G - B) / d, 6.0) : mx == G ? (B - R) / d + 2.0 : (R - G) / d + 4.0;
            hues.push_back(std::fmod(h * 60.0 + 360.0, 360.0));
        }
    Colored out;
    out.range = surface.colorRange();
    out.dataRange = surface.colorDataRange();
    if (hues.size() < 100) return out;
    int bins[12] = {};
    for (double h : hues) ++bins[std::min(11, int(h / 30.0))];
    out.dominant = double(*std::max_element(bins, bins + 12)) / double(hues.size());
    return out;
}

}  // namespace

// 0.1 % and 5 % outliers at +-1e6: the data range paints one colour (most of the
// surface in one hue bin); the default, robust, spreads the bulk over the map as on the
// clean field, and the legend marks both ends as clamped.
TEST(ColorRange, RobustDefaultShowsStructureDespiteOutliers) {
    const Colored clean = renderColored(sphereWith(0.0, false), "robust");
    std::printf("clean: range %g:%g, most common hue bin %.2f of the surface\n", clean.range.x, clean.range.y,
                clean.dominant);
    EXPECT_LT(clean.dominant, 0.3);
    for (double fraction : {0.001, 0.05}) {
        const core::SurfaceMesh mesh = sphereWith(fraction, false);
        const Colored robust = renderColored(mesh, "robust"), data = renderColored(mesh, "data");
        std::printf("%.1f %% outliers: robust %g:%g most common hue bin %.2f; data %g:%g most common hue bin %.2f\n",
                    fraction * 100, robust.range.x, robust.range.y, robust.dominant, data.range.x, data.range.y,
                    data.dominant);
        EXPECT_GT(data.dominant, 0.7) << fraction;  // the outliers themselves and their triangles are the rest
        EXPECT_GT(data.dominant, 2.5 * robust.dominant) << fraction;
        EXPECT_LT(robust.dominant, 0.3) << fraction;
        const methods::LegendScale marks = methods::legendScale({}, robust.range, robust.dataRange);
        EXPECT_TRUE(marks.below && marks.above) << fraction;
    }
}

// Four decades (1 .. 1e4): the log scale spreads them over the map as the clean height
// does; the linear scale cannot (half the area is in the first tenth of its range). The
// clean height's legend has no end marks.
TEST(ColorRange, FourDecadesOnALogScale) {
    const core::SurfaceMesh mesh = sphereWith(0.0, true);
    const Colored log = renderColored(mesh, "robust", "log"), lin = renderColored(mesh, "robust");
    const Colored clean = renderColored(sphereWith(0.0, false), "robust");
    std::printf("4 decades: log %g:%g most common hue bin %.2f; linear %g:%g most common hue bin %.2f\n", log.range.x,
                log.range.y, log.dominant, lin.range.x, lin.range.y, lin.dominant);
    EXPECT_NEAR(log.range.x, 1.0f, 0.05f);
    EXPECT_NEAR(log.range.y, 1e4f, 500.0f);
    EXPECT_LT(log.dominant, 0.3);
    EXPECT_GT(lin.dominant, 1.5 * log.dominant);
    const methods::LegendScale marks = methods::legendScale({}, clean.range, clean.dataRange);
    EXPECT_FALSE(marks.below || marks.above);
}

// The legend never covers the surface [docs/cfd.md, colour ranges], at 420x315: the pixels it changes
// are background pixels only, and there are many of them. The sphere at the centre (the
// usual place at the right edge is free), shifted right (the legend moves to the left
// margin), filling the height with room only at the sides (the legend shrinks), wider than
// the image with room only above and below (the legend lies along the bottom), and filling
// the whole image (no legend at all).
TEST(LegendPlacement, NeverCoversTheSurfaceAt420x315) {
    methods::MethodParams p = test::testParams();
    p.common.colorBy = std::string("s");  // not = "s": GCC 12 -O2 gives a false -Wrestrict
    const core::Viewport vp{420, 315};
    struct View { const char* name; float shiftX, height, stretchX; bool room; };
    for (const View v : {View{"centred", 0.0f, 2.3f, 1.0f, true}, View{"shifted right", -0.9f, 2.3f, 1.0f, true},
                         View{"filling", -0.35f, 2.02f, 1.0f, true}, View{"wide", 0.0f, 3.2f, 2.2f, true},
                         View{"filling all", 0.0f, 1.0f, 1.0f, false}}) {
        core::SurfaceMesh mesh = sphereWith(0.0, false);
        for (glm::vec3& q : mesh.positions) q.x *= v.stretchX;
        core::Camera cam = test::orthoFront(v.height);
        cam.eye.x = cam.target.x = v.shiftX;  // the sphere appears right of the centre
        auto render = [&](bool legend) {
            methods::MethodParams q = p;
            q.common.legend = legend;
            methods::SurfaceGpu surface(mesh, "velocity", q.common);
            auto m = methods::makeMethod("isa", q, vp);
            for (int k = 0; k <= 2; ++k) m->renderFrame({&surface, cam, uint32_t(k)});
            return test::readBack(*m, vp);
        };
        const test::Rendered plain = render(false), withLegend = render(true);
        size_t onSurface = 0, off = 0;
        int minX = vp.width, maxX = -1;
        for (int y = 0; y < vp.height; ++y)
            for (int x = 0; x < vp.width; ++x) {
                const size_t i = (size_t(y) * vp.width + x) * 3;
                if (plain.rgb[i] == withLegend.rgb[i] && plain.rgb[i + 1] == withLegend.rgb[i + 1] &&
                    plain.rgb[i + 2] == withLegend.rgb[i + 2])
                    continue;
                (plain.onSurface(x, vp.height - 1 - y) ? onSurface : off)++;
                minX = std::min(minX, x);
                maxX = std::max(maxX, x);
            }
        int sMin = vp.width, sMax = -1;
        for (int y = 0; y < vp.height; ++y)
            for (int x = 0; x < vp.width; ++x)
                if (plain.onSurface(x, y)) { sMin = std::min(sMin, x); sMax = std::max(sMax, x); }
        std::printf("%s: surface x %d..%d; legend changed %zu background px (x %d..%d), %zu surface px\n", v.name,
                    sMin, sMax, off, minX, maxX, onSurface);
        EXPECT_EQ(onSurface, 0u) << v.name;
        if (v.room) {
            EXPECT_GT(off, 300u) << v.name;
        } else {
            EXPECT_EQ(off, 0u) << v.name;
        }
        if (std::string(v.name) == "wide") {
            EXPECT_GT(maxX - minX, 150) << "a horizontal legend";
        }
    }
}
