// ISA property tests [L §IV]: each asserts what a user sees, not just that it ran.
#include "core/builtin_scenes.h"
#include "gl_test_util.h"
#include "methods/make_renderer.h"
#include "raster/surface_gpu.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace flowsurf;

namespace {

class MethodProperties : public ::testing::TestWithParam<std::string> {
protected:
    // Image-space methods need a history of frames; the hybrid LIC is complete in one.
    int frames(int imageSpace) const { return GetParam() == "hybrid" ? 1 : imageSpace; }
};

}  // namespace

INSTANTIATE_TEST_SUITE_P(Methods, MethodProperties, ::testing::Values("isa", "ibfvs", "hybrid"),
                         [](const auto& info) { return info.param; });

// Uniform flow along x on a plane: streaks along x. The correlation length along the
// flow must be several times the length across it.
TEST_P(MethodProperties, UniformFlowStreaksAlongFlow) {
    core::Dataset d = core::makeBuiltin("builtin:uniform-plane");
    test::Rendered r = test::renderScene(d, GetParam(), test::testParams(), {256, 256}, test::orthoFront(2.2f), frames(80));
    float along = test::correlationLength(r, 40, 40, 216, 216, 1, 0);
    float across = test::correlationLength(r, 40, 40, 216, 216, 0, 1);
    std::printf("correlation length along %.0f px, across %.0f px\n", along, across);
    EXPECT_GE(along, 3.0f * across) << "along " << along << " px, across " << across << " px";
}

namespace {

// The spinning sphere of the orientation tests: builtin:sphere turning about a tilted
// axis, 320^2, seen from (0.3, 0.4, 1).
struct SpinningSphere {
    core::Dataset data = core::makeBuiltin("builtin:sphere");
    core::Viewport vp{320, 320};
    core::Camera cam = core::fitCamera(data.bounds(), vp, {0.3f, 0.4f, 1.0f});
    test::Rendered render(const std::string& method, const methods::MethodParams& p, int frames) const {
        return test::renderScene(data, method, p, vp, cam, frames);
    }
    // Median angle between the streaks (structure tensor of F_a averaged over a Gaussian
    // of `sigma` px) and the projected field, where the surface faces the camera and moves.
    float medianErrorDeg(const test::Rendered& r, float sigma) const {
        const glm::vec3 w = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
        const glm::mat4 invVP = glm::inverse(cam.viewProjection(vp.aspect()));
        std::vector<float> errors;
        for (int y = 8; y < vp.height - 8; y += 6)
            for (int x = 8; x < vp.width - 8; x += 6) {
                if (!r.onSurface(x, y)) continue;
                float depth = r.depth[size_t(y) * vp.width + x];
                glm::vec4 h = invVP * glm::vec4((x + 0.5f) / vp.width * 2 - 1, (y + 0.5f) / vp.height * 2 - 1,
                                                depth * 2 - 1, 1);
                glm::vec3 p = glm::vec3(h) / h.w;
                glm::vec3 toEye = glm::normalize(cam.eye - p);
                if (glm::dot(glm::normalize(p), toEye) < 0.4f) continue;  // near the silhouette
                glm::vec3 v = glm::cross(w, p);
                glm::vec3 a = core::projectToPixels(cam, vp, p), b = core::projectToPixels(cam, vp, p + 0.01f * v);
                glm::vec2 vPx = glm::vec2(b - a);
                if (glm::length(vPx) < 0.01f * 0.4f * 120.0f) continue;  // near the rotation poles
                float expected = std::fmod(std::atan2(vPx.y, vPx.x) + glm::two_pi<float>(), glm::pi<float>());
                errors.push_back(test::orientationErrorDeg(test::streakOrientation(r, x, y, sigma), expected));
            }
        EXPECT_GT(errors.size(), 200u);
        if (errors.empty()) return 90.0f;
        std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
        return errors[errors.size() / 2];
    }
};


}  // namespace

