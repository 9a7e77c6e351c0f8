// The hybrid's particle tracing as a compute pass (--gl-path compute) renders the images of
// the fragment pass: every kernel and integrator variant, steady and unsteady, perspective
// and orthographic, a line field; mean difference <= 1 gray level (the bound).
// Image sizes are not multiples of the 8 x 8 work group, so partial groups are covered.
#include "core/builtin_scenes.h"
#include "core/derived_fields.h"
#include "core/step_stream.h"
#include "gl_test_util.h"
#include "methods/make_renderer.h"
#include "raster/surface_gpu.h"
#include "raster/time_levels.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

using namespace flowsurf;

namespace {

struct Difference {
    double flowMean = 0;  // |I_compute - I_fragment| x 255, mean over the surface pixels
    double flowMax = 0;   // the same, worst pixel of the image
    double rgbMean = 0;   // composite, gray levels per channel, mean over the image
    size_t surfacePixels = 0;
};

Difference compare(const test::Rendered& a, const test::Rendered& b) {
    Difference d;
    for (size_t i = 0; i < a.flow.size(); ++i) {
        const double e = 255.0 * std::abs(double(a.flow[i]) - double(b.flow[i]));
        d.flowMax = std::max(d.flowMax, e);
        if (a.depth[i] >= 1.0f) continue;
        d.flowMean += e;
        ++d.surfacePixels;
    }
    d.flowMean /= double(std::max<size_t>(d.surfacePixels, 1));
    for (size_t i = 0; i < a.rgb.size(); ++i) d.rgbMean += std::abs(int(a.rgb[i]) - int(b.rgb[i]));
    d.rgbMean /= double(a.rgb.size());
    return d;
}

// One frame (noise frame 7) of `mesh` with `field` through each path.
std::pair<test::Rendered, test::Rendered> bothPaths(const core::SurfaceMesh& mesh, const std::string& field,
                                                    methods::MethodParams p, const core::Viewport& vp,
                                                    const core::Camera& cam, const methods::TimeLevels* levels = nullptr) {
    methods::SurfaceGpu surface(mesh, field, p.common);
    auto render = [&](methods::GlPath path) {
        p.common.glPath = path;
        auto m = methods::makeMethod("hybrid", p, vp);
        m->renderFrame({&surface, cam, 7u, levels});
        return test::readBack(*m, vp);
    };
    return {render(methods::GlPath::Fragment), render(methods::GlPath::Compute)};
}

void expectSame(const Difference& d, const std::string& what) {
    std::printf("%s: |compute - fragment| mean %.4f, max %.3f gray levels (I); composite mean %.4f\n", what.c_str(),
                d.flowMean, d.flowMax, d.rgbMean);
    EXPECT_GT(d.surfacePixels, 1000u) << what;
    EXPECT_LE(d.flowMean, 1.0) << what;  // the bound: the same images
    EXPECT_LE(d.rgbMean, 1.0) << what;
    // A pixel whose particle the two compilations trace differently (arithmetic contracted
    // differently at an edge) may differ; a missing or misplaced pixel differs by about
    // the texture's contrast (~50 gray levels).
    EXPECT_LE(d.flowMax, 16.0) << what;
}

methods::MethodParams baseParams() {
    methods::MethodParams p;
    p.common.noise.seed = 11;
    p.hybrid.filterLength = 21;
    return p;
}

}  // namespace

using Variant = std::tuple<methods::LicKernel, methods::Integrator>;
class HybridGlPath : public ::testing::TestWithParam<Variant> {};
INSTANTIATE_TEST_SUITE_P(KernelsIntegrators, HybridGlPath,
                         ::testing::Combine(::testing::Values(methods::LicKernel::Box, methods::LicKernel::Exponential,
                                                              methods::LicKernel::Gaussian, methods::LicKernel::Hann),
                                            ::testing::Values(methods::Integrator::Euler, methods::Integrator::Rk2,
                                                              methods::Integrator::Rk4)),
                         [](const ::testing::TestParamInfo<Variant>& info) {
                             return std::string(methods::nameOf(methods::kKernelNames, std::get<0>(info.param))) +
                                    "_" + std::string(methods::nameOf(methods::kIntegratorNames, std::get<1>(info.param)));
                         });

// Steady flow: the spinning sphere in perspective (both noise octaves mixed per pixel).
TEST_P(HybridGlPath, SteadyPerspectiveSameImage) {
    core::Dataset d = core::makeBuiltin("builtin:sphere");
    methods::MethodParams p = baseParams();
    p.hybrid.kernel = std::get<0>(GetParam());
    p.hybrid.integrator = std::get<1>(GetParam());
    const core::Viewport vp{125, 117};
    const core::Camera cam = core::fitCamera(d.bounds(), vp, {0.3f, 0.4f, 1.0f});
    auto [fragment, compute] = bothPaths(d.steps[0].mesh, "velocity", p, vp, cam);
    expectSame(compare(fragment, compute), "sphere");
}

// Unsteady flow (pathlines through the velocity levels): the turning plane, orthographic.
TEST_P(HybridGlPath, UnsteadySameImage) {
    core::DatasetSteps steps(core::makeBuiltin("builtin:turning-plane"));
    core::StepStream stream(steps);
    methods::TimeLevelSource source(stream, "velocity");
    methods::MethodParams p = baseParams();
    p.hybrid.kernel = std::get<0>(GetParam());
    p.hybrid.integrator = std::get<1>(GetParam());
    const double t0 = 3.0, tau = 0.2;  // the field turns by ~20 degrees over the streak
    const methods::TimeLevels& levels = source.at(t0, tau, (p.hybrid.filterLength - 1) / 2);
    ASSERT_GE(levels.levels.size(), 2u);
    const core::Viewport vp{125, 117};
    auto [fragment, compute] = bothPaths(stream.meshAt(t0), "velocity", p, vp, test::orthoFront(2.2f), &levels);
    expectSame(compare(fragment, compute), "turning plane, unsteady");
}

// Orthographic view with an occluding edge (the particles' depth test) and a line field
// (principal curvature directions: each sample turned to the previous step).
TEST(HybridGlPathCases, OcclusionAndLineFieldSameImage) {
    methods::MethodParams p = baseParams();
    const core::Viewport vp{125, 117};
    core::Dataset planes = core::makeBuiltin("builtin:overlap-planes");
    auto [f1, c1] = bothPaths(planes.steps[0].mesh, "velocity", p, vp, test::orthoFront(2.2f));
    expectSame(compare(f1, c1), "overlapping planes");
    core::SurfaceMesh torus = core::makeTorus({0, 0, 0}, 1.0f, 0.4f, 96, 32);
    core::addDerivedField(torus, "curvature-max");
    auto [f2, c2] = bothPaths(torus, "curvature-max", p, vp,
                              core::fitCamera(torus.bounds(), vp, {0.2f, 0.9f, 0.4f}));
    expectSame(compare(f2, c2), "torus, curvature-max line field");
}
