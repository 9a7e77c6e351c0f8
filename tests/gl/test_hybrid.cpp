// Hybrid physical/device-space LIC [W]: the properties its users rely on.
#include "core/builtin_scenes.h"
#include "gl/readback.h"
#include "gl_test_util.h"
#include "methods/hybrid/hybrid_renderer.h"
#include "methods/make_renderer.h"
#include "raster/surface_gpu.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

using namespace flowsurf;

namespace {

methods::MethodParams hybridParams() {
    methods::MethodParams p;
    p.common.noise.seed = 3;
    return p;
}


}  // namespace

// Spinning sphere: streak orientation matches the projected field, median error <= 5 deg.
namespace {
// Median streak orientation error on the spinning sphere (256^2, perspective) against the
// projected rotation field.
float sphereOrientationError(const methods::MethodParams& p) {
    core::Dataset d = core::makeBuiltin("builtin:sphere");
    const core::Viewport vp{256, 256};
    core::Camera cam = core::fitCamera(d.bounds(), vp, {0.3f, 0.4f, 1.0f});
    test::Rendered r = test::renderScene(d, "hybrid", p, vp, cam, 0);
    const glm::vec3 w = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    const glm::mat4 invVP = glm::inverse(cam.viewProjection(vp.aspect()));
    std::vector<float> errors;
    for (int y = 8; y < vp.height - 8; y += 5)
        for (int x = 8; x < vp.width - 8; x += 5) {
            if (!r.onSurface(x, y)) continue;
            float depth = r.depth[size_t(y) * vp.width + x];
            glm::vec4 h = invVP * glm::vec4((x + 0.5f) / vp.width * 2 - 1, (y + 0.5f) / vp.height * 2 - 1, depth * 2 - 1, 1);
            glm::vec3 p = glm::vec3(h) / h.w;
            if (glm::dot(glm::normalize(p), glm::normalize(cam.eye - p)) < 0.4f) continue;
            glm::vec3 v = glm::cross(w, p);
            if (glm::length(v) < 0.3f) continue;  // near the rotation poles
            glm::vec2 vPx = glm::vec2(core::projectToPixels(cam, vp, p + 0.01f * v) - core::projectToPixels(cam, vp, p));
            float expected = std::fmod(std::atan2(vPx.y, vPx.x) + glm::two_pi<float>(), glm::pi<float>());
            errors.push_back(test::orientationErrorDeg(test::streakOrientation(r, x, y, 4.0f), expected));
        }
    EXPECT_GT(errors.size(), 200u);
    if (errors.empty()) return 90.0f;
    std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
    return errors[errors.size() / 2];
}
}  // namespace

TEST(Hybrid, SphereOrientationMatchesProjectedField) {
    float median = sphereOrientationError(hybridParams());
    std::printf("hybrid: median orientation error %.2f deg\n", median);
    EXPECT_LE(median, 5.0f);
}

// Every kernel and integrator is its own shader variant: each must trace along the flow.
using Variant = std::tuple<methods::LicKernel, methods::Integrator>;
class HybridVariants : public ::testing::TestWithParam<Variant> {};
std::string variantName(const ::testing::TestParamInfo<Variant>& info) {
    static const char* kernels[] = {"box", "exponential", "gaussian", "hann"};
    static const char* integrators[] = {"euler", "rk2", "rk4"};
    return std::string(kernels[int(std::get<0>(info.param))]) + "_" + integrators[int(std::get<1>(info.param))];
}
INSTANTIATE_TEST_SUITE_P(KernelsIntegrators, HybridVariants,
                         ::testing::Combine(::testing::Values(methods::LicKernel::Box, methods::LicKernel::Exponential,
                                                              methods::LicKernel::Gaussian, methods::LicKernel::Hann),
                                            ::testing::Values(methods::Integrator::Euler, methods::Integrator::Rk2,
                                                              methods::Integrator::Rk4)),
                         variantName);
