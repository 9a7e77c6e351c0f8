// Robust colour and mask ranges [docs/cfd.md, colour ranges]: the rule on generated values (clean, 0.1 % and
// 5 % outliers, four decades), area weights, a series summed a step at a time, the option
// rows, the log scale's refusals and the legend's ticks and end marks.
#include "core/errors.h"
#include "core/value_range.h"
#include "present/legend.h"
#include "raster/surface_gpu.h"
#include "session/options/options.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using namespace flowsurf;

namespace {

// A deterministic value in [0, 1) per index (our own hash, as the noise does).
float hash01(uint32_t i) {
    i ^= i >> 16; i *= 0x7feb352dU; i ^= i >> 15; i *= 0x846ca68bU; i ^= i >> 16;
    return float(i >> 8) / float(1u << 24);
}

// A bulk uniform in [-1, 1] with `fraction` of the values replaced by +-1e6 outliers.
std::vector<float> bulkWithOutliers(size_t n, double fraction) {
    std::vector<float> v(n);
    for (size_t i = 0; i < n; ++i) {
        v[i] = 2.0f * (float(i) + 0.5f) / float(n) - 1.0f;
        if (hash01(uint32_t(i)) < fraction) v[i] = hash01(uint32_t(i) + 77777u) < 0.5f ? -1e6f : 1e6f;
    }
    return v;
}

core::ValueDistribution distributionOf(const std::vector<float>& v) {
    core::ValueDistribution d;
    d.add(v);
    return d;
}

}  // namespace

// A clean field keeps its whole range: a uniform ramp's fences lie outside its ends.
TEST(RobustRange, CleanFieldKeepsItsDataRange) {
    const core::ValueDistribution d = distributionOf(bulkWithOutliers(100000, 0.0));
    const glm::vec2 r = core::robustRange(d), all = core::dataRange(d);
    EXPECT_FLOAT_EQ(r.x, all.x);
    EXPECT_FLOAT_EQ(r.y, all.y);
}

// 0.1 % and 5 % of outliers at +-1e6 (the data range is then 2e6 wide, the bulk 2): the
// robust range stays on the bulk, [-1, 1], to within the quantile summary's rank error.
TEST(RobustRange, OutliersLeaveTheBulk) {
    for (double fraction : {0.001, 0.05}) {
        const core::ValueDistribution d = distributionOf(bulkWithOutliers(200000, fraction));
        const glm::vec2 r = core::robustRange(d), all = core::dataRange(d);
        std::printf("%.1f %% outliers: data %g:%g, robust %g:%g\n", fraction * 100, all.x, all.y, r.x, r.y);
        EXPECT_EQ(all.x, -1e6f);
        EXPECT_EQ(all.y, 1e6f);
        EXPECT_NEAR(r.x, -1.0f, 0.01f) << fraction;
        EXPECT_NEAR(r.y, 1.0f, 0.01f) << fraction;
    }
}

// Four decades, log-uniform in [1, 1e4]: in log10 the quartiles are 1 and 3, the fences -2
// and 6, so the log range is the data's; the linear one clips the long upper tail at
// Q3 + 1.5 IQR = 1000 + 1.5 * 990.
// (With outliers at +-1e6 the range above is the bulk's own ends, not the fences +-2:
// the whiskers stop at the most extreme values inside the fences.)
TEST(RobustRange, FourDecadesInLogAndLinear) {
    std::vector<float> v(100000);
    for (size_t i = 0; i < v.size(); ++i) v[i] = float(std::pow(10.0, 4.0 * (double(i) + 0.5) / double(v.size())));
    const core::ValueDistribution d = distributionOf(v);
    const glm::vec2 log = core::robustRange(d, true), lin = core::robustRange(d, false);
    EXPECT_NEAR(log.x, 1.0f, 1e-3f);
    EXPECT_NEAR(log.y, 1e4f, 1.0f);
    EXPECT_NEAR(lin.x, 1.0f, 1e-3f);
    EXPECT_NEAR(lin.y, 2485.0f, 15.0f);
    // A quarter of the area not positive: no log range shows the bulk.
    for (size_t i = 0; i < v.size() / 3; ++i) v[i] = -v[i];
    EXPECT_GT(core::robustRange(distributionOf(v), true).x, core::robustRange(distributionOf(v), true).y);
}

