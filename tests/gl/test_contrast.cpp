// Contrast enhancement [doc/contrast.md]: what a user relies on when turning
// it on, for every method on a small analytic scene (the spinning sphere at 160^2): the
// texture's contrast (std over the surface, the quality report's) at least doubles, its
// streaks keep their orientation (median error at most 0.5 degrees worse) and the animation
// its coherence (frame correlation at most 0.02 lower); the colour stretch widens the
// surface's lightness; the background is untouched; the same inputs give the same image.
#include "core/builtin_scenes.h"
#include "gl/readback.h"
#include "gl_test_util.h"
#include "methods/make_renderer.h"
#include "present/percentile_range.h"
#include "quality/quality_probe.h"
#include "raster/surface_gpu.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace flowsurf;

namespace {

constexpr core::Viewport kViewport{160, 160};

struct SphereRun {
    quality::FrameQuality q;
    test::Rendered image;
};

// Renders frames 0..`frames` of the sphere with `method` and measures the last frame (the
// one before kept for the correlations) with the quality report's probe.
SphereRun runSphere(const std::string& method, const methods::MethodParams& params, int frames) {
    core::Dataset data = core::makeBuiltin("builtin:sphere");
    const core::Camera cam = core::fitCamera(data.bounds(), kViewport, {0.3f, 0.4f, 1.0f});
    methods::SurfaceGpu surface(data.steps.front().mesh, "velocity", params.common);
    auto m = methods::makeMethod(method, params, kViewport);
    quality::QualityProbe probe(kViewport);
    SphereRun out;
    for (int k = 0; k <= frames; ++k) {
        m->renderFrame({&surface, cam, uint32_t(k)});
        if (k == frames - 1) probe.keep(*m, cam, uint32_t(k));
    }
    out.q = probe.measure(*m, surface, cam, uint32_t(frames));
    out.image = test::readBack(*m, kViewport);
    return out;
}

int framesFor(const std::string& method) { return method == "hybrid" ? 12 : 50; }

methods::MethodParams enhanced(methods::EnhanceContrast e) {
    methods::MethodParams p = test::testParams();
    p.common.enhanceContrast = e;
    return p;
}

// HSL lightness of the composite's surface pixels.
std::vector<float> surfaceLightness(const test::Rendered& r) {
    std::vector<float> l;
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            if (!r.onSurface(x, y)) continue;
            const uint8_t* c = &r.rgb[(size_t(r.height - 1 - y) * r.width + x) * 3];  // rgb rows top to bottom
            l.push_back(0.5f * float(std::max({c[0], c[1], c[2]}) + std::min({c[0], c[1], c[2]})) / 255.0f);
        }
    return l;
}

float percentile(std::vector<float> v, float p) {
    const size_t i = std::min(v.size() - 1, size_t(p / 100.0f * float(v.size())));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(i), v.end());
    return v[i];
}

class ContrastMethods : public ::testing::TestWithParam<std::string> {};

}  // namespace

// The percentiles of a histogram, by hand: 100 counts in bins 10..19 of 100 (10 each).
TEST(PercentileRange, HistogramPercentilesByHand) {
    std::vector<uint32_t> bins(100, 0);
    for (int b = 10; b < 20; ++b) bins[size_t(b)] = 10;
    const glm::vec2 r = methods::histogramPercentiles(bins, 5.0f);
    EXPECT_NEAR(r.x, 0.105f, 1e-6f);  // 5 of 100 counts: half of bin 10
    EXPECT_NEAR(r.y, 0.195f, 1e-6f);  // 95 of 100: half of bin 19
    const glm::vec2 all = methods::histogramPercentiles(bins, 0.0f);
    EXPECT_NEAR(all.x, 0.10f, 1e-6f);
    EXPECT_NEAR(all.y, 0.20f, 1e-6f);
    const glm::vec2 none = methods::histogramPercentiles(std::vector<uint32_t>(100, 0), 1.0f);
    EXPECT_GT(none.x, none.y);  // empty: no range
    // Smoothing over 4 frames moves a quarter of the way.
    const glm::vec2 s = methods::smoothRange({0.2f, 0.6f}, {0.4f, 1.0f}, 4.0f);
    EXPECT_NEAR(s.x, 0.25f, 1e-6f);
    EXPECT_NEAR(s.y, 0.7f, 1e-6f);
}

INSTANTIATE_TEST_SUITE_P(All, ContrastMethods, ::testing::Values("isa", "ibfvs", "hybrid"));

// Texture enhancement doubles the contrast at most 0.5 degrees off the field and 0.02 less
// coherent in time (doc/algorithms.md §9's criteria, as the quality report measures them).
TEST_P(ContrastMethods, TextureStretchDoublesContrastKeepingOrientationAndCoherence) {
    const std::string method = GetParam();
    const SphereRun off = runSphere(method, test::testParams(), framesFor(method));
    const SphereRun on = runSphere(method, enhanced(methods::EnhanceContrast::Texture), framesFor(method));
    std::printf("%s: contrast %.3f -> %.3f, orientation %.2f -> %.2f deg, correlation %.3f -> %.3f\n", method.c_str(),
                off.q.contrast, on.q.contrast, off.q.orientationErrorDeg, on.q.orientationErrorDeg,
                off.q.frameCorrelation, on.q.frameCorrelation);
    EXPECT_GE(on.q.contrast, 2.0 * off.q.contrast);
    EXPECT_LE(on.q.orientationErrorDeg, off.q.orientationErrorDeg + 0.5);
    EXPECT_GE(on.q.frameCorrelation, off.q.frameCorrelation - 0.02);
}

// The colour stretch widens the spread of the surface's lightness (5th to 95th percentile)
// and leaves the background's colour as it was.
TEST_P(ContrastMethods, ColorStretchWidensLightnessKeepsBackground) {
    const std::string method = GetParam();
    const SphereRun off = runSphere(method, test::testParams(), framesFor(method));
    const SphereRun on = runSphere(method, enhanced(methods::EnhanceContrast::Color), framesFor(method));
    const std::vector<float> a = surfaceLightness(off.image), b = surfaceLightness(on.image);
    const float spreadOff = percentile(a, 95) - percentile(a, 5), spreadOn = percentile(b, 95) - percentile(b, 5);
    std::printf("%s: lightness spread %.3f -> %.3f\n", method.c_str(), spreadOff, spreadOn);
    EXPECT_GT(spreadOn, 1.2f * spreadOff);
    const glm::vec3 bg = test::testParams().common.background;
    int background = 0;
    for (int y = 0; y < on.image.height; ++y)
        for (int x = 0; x < on.image.width; ++x) {
            if (on.image.onSurface(x, y)) continue;
            ++background;
            const uint8_t* c = &on.image.rgb[(size_t(on.image.height - 1 - y) * on.image.width + x) * 3];
            for (int i = 0; i < 3; ++i) ASSERT_NEAR(c[i], bg[i] * 255.0f, 1.0f) << x << "," << y;
        }
    EXPECT_GT(background, 1000);
}

// Same inputs, seed and frame count: the same image, with both stretches and their
// smoothing over frames.
TEST_P(ContrastMethods, Deterministic) {
    const std::string method = GetParam();
    const SphereRun a = runSphere(method, enhanced(methods::EnhanceContrast::Both), 6);
    const SphereRun b = runSphere(method, enhanced(methods::EnhanceContrast::Both), 6);
    EXPECT_EQ(a.image.flow, b.image.flow);
    EXPECT_EQ(a.image.rgb, b.image.rgb);
}