TEST_P(HybridVariants, SphereOrientationMatchesProjectedField) {
    methods::MethodParams p = hybridParams();
    p.hybrid.kernel = std::get<0>(GetParam());
    p.hybrid.integrator = std::get<1>(GetParam());
    float median = sphereOrientationError(p);
    std::printf("median orientation error %.2f deg\n", median);
    EXPECT_LE(median, 6.0f);
}

// Camera roll with the noise phase frozen: the pattern turns with the surface. The new
// image correlates >= 0.9 with the old one rotated by the roll, on surface pixels.
TEST(Hybrid, PatternSticksToTheSurfaceUnderCameraRoll) {
    core::Dataset d = core::makeBuiltin("builtin:vortex-plane");
    const core::Viewport vp{256, 256};
    core::Camera cam0 = core::fitCamera(d.bounds(), vp, {0.2f, 0.3f, 1.0f});
    const float rollDeg = 6.0f;
    core::Camera cam1 = cam0;
    glm::vec3 axis = glm::normalize(cam0.target - cam0.eye);
    cam1.up = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(rollDeg), axis) * glm::vec4(cam0.up, 0.0f));
    methods::MethodParams p = hybridParams();
    methods::SurfaceGpu surface(d.steps[0].mesh, "velocity", p.common);
    auto run = [&](const std::string& method, double& image) {
        auto m = methods::makeMethod(method, p, vp);
        for (int k = 0; k < 40; ++k) m->renderFrame({&surface, cam0, uint32_t(k)});
        std::vector<float> before = gl::readChannel(m->flowTexture());
        m->renderFrame({&surface, cam1, 39});  // same noise phase as the last frame
        std::vector<float> after = gl::readChannel(m->flowTexture());
        std::vector<float> depth = gl::readDepth(m->surfaceDepth());
        // Rotating the image by the roll about the centre: where was pixel (x, y)?
        std::vector<double> a, b;
        // Rolling the up vector by +roll about the view axis turns the image content by
        // +roll (counter-clockwise) about the centre.
        const float c = std::cos(glm::radians(-rollDeg)), s = std::sin(glm::radians(-rollDeg));
        for (int y = 0; y < vp.height; ++y)
            for (int x = 0; x < vp.width; ++x) {
                if (depth[size_t(y) * vp.width + x] >= 1.0f) continue;
                float dx = x + 0.5f - vp.width * 0.5f, dy = y + 0.5f - vp.height * 0.5f;
                int sx = int(std::floor(c * dx - s * dy + vp.width * 0.5f)),
                    sy = int(std::floor(s * dx + c * dy + vp.height * 0.5f));
                if (sx < 0 || sy < 0 || sx >= vp.width || sy >= vp.height) continue;
                a.push_back(after[size_t(y) * vp.width + x]);
                b.push_back(before[size_t(sy) * vp.width + sx]);
            }
        image = test::pearson(a, b);
    };
    double hybrid = 0, isa = 0;
    run("hybrid", hybrid);
    p.common.onCameraMove = methods::CameraMoveRemedy::None;
    run("isa", isa);
    std::printf("correlation with the rolled image: hybrid %.3f, isa (no remedy) %.3f\n", hybrid, isa);
    EXPECT_GE(hybrid, 0.9);
    EXPECT_LT(isa, 0.9) << "an image-space method without remedy should not follow the roll";
}

// Two overlapping planes with perpendicular flows: next to the front plane's edge, the
// back plane's streaks keep the back plane's direction (within 10 degrees).
TEST(Hybrid, NoStreakCrossesAnOccludingEdge) {
    core::Dataset d = core::makeBuiltin("builtin:overlap-planes");
    const core::Viewport vp{256, 256};
    test::Rendered r = test::renderScene(d, "hybrid", hybridParams(), vp, test::orthoFront(2.2f), 0);
    std::vector<float> errors;
    for (int y = 30; y < 226; y += 4)
        for (int x = 131; x < 140; x += 2) errors.push_back(test::orientationErrorDeg(test::streakOrientation(r, x, y, 2.5f), 0.0f));
    std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
    float median = errors[errors.size() / 2];
    std::printf("back plane next to the edge: median orientation error %.2f deg\n", median);
    EXPECT_LE(median, 10.0f);
}