// Half the area one value (IQR 0): the 1st-99th percentiles, not a flat range.
TEST(RobustRange, DegenerateQuartilesFallBackToPercentiles) {
    std::vector<float> v(10000, 0.0f);
    for (size_t i = 0; i < 2000; ++i) v[i] = float(i + 1);
    const glm::vec2 r = core::robustRange(distributionOf(v));
    EXPECT_EQ(r.x, 0.0f);
    EXPECT_NEAR(r.y, 1900.0f, 5.0f);  // 10000 values are summarised in kPoints: rank error
}

// Weights are areas: value 10 on a quarter of the area and 0 on the rest has median 0
// whatever the counts; a mesh's vertex areas sum to its area.
TEST(RobustRange, AreaWeightsAndVertexAreas) {
    core::ValueDistribution d;
    const std::vector<float> values{0.0f, 10.0f}, weights{3.0f, 1.0f};
    d.add(values, weights);
    EXPECT_FLOAT_EQ(d.quantile(0.5), 0.0f);
    core::SurfaceMesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {2, 3, 0}};
    m.triangles = {{0, 1, 2}, {1, 3, 2}};
    const std::vector<float> a = core::vertexAreas(m);
    EXPECT_FLOAT_EQ(a[0] + a[1] + a[2] + a[3], 6.0f);
    EXPECT_FLOAT_EQ(a[0], 1.0f);
    EXPECT_FLOAT_EQ(a[1], 2.0f);
}

// A series added a step at a time (each step summarised to kPoints) gives the quantiles
// of all its values at once.
TEST(RobustRange, SeriesStepByStepMatchesAllAtOnce) {
    std::vector<float> all;
    core::ValueDistribution steps;
    for (int s = 0; s < 40; ++s) {
        std::vector<float> v = bulkWithOutliers(20000, 0.02);
        for (float& x : v) x += 0.05f * float(s);
        steps.add(v);
        all.insert(all.end(), v.begin(), v.end());
    }
    const core::ValueDistribution once = distributionOf(all);
    for (double q : {0.01, 0.25, 0.5, 0.75, 0.99})
        EXPECT_NEAR(steps.quantile(q), once.quantile(q), 0.01 + 1e-6 * std::abs(once.quantile(q))) << q;
    // The whiskers' ends are single values, resolved to the summary's rank step: within
    // 2.5 % of the bulk's width.
    EXPECT_NEAR(core::robustRange(steps).x, core::robustRange(once).x, 0.05);
    EXPECT_NEAR(core::robustRange(steps).y, core::robustRange(once).y, 0.05);
}

// The option rows: robust is the default; data, auto and MIN:MAX read back; the mask too.
TEST(RangeOptions, ColorAndMaskRangeRows) {
    session::RenderOptions o;
    EXPECT_EQ(session::findOption("color-range")->get(o), "robust");
    EXPECT_EQ(session::findOption("mask-range")->get(o), "robust");
    EXPECT_EQ(session::findOption("color-scale")->get(o), "linear");
    for (const char* v : {"data", "auto", "robust", "-2:3.5"}) {
        session::setOption(o, "color-range", v);
        EXPECT_EQ(session::findOption("color-range")->get(o), v);
        session::setOption(o, "mask-range", v);
        EXPECT_EQ(session::findOption("mask-range")->get(o), v);
    }
    session::setOption(o, "color-range", "data");
    EXPECT_EQ(o.params.common.colorRangeMode, methods::RangeMode::Data);
    EXPECT_THROW(session::setOption(o, "color-range", "robustly"), ConfigError);
    EXPECT_THROW(session::setOption(o, "color-scale", "ln"), ConfigError);
}