// Spinning sphere: the structure orientation of F_a matches the projected field. Median
// error, sigma = 4 px: ISA and IBFVS measured 2.63 deg at seed 7 (2.46-2.87 at seeds
// 1-3; 4.1 deg before the bicubic resampling and swept noise), tolerance 3.5 deg; the
// hybrid measured 3.56 deg, tolerance 10 (its own tests hold it to 5).
TEST_P(MethodProperties, SphereOrientationMatchesProjectedField) {
    SpinningSphere s;
    test::Rendered r = s.render(GetParam(), test::testParams(), frames(100));
    float median = s.medianErrorDeg(r, 4.0f);
    std::printf("median orientation error %.2f deg (sigma 4 px)\n", median);
    EXPECT_LE(median, GetParam() == "hybrid" ? 10.0f : 3.5f);
}

// The same at a finer scale (sigma = 2 px), where blotchy texture shows: the target of
// the sharper defaults (docs/methods.md) is 5 deg. ISA and IBFVS measured 4.41 / 4.40 deg at seed 7 (3.67-4.39 at seeds
// 1-3; 7.5 deg with the paper's bilinear, point-noise defaults); the hybrid 3.80 deg.
TEST_P(MethodProperties, SphereOrientationFineScale) {
    SpinningSphere s;
    test::Rendered r = s.render(GetParam(), test::testParams(), frames(100));
    float median = s.medianErrorDeg(r, 2.0f);
    std::printf("median orientation error %.2f deg (sigma 2 px)\n", median);
    EXPECT_LE(median, 5.0f);
}

// No flicker: with a still camera, consecutive frames of F_a correlate >= 0.9 over the
// surface (the texture moves one step along streaks of ~step / alpha px, and alpha of
// it is renewed). Measured 0.956 for ISA and IBFVS (the paper's defaults: 0.975).
TEST(ImageSpaceMethods, ConsecutiveFramesCorrelate) {
    SpinningSphere s;
    for (const std::string method : {"isa", "ibfvs"}) {
        methods::SurfaceGpu surface(s.data.steps.front().mesh, "velocity", test::testParams().common);
        auto m = methods::makeMethod(method, test::testParams(), s.vp);
        test::Rendered prev;
        double worst = 1.0;
        for (int k = 0; k <= 100; ++k) {
            m->renderFrame({&surface, s.cam, uint32_t(k)});
            if (k < 96) continue;
            test::Rendered r = test::readBack(*m, s.vp);
            if (k > 96) {
                std::vector<double> a, b;
                for (int y = 0; y < s.vp.height; ++y)
                    for (int x = 0; x < s.vp.width; ++x)
                        if (r.onSurface(x, y)) {
                            a.push_back(prev.f(x, y));
                            b.push_back(r.f(x, y));
                        }
                worst = std::min(worst, test::pearson(a, b));
            }
            prev = std::move(r);
        }
        std::printf("%s: consecutive frames correlate >= %.3f\n", method.c_str(), worst);
        EXPECT_GE(worst, 0.9) << method;
    }
}

// The paper's behaviour stays reachable by options (--resample bilinear --noise-injection
// point --step-px 2) and is the texture of the paper's pipeline: its orientation errors are
// those measured then (sigma 4 / 2 px: ISA 4.11 / 7.53, IBFVS 4.06 / 7.57 deg, within
// 0.3 deg), measurably worse than the defaults.
TEST(ImageSpaceMethods, PaperBehaviourReachable) {
    SpinningSphere s;
    const struct { const char* method; float coarse, fine; } before[] = {{"isa", 4.11f, 7.53f},
                                                                          {"ibfvs", 4.06f, 7.57f}};
    for (const auto& b : before) {
        test::Rendered paper = s.render(b.method, test::paperParams(), 100);
        test::Rendered now = s.render(b.method, test::testParams(), 100);
        float coarse = s.medianErrorDeg(paper, 4.0f), fine = s.medianErrorDeg(paper, 2.0f);
        float fineNow = s.medianErrorDeg(now, 2.0f);
        std::printf("%s, paper's options: %.2f / %.2f deg (defaults %.2f at sigma 2)\n", b.method, coarse, fine,
                    fineNow);
        EXPECT_NEAR(coarse, b.coarse, 0.3f) << b.method;
        EXPECT_NEAR(fine, b.fine, 0.3f) << b.method;
        EXPECT_GT(fine - fineNow, 2.0f) << b.method;
    }
}