// A long plane in perspective, the flow running away from the camera: near and far
// parts show the same dominant spatial frequency across the flow (image x) within a
// factor 1.5, thanks to the octave-mixed noise. (Across = horizontal in the image, so
// foreshortening of the plane does not enter.)
TEST(Hybrid, ConstantImageSpaceFrequencyNearAndFar) {
    core::SurfaceMesh m = core::makeRectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 16.0f, 12.0f, 64, 96);
    m.fields = {{"velocity", std::vector<glm::vec3>(m.positions.size(), glm::vec3(0, 1, 0))}};
    core::Dataset d{"plane", {{0.0, m}}};
    const core::Viewport vp{256, 256};
    core::Camera cam;
    cam.eye = {0, -7.5f, 1.2f};
    cam.target = {0, 0, 0};
    cam.up = {0, 0, 1};
    cam.fovDeg = 50.0f;
    core::fitClipPlanes(cam, m.bounds());
    methods::MethodParams p = hybridParams();
    p.common.noise.scale = 4.0f;
    test::Rendered r = test::renderScene(d, "hybrid", p, vp, cam, 0);
    auto lengthAcross = [&](int y0, int y1) { return test::correlationLength(r, 40, y0, 216, y1, 1, 0); };
    ASSERT_TRUE(r.onSurface(40, 5) && r.onSurface(216, 135));
    float nearL = lengthAcross(5, 45), farL = lengthAcross(100, 135);
    float ratio = std::max(nearL, farL) / std::min(nearL, farL);
    std::printf("correlation length across the flow: near %.2f px, far %.2f px (ratio %.2f)\n", nearL, farL, ratio);
    EXPECT_LE(ratio, 1.5f);
}

// With L = 1 the output is the solid noise sampled at the seed positions.
TEST(Hybrid, FilterLengthOneReproducesTheNoise) {
    core::Dataset d = core::makeBuiltin("builtin:sphere");
    const core::Viewport vp{96, 96};
    core::Camera cam = core::fitCamera(d.bounds(), vp, {0.3f, 0.4f, 1.0f});
    methods::MethodParams p = hybridParams();
    p.hybrid.filterLength = 1;
    methods::SurfaceGpu surface(d.steps[0].mesh, "velocity", p.common);
    methods::hybrid::HybridRenderer m(p, vp);
    m.renderFrame({&surface, cam, 5});
    std::vector<float> lic = gl::readChannel(m.flowTexture());
    std::vector<float> depth = gl::readDepth(m.surfaceDepth());
    const int n = p.hybrid.noiseSize;
    const std::vector<float> noise = m.noiseValues();
    ASSERT_EQ(noise.size(), size_t(n) * n * n);
    // Trilinear, wrapped sampling of the volume at texture coordinate t (as GL does).
    auto sample = [&](glm::vec3 t) {
        glm::vec3 u = t * float(n) - 0.5f;
        glm::vec3 f = glm::floor(u), a = u - f;
        float v = 0;
        for (int k = 0; k < 8; ++k) {
            glm::ivec3 o(k & 1, (k >> 1) & 1, (k >> 2) & 1);
            glm::ivec3 q = (glm::ivec3(f) + o) % n;
            q = (q + n) % n;
            float w = (o.x ? a.x : 1 - a.x) * (o.y ? a.y : 1 - a.y) * (o.z ? a.z : 1 - a.z);
            v += w * noise[(size_t(q.z) * n + q.y) * n + q.x];
        }
        return v;
    };
    const glm::mat4 invVP = glm::inverse(cam.viewProjection(1.0f));
    const float pixelPerDist = 2.0f * std::tan(glm::radians(cam.fovDeg) * 0.5f) / float(vp.height);
    const float freq = (2.0f / float(n)) / (p.common.noise.scale * pixelPerDist);
    double worst = 0;
    int count = 0;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            float z = depth[size_t(y) * vp.width + x];
            if (z >= 1.0f) continue;
            glm::vec4 h = invVP * glm::vec4((x + 0.5f) / vp.width * 2 - 1, (y + 0.5f) / vp.height * 2 - 1, z * 2 - 1, 1);
            glm::vec3 pos = glm::vec3(h) / h.w;
            float l = std::log2(glm::length(pos - cam.eye)), i = std::floor(l), f = l - i;
            // The shader's fixed oblique rotation of the lookup (column-major, as GLSL).
            const glm::mat3 rot(0.781639f, 0.550117f, -0.293958f, -0.482929f, 0.832030f, 0.272956f, 0.394740f,
                                -0.071392f, 0.916015f);
            glm::vec3 q = rot * pos;
            float expected = (1 - f) * sample(q * freq * std::exp2(-i)) + f * sample(q * freq * std::exp2(-(i + 1)));
            worst = std::max(worst, double(std::abs(expected - lic[size_t(y) * vp.width + x])));
            ++count;
        }
    std::printf("L = 1: worst difference from the sampled noise %.2e over %d pixels\n", worst, count);
    ASSERT_GT(count, 1000);
    EXPECT_LT(worst, 2e-2) << "positions reconstructed from depth differ slightly from the seed texture";
}

