// The compute path (--gl-path compute) renders the images of the fragment path: ISA's
// advection mesh, ISA's and IBFVS's texture advection with noise injection and the overlay
// in each colour scheme.
#include "core/builtin_scenes.h"
#include "gl_test_util.h"
#include "gpu/gl_path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace flowsurf;

namespace {

struct Difference {
    double meanGray = 0;  // composite, mean |a - b| over channels, gray levels
    int maxGray = 0;      // composite, worst channel
    double meanFlow = 0;  // F_a, mean |a - b|
};

Difference compare(const test::Rendered& a, const test::Rendered& b) {
    Difference d;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        const int e = std::abs(int(a.rgb[i]) - int(b.rgb[i]));
        d.meanGray += e;
        d.maxGray = std::max(d.maxGray, e);
    }
    d.meanGray /= double(a.rgb.size());
    for (size_t i = 0; i < a.flow.size(); ++i) d.meanFlow += std::abs(a.flow[i] - b.flow[i]);
    d.meanFlow /= double(a.flow.size());
    return d;
}

// `method` on the spinning tori (silhouettes, occluding edges) after 60 frames, both paths.
Difference renderBothPaths(const std::string& method, methods::MethodParams p) {
    core::Dataset data = core::makeBuiltin("builtin:tori");
    const core::Viewport vp{200, 150};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.2f, 0.6f, 1.0f});
    p.common.noise.seed = 3;
    p.common.glPath = methods::GlPath::Fragment;
    test::Rendered fragment = test::renderScene(data, method, p, vp, cam, 60);
    p.common.glPath = methods::GlPath::Compute;
    test::Rendered compute = test::renderScene(data, method, p, vp, cam, 60);
    EXPECT_EQ(fragment.depth, compute.depth);
    Difference d = compare(fragment, compute);
    std::printf("%s: compute vs fragment: composite mean %.4f, max %d gray levels; F_a mean %.2e\n", method.c_str(),
                d.meanGray, d.maxGray, d.meanFlow);
    return d;
}

}  // namespace

// The same image: mean <= 1 gray level. The passes compute the same arithmetic
// on the same inputs, so only the interpolation of the pixel warp's mesh coordinate (the
// rasteriser's vs a per-pixel expression) can round differently, and F_a carries such a
// difference along for ~1/alpha frames. Measured: identical images (0 gray levels).
class GlPathSameImage : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(Methods, GlPathSameImage, ::testing::Values("isa", "ibfvs", "hybrid"),
                         [](const auto& info) { return info.param; });

TEST_P(GlPathSameImage, DefaultOptions) {
    Difference d = renderBothPaths(GetParam(), methods::MethodParams{});
    EXPECT_LE(d.meanGray, 1.0);
}

// The paper's variants take the same road: bilinear resampling, point noise, gray edge fill,
// and ISA's mesh warp (a raster pass in both paths, with the compute path's overlay).
TEST_P(GlPathSameImage, PaperVariants) {
    methods::MethodParams p;
    p.common.resample = methods::Resample::Bilinear;
    p.common.noiseInjection = methods::NoiseInjectionMode::Point;
    p.isa.edgeFill = methods::EdgeFill::Gray;
    p.isa.warp = methods::IsaWarp::Mesh;
    p.isa.gridRes = 64;  // the grid draw costs ~ R^2 on llvmpipe
    Difference d = renderBothPaths(GetParam(), p);
    EXPECT_LE(d.meanGray, 1.0);
}

// The overlay's colour schemes, the texture mask and the legend.
TEST(GlPathSameImage, OverlaySchemes) {
    for (const auto& [scheme, name] : methods::kOverlayNames) {
        methods::MethodParams p;
        p.common.overlay = scheme;
        p.common.velocityMask = true;
        p.common.legend = true;
        std::printf("overlay %s\n", std::string(name).c_str());
        Difference d = renderBothPaths("isa", p);
        EXPECT_LE(d.meanGray, 1.0) << name;
    }
}

// `auto` picks per renderer from one table; what it picks on this machine is one of the two.
TEST(GlPathSameImage, AutoResolvesToAPath) {
    const methods::GlPath path = methods::resolveGlPath(methods::GlPath::Auto);
    EXPECT_NE(path, methods::GlPath::Auto);
    EXPECT_EQ(methods::resolveGlPath(methods::GlPath::Compute), methods::GlPath::Compute);
    EXPECT_EQ(methods::resolveGlPath(methods::GlPath::Fragment), methods::GlPath::Fragment);
}