// Texture clipping: every background pixel equals the background colour exactly.
TEST_P(MethodProperties, BackgroundStaysBackgroundColour) {
    core::Dataset d = core::makeBuiltin("builtin:tori");
    methods::MethodParams p = test::testParams();
    p.common.background = {0.2f, 0.4f, 0.6f};
    const core::Viewport vp{256, 192};
    core::Camera cam = core::fitCamera(d.bounds(), vp, {0.2f, 0.6f, 1.0f});
    test::Rendered r = test::renderScene(d, GetParam(), p, vp, cam, frames(30));
    const uint8_t expect[3] = {51, 102, 153};
    int background = 0, wrong = 0;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            if (r.onSurface(x, y)) continue;
            ++background;
            const uint8_t* px = &r.rgb[(size_t(vp.height - 1 - y) * vp.width + x) * 3];
            if (px[0] != expect[0] || px[1] != expect[1] || px[2] != expect[2]) ++wrong;
        }
    EXPECT_GT(background, vp.width * vp.height / 5);
    EXPECT_EQ(wrong, 0) << "of " << background << " background pixels";
}

// Same inputs, seed and frame count: identical images.
TEST_P(MethodProperties, DeterministicForSameSeed) {
    core::Dataset d = core::makeBuiltin("builtin:vortex-plane");
    const core::Viewport vp{200, 160};
    core::Camera cam = core::fitCamera(d.bounds(), vp, {0.2f, 0.3f, 1.0f});
    test::Rendered a = test::renderScene(d, GetParam(), test::testParams(), vp, cam, frames(40));
    test::Rendered b = test::renderScene(d, GetParam(), test::testParams(), vp, cam, frames(40));
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(a.flow, b.flow);
    methods::MethodParams other = test::testParams();
    other.common.noise.seed = 8;
    test::Rendered c = test::renderScene(d, GetParam(), other, vp, cam, frames(40));
    EXPECT_NE(a.flow, c.flow) << "a different seed must give a different texture";
}

// Occluding edge: the back plane flows along +x out from under the front plane's edge.
// Render twice with the front plane's flow reversed: downstream of the edge the back
// plane must not change (no front texture carried across) with edge blending on, with
// either edge fill, and must change with it off.
TEST(IsaProperties, EdgeBlendingStopsTextureAtOccludingEdge) {
    core::Dataset d = core::makeBuiltin("builtin:overlap-planes");
    core::Dataset reversed = d;
    auto& mesh = reversed.steps[0].mesh;
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        if (mesh.positions[i].z > -0.5f) mesh.fields[0].values[i] *= -1.0f;  // front plane only
    const core::Viewport vp{256, 256};
    core::Camera cam = test::orthoFront(2.2f);
    const int edge = 128;  // the front plane's right edge x = 0 is at the image centre
    auto meanDiff = [](const test::Rendered& a, const test::Rendered& b, int x0, int x1) {
        double sum = 0;
        int n = 0;
        for (int y = 30; y < 226; ++y)
            for (int x = x0; x < x1; ++x, ++n) sum += std::abs(a.f(x, y) - b.f(x, y));
        return sum / n;
    };
    for (int mode = 0; mode < 3; ++mode) {
        methods::MethodParams p = test::testParams();
        p.isa.edgeBlending = mode > 0;
        p.isa.edgeFill = mode == 2 ? methods::EdgeFill::Gray : methods::EdgeFill::Noise;
        test::Rendered a = test::renderScene(d, "isa", p, vp, cam, 60);
        test::Rendered b = test::renderScene(reversed, "isa", p, vp, cam, 60);
        double front = meanDiff(a, b, edge - 40, edge - 2);
        double downstream = meanDiff(a, b, edge + 2, edge + 8) / front;
        const char* name = mode == 0 ? "off" : mode == 1 ? "on, noise fill" : "on, gray fill";
        std::printf("edge blending %s: downstream change %.3f of the front plane's\n", name, downstream);
        if (mode > 0)
            EXPECT_LT(downstream, 0.05) << "with edge blending the texture must not cross the edge";
        else
            EXPECT_GT(downstream, 0.3) << "without edge blending the texture should cross the edge";
    }
}