// The solid noise is kept as 8-bit codes (SolidNoise::kCode): for both profiles no value may
// reach the ends of the code range (it would be clipped there), the mean stays at 0.5 and the
// deviation at half the profile's (0.5 for the square profile's 0/1 values, 1/sqrt(12) for
// the sawtooth), as the blur's rescaling intends.
TEST(Hybrid, SolidNoiseCodesNeitherClipNorLoseContrast) {
    core::Dataset d = core::makeBuiltin("builtin:sphere");
    const core::Viewport vp{64, 64};
    const core::Camera cam = core::fitCamera(d.bounds(), vp, {0.3f, 0.4f, 1.0f});
    for (core::NoiseProfile profile : {core::NoiseProfile::Square, core::NoiseProfile::Sawtooth}) {
        methods::MethodParams p = hybridParams();
        p.common.noise.profile = profile;
        methods::SurfaceGpu surface(d.steps[0].mesh, "velocity", p.common);
        methods::hybrid::HybridRenderer m(p, vp);
        m.renderFrame({&surface, cam, 7});
        const std::vector<float> n = m.noiseValues();
        ASSERT_EQ(n.size(), size_t(p.hybrid.noiseSize) * p.hybrid.noiseSize * p.hybrid.noiseSize);
        const float step = 1.0f / (255.0f * methods::hybrid::SolidNoise::kCode);  // one code in N
        const float lowest = 0.5f - 0.5f / methods::hybrid::SolidNoise::kCode, highest = 1.0f - lowest;
        double sum = 0, sq = 0;
        float lo = n[0], hi = n[0];
        for (float v : n) {
            sum += v;
            sq += double(v) * v;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        const double mean = sum / double(n.size()), sd = std::sqrt(sq / double(n.size()) - mean * mean);
        const double profileSd = profile == core::NoiseProfile::Square ? 0.5 : 1.0 / std::sqrt(12.0);
        std::printf("%s: N in [%.3f, %.3f] (codes reach [%.3f, %.3f]), mean %.4f, sd %.4f (half the profile's: %.4f)\n",
                    profile == core::NoiseProfile::Square ? "square" : "sawtooth", lo, hi, lowest, highest, mean, sd,
                    0.5 * profileSd);
        EXPECT_GT(lo, lowest + 0.5f * step) << "a value clipped at the lowest code";
        EXPECT_LT(hi, highest - 0.5f * step) << "a value clipped at the highest code";
        EXPECT_NEAR(mean, 0.5, 0.01);
        EXPECT_NEAR(sd, 0.5 * profileSd, 0.05 * profileSd);
    }
}