// A log scale refuses ranges that are not positive, naming the option and the value.
TEST(RangeOptions, LogScaleRefusesNonPositiveRanges) {
    session::RenderOptions o;
    o.input = "builtin:sphere";
    session::setOption(o, "color-scale", "log");
    session::setOption(o, "color-range", "-1:5");
    try {
        session::validateRenderOptions(o);
        ADD_FAILURE() << "no error";
    } catch (const ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("--color-scale log: --color-range -1:5"), std::string::npos) << e.what();
    }
    // From the data: a scalar that is negative on most of the surface.
    methods::CommonParams p;
    p.colorBy = "p";
    p.colorScale = methods::ColorScale::Log;
    methods::StatisticsSamples s;
    s.color = bulkWithOutliers(1000, 0.0);  // -1 .. 1
    for (methods::RangeMode mode : {methods::RangeMode::Robust, methods::RangeMode::Data}) {
        p.colorRangeMode = mode;
        methods::RangeAccumulator acc(p);
        acc.add(s);
        try {
            acc.colorRange();
            ADD_FAILURE() << "no error";
        } catch (const ConfigError& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("--color-scale log: 'p' is not positive"), std::string::npos) << m;
            EXPECT_NE(m.find("data range -0.999:0.999"), std::string::npos) << m;
        }
    }
    // Positive values: a log range.
    for (float& x : s.color) x = std::pow(10.0f, 2.0f * (x + 1.0f));
    p.colorRangeMode = methods::RangeMode::Robust;
    methods::RangeAccumulator acc(p);
    acc.add(s);
    EXPECT_NEAR(acc.colorRange().x, 1.0f, 0.01f);
    EXPECT_NEAR(acc.colorRange().y, 1e4f, 100.0f);
}

// Ticks: decades on a log scale, 1-2-5 within one decade; a tick's place on the bar.
TEST(LegendScale, LogTicksAndPositions) {
    EXPECT_EQ(methods::logTicks(1.0, 1e4), (std::vector<double>{1, 10, 100, 1000, 1e4}));
    EXPECT_EQ(methods::logTicks(0.3, 7.0), (std::vector<double>{0.5, 1, 2, 5}));
    const std::vector<double> many = methods::logTicks(1e-6, 1e6);
    EXPECT_LE(many.size(), 7u);
    EXPECT_DOUBLE_EQ(many.front(), 1e-6);
    methods::LegendScale s;
    s.range = {1.0f, 1e4f};
    s.log = true;
    EXPECT_NEAR(methods::legendPosition(s, 100.0), 0.5, 1e-6);
    s.log = false;
    EXPECT_NEAR(methods::legendPosition(s, 5000.5), 0.5, 1e-6);
}

// End marks: drawn exactly where the data goes beyond the range, in the end's colour.
TEST(LegendScale, EndTrianglesMarkClampedEnds) {
    methods::CommonParams p;
    methods::LegendScale both = methods::legendScale(p, {-1.0f, 1.0f}, {-1e6f, 1e6f});
    EXPECT_TRUE(both.below);
    EXPECT_TRUE(both.above);
    methods::LegendScale none = methods::legendScale(p, {-1.0f, 1.0f}, {-1.0f, 1.0f});
    EXPECT_FALSE(none.below);
    EXPECT_FALSE(none.above);
    methods::LegendScale top = methods::legendScale(p, {-1.0f, 1.0f}, {-0.5f, 3.0f});
    EXPECT_FALSE(top.below);
    EXPECT_TRUE(top.above);
    // Pixels of the end colours outside the bar's rows: there with marks, absent without.
    auto endColourPixels = [&](const methods::LegendScale& s) {
        const methods::RgbImage img = methods::makeLegendImage(p, s, "p", 480);
        const methods::RgbImage plain = methods::makeLegendImage(p, none, "p", 480);
        EXPECT_EQ(img.width, plain.width);
        EXPECT_EQ(img.height, plain.height);  // room is kept either way
        int above = 0, below = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const uint8_t* a = &img.pixels[(size_t(y) * img.width + x) * 4];
                const uint8_t* b = &plain.pixels[(size_t(y) * img.width + x) * 4];
                if (a[3] && !b[3]) (y < img.height / 2 ? above : below)++;
            }
        return std::make_pair(above, below);
    };
    const auto b = endColourPixels(both), t = endColourPixels(top), n = endColourPixels(none);
    std::printf("end-mark pixels (above, below): both %d,%d top %d,%d none %d,%d\n", b.first, b.second, t.first,
                t.second, n.first, n.second);
    EXPECT_GT(b.first, 30);
    EXPECT_GT(b.second, 30);
    EXPECT_GT(t.first, 30);
    EXPECT_EQ(t.second, 0);
    EXPECT_EQ(n.first + n.second, 0);
}