namespace {
// Standard deviation of F_a and its correlation with F_a `lag` pixels downstream (+x),
// over columns [x0, x1) and rows [30, 226).
struct BandStats {
    double contrast, alongCorr;
};
BandStats bandStats(const test::Rendered& r, int x0, int x1, int lag) {
    std::vector<double> a, b;
    double sum = 0, sum2 = 0;
    for (int y = 30; y < 226; ++y)
        for (int x = x0; x < x1; ++x) {
            sum += r.f(x, y);
            sum2 += double(r.f(x, y)) * r.f(x, y);
            a.push_back(r.f(x, y));
            b.push_back(r.f(x + lag, y));
        }
    const double n = double(a.size()), mean = sum / n;
    return {std::sqrt(std::max(sum2 / n - mean * mean, 0.0)), test::pearson(a, b)};
}
}  // namespace

// Beyond [L]: just downstream of an occluding edge the far surface's texture has the
// contrast and along-flow correlation of its interior (within 10 %) with the noise edge
// fill; with the paper's gray fill it is faint there (streaks regain contrast over
// ~1/alpha frames). The no-crossing half is EdgeBlendingStopsTextureAtOccludingEdge.
TEST(IsaProperties, NoiseEdgeFillStartsStreaksAtFullContrast) {
    core::Dataset d = core::makeBuiltin("builtin:overlap-planes");
    const core::Viewport vp{256, 256};
    core::Camera cam = test::orthoFront(2.2f);
    const int edge = 128, lag = 4;
    double nearContrast[2], nearCorr[2];
    for (int fill = 0; fill < 2; ++fill) {
        methods::MethodParams p = test::testParams();
        p.isa.edgeFill = fill == 0 ? methods::EdgeFill::Gray : methods::EdgeFill::Noise;
        test::Rendered r = test::renderScene(d, "isa", p, vp, cam, 120);
        BandStats interior = bandStats(r, 180, 236, lag);
        BandStats nearEdge = bandStats(r, edge + 1, edge + 11, lag);
        nearContrast[fill] = nearEdge.contrast / interior.contrast;
        nearCorr[fill] = nearEdge.alongCorr / interior.alongCorr;
        std::printf("%s fill: next to the edge contrast %.2f, along-flow correlation %.2f of the interior's "
                    "(interior: std %.3f, corr at %d px %.2f)\n",
                    fill == 0 ? "gray" : "noise", nearContrast[fill], nearCorr[fill], interior.contrast, lag,
                    interior.alongCorr);
    }
    EXPECT_NEAR(nearContrast[1], 1.0, 0.1);
    EXPECT_NEAR(nearCorr[1], 1.0, 0.1);
    EXPECT_LT(nearContrast[0], 0.8) << "the paper's gray fill should be faint next to the edge";
}

// The two variants of texture advection (the paper's grid drawing, and the per-pixel
// interpolation of the same mesh) give the same texture up to interpolation inside a
// cell.
TEST(IsaProperties, MeshAndPixelWarpAgree) {
    core::Dataset d = core::makeBuiltin("builtin:vortex-plane");
    const core::Viewport vp{192, 160};
    core::Camera cam = core::fitCamera(d.bounds(), vp, {0.2f, 0.3f, 1.0f});
    methods::MethodParams p = test::testParams();
    p.isa.gridRes = 96;
    test::Rendered pixel = test::renderScene(d, "isa", p, vp, cam, 12);
    p.isa.warp = methods::IsaWarp::Mesh;
    test::Rendered mesh = test::renderScene(d, "isa", p, vp, cam, 12);
    std::vector<double> a, b;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x)
            if (pixel.onSurface(x, y)) {
                a.push_back(pixel.f(x, y));
                b.push_back(mesh.f(x, y));
            }
    double corr = test::pearson(a, b);
    std::printf("mesh vs pixel warp correlation %.3f\n", corr);
    EXPECT_GT(corr, 0.9);
}
