// Unsteady flow and dynamic meshes [L §I, Fig. 11]: the texture follows the field of the
// current data time; a changing topology never shows stale geometry; memory stays flat.
#include "core/builtin_scenes.h"
#include "core/step_stream.h"
#include "gl/readback.h"
#include "gl_test_util.h"
#include "methods/make_renderer.h"
#include "raster/surface_gpu.h"
#include "raster/time_levels.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using namespace flowsurf;

namespace {

// Runs `frames` + 1 frames over the stream, uploading when the data changed; returns
// the method for read-back.
std::unique_ptr<methods::FlowMethod> animate(core::StepStream& stream, const core::TimeMapping& map,
                                             const std::string& name, const core::Viewport& vp,
                                             const core::Camera& cam, int frames) {
    methods::MethodParams p;
    auto m = methods::makeMethod(name, p, vp);
    std::unique_ptr<methods::SurfaceGpu> surface;
    for (int k = 0; k <= frames; ++k) {
        bool changed = false;
        const core::SurfaceMesh& mesh = stream.meshAt(map.at(k), &changed);
        if (changed || !surface) surface = std::make_unique<methods::SurfaceGpu>(mesh, "velocity", p.common);
        m->renderFrame({surface.get(), cam, uint32_t(k)});
    }
    return m;
}

long residentKb() {
    std::ifstream f("/proc/self/status");
    for (std::string line; std::getline(f, line);)
        if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    return -1;
}

}  // namespace

class UnsteadyOrientation : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(Methods, UnsteadyOrientation, ::testing::Values("isa", "ibfvs"),
                         [](const auto& info) { return info.param; });

// The turning plane: at frame k the streaks follow the field at data time t(k), not the
// first step's (which is 90 degrees off by the end).
TEST_P(UnsteadyOrientation, TextureFollowsTheFieldOfTheCurrentTime) {
    core::DatasetSteps steps(core::makeBuiltin("builtin:turning-plane"));
    core::StepStream stream(steps);
    core::TimeMapping map{0.0, 8.0, 8.0 / 120.0};  // the whole turn over 120 frames
    const core::Viewport vp{192, 192};
    auto m = animate(stream, map, GetParam(), vp, test::orthoFront(2.2f), 120);
    test::Rendered r = test::readBack(*m, vp);
    const float now = glm::half_pi<float>() * float(map.at(120) / 8.0);  // the field's angle at t(120)
    std::vector<float> errNow, errFirst;
    for (int y = 30; y < 162; y += 6)
        for (int x = 30; x < 162; x += 6) {
            float o = test::streakOrientation(r, x, y, 4.0f);
            errNow.push_back(test::orientationErrorDeg(o, now));
            errFirst.push_back(test::orientationErrorDeg(o, 0.0f));
        }
    std::nth_element(errNow.begin(), errNow.begin() + errNow.size() / 2, errNow.end());
    std::nth_element(errFirst.begin(), errFirst.begin() + errFirst.size() / 2, errFirst.end());
    float medNow = errNow[errNow.size() / 2], medFirst = errFirst[errFirst.size() / 2];
    std::printf("%s: median error vs the current field %.1f deg, vs the first step's %.1f deg\n",
                GetParam().c_str(), medNow, medFirst);
    EXPECT_LE(medNow, 10.0f);
    EXPECT_GE(medFirst, 45.0f);
}

// The piston changes topology between steps: every frame's surface mask equals the mask
// of the geometry of its own (nearest or interpolated) step, never a stale one.
TEST(Unsteady, TopologyChangesNeverShowStaleGeometry) {
    core::Dataset data = core::makeBuiltin("builtin:piston");
    core::DatasetSteps steps(data);
    core::StepStream stream(steps);
    const core::Viewport vp{128, 128};
    core::Camera cam = core::fitCamera(data.bounds(), vp, {0.5f, -0.8f, 0.4f});
    cam.up = {0, 0, 1};
    core::TimeMapping map{0.0, 1.0, 1.0 / 37.0};  // not a multiple of the step spacing
    methods::MethodParams p;
    auto m = methods::makeMethod("isa", p, vp);
    int mismatched = 0, checked = 0;
    std::unique_ptr<methods::SurfaceGpu> surface;
    for (int k = 0; k <= 37; ++k) {
        bool changed = false;
        const core::SurfaceMesh& mesh = stream.meshAt(map.at(k), &changed);
        if (changed || !surface) surface = std::make_unique<methods::SurfaceGpu>(mesh, "velocity", p.common);
        m->renderFrame({surface.get(), cam, uint32_t(k)});
        std::vector<float> depth = gl::readDepth(m->surfaceDepth());
        // Reference: a fresh method on a fresh upload of this frame's mesh.
        methods::SurfaceGpu fresh(mesh, "velocity", p.common);
        auto ref = methods::makeMethod("isa", p, vp);
        ref->renderFrame({&fresh, cam, 0});
        std::vector<float> refDepth = gl::readDepth(ref->surfaceDepth());
        for (size_t i = 0; i < depth.size(); ++i) mismatched += (depth[i] < 1.0f) != (refDepth[i] < 1.0f);
        ++checked;
        EXPECT_EQ(surface->triangleCount(), mesh.triangleCount());
    }
    EXPECT_EQ(checked, 38);
    EXPECT_EQ(mismatched, 0);
    EXPECT_LE(stream.resident(), 3u);
}

// A surface that shrinks between frames (the piston's wall, in miniature: a plane that
// loses its right half): wherever the current frame has no surface, the exported F_a
// holds the noise mean, for every method; no texture stays where the surface was.
class ShrinkingSurface : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(Methods, ShrinkingSurface, ::testing::Values("isa", "ibfvs", "hybrid"),
                         [](const auto& info) { return info.param; });
TEST_P(ShrinkingSurface, FlowTextureHoldsTheNoiseMeanOffTheSurface) {
    core::SurfaceMesh big = core::makeRectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0f, 2.0f, 40, 40);
    core::SurfaceMesh small = core::makeRectangle({-0.5f, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0f, 2.0f, 20, 40);
    for (core::SurfaceMesh* m : {&big, &small})
        m->fields.push_back({"velocity", std::vector<glm::vec3>(m->positions.size(), glm::vec3(1, 0.3f, 0))});
    const core::Viewport vp{128, 128};
    const core::Camera cam = test::orthoFront(2.2f);
    methods::MethodParams p;
    auto m = methods::makeMethod(GetParam(), p, vp);
    methods::SurfaceGpu before(big, "velocity", p.common), after(small, "velocity", p.common);
    for (int k = 0; k < 30; ++k) m->renderFrame({k < 25 ? &before : &after, cam, uint32_t(k)});
    test::Rendered r = test::readBack(*m, vp);
    int background = 0, stale = 0;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x)
            if (!r.onSurface(x, y)) {
                ++background;
                stale += std::abs(r.f(x, y) - core::kNoiseMean) > 1e-3f;
            }
    std::printf("%s: %d of %d background pixels of F_a textured\n", GetParam().c_str(), stale, background);
    EXPECT_GT(background, vp.width * vp.height / 2);
    EXPECT_EQ(stale, 0);
}

// A 2000-frame run over a series keeps resident memory flat after warm-up.
TEST(Unsteady, LongRunKeepsMemoryFlat) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer's quarantine holds freed memory: resident size is not the program's";
#endif
    core::DatasetSteps steps(core::makeBuiltin("builtin:piston:2000"));
    core::StepStream stream(steps);
    const core::Viewport vp{64, 64};
    core::Camera cam = core::fitCamera(core::makeBuiltin("builtin:piston:2000").bounds(), vp, {0.5f, -0.8f, 0.4f});
    core::TimeMapping map{0.0, 1.0e9, 1.0 / 150.0};  // cycles through the steps; wraps below
    methods::MethodParams p;
    auto m = methods::makeMethod("isa", p, vp);
    std::unique_ptr<methods::SurfaceGpu> surface;
    long afterWarmup = 0;
    for (int k = 0; k < 2000; ++k) {
        bool changed = false;
        double t = std::fmod(map.at(k), 1.0);  // loop the cycle: steps are evicted and reloaded
        const core::SurfaceMesh& mesh = stream.meshAt(t, &changed);
        if (changed || !surface) surface = std::make_unique<methods::SurfaceGpu>(mesh, "velocity", p.common);
        m->renderFrame({surface.get(), cam, uint32_t(k)});
        if (k == 199) {
            glFinish();
            afterWarmup = residentKb();
        }
    }
    glFinish();
    long end = residentKb();
    std::printf("resident memory: %ld kB after 200 frames, %ld kB after 2000\n", afterWarmup, end);
    EXPECT_LT(end - afterWarmup, 16 * 1024) << "more than 16 MB growth";
    EXPECT_LE(stream.resident(), 3u);
}

// Rewriting the vertices of an uploaded surface in place (same topology, new step) gives
// the same image as a fresh upload of that step; a different topology is refused.
TEST(Unsteady, InPlaceVertexUpdateMatchesAFreshUpload) {
    core::Dataset gyre = core::makeBuiltin("builtin:double-gyre");
    const core::Viewport vp{96, 64};
    core::Camera cam = core::fitCamera(gyre.bounds(), vp, {0.2f, 0.3f, 1.0f});
    methods::MethodParams p;
    methods::SurfaceGpu updated(gyre.steps[0].mesh, "velocity", p.common);
    ASSERT_TRUE(updated.updateVertices(gyre.steps[5].mesh, "velocity", p.common));
    methods::SurfaceGpu fresh(gyre.steps[5].mesh, "velocity", p.common);
    auto a = methods::makeMethod("ibfvs", p, vp), b = methods::makeMethod("ibfvs", p, vp);
    for (int k = 0; k < 10; ++k) {
        a->renderFrame({&updated, cam, uint32_t(k)});
        b->renderFrame({&fresh, cam, uint32_t(k)});
    }
    EXPECT_EQ(gl::readChannel(a->flowTexture()), gl::readChannel(b->flowTexture()));
    EXPECT_FALSE(updated.updateVertices(core::makeBuiltin("builtin:piston").steps[3].mesh, "velocity", p.common));
}

// ---- Hybrid pathlines through unsteady data [W §3] ----
namespace {

// A plane with uniform flow; per step the direction given (angle in radians).
core::Dataset planeSeries(const std::vector<std::pair<double, float>>& steps) {
    const core::SurfaceMesh base = core::makeBuiltin("builtin:uniform-plane").steps[0].mesh;
    core::Dataset d{"plane series", {}};
    for (const auto& [t, angle] : steps) {
        core::SurfaceMesh m = base;
        for (auto& v : m.fields[0].values) v = {std::cos(angle), std::sin(angle), 0.0f};
        d.steps.push_back({t, std::move(m)});
    }
    return d;
}

// The hybrid's flow texture I at data time t0 with `tau` data time per particle step
// (0: streamlines of the field at t0), noise frame 5 throughout.
test::Rendered hybridAt(core::StepStream& stream, methods::TimeLevelSource& source, double t0, double tau,
                        const core::Viewport& vp, const core::Camera& cam) {
    methods::MethodParams p;
    const core::SurfaceMesh& mesh = stream.meshAt(t0);
    methods::SurfaceGpu surface(mesh, "velocity", p.common);
    const methods::TimeLevels& levels = source.at(t0, tau, (p.hybrid.filterLength - 1) / 2);
    auto m = methods::makeMethod("hybrid", p, vp);
    m->renderFrame({&surface, cam, 5u, levels.empty() ? nullptr : &levels});
    return test::readBack(*m, vp);
}

// Correlation of a with b shifted by (dx, dy), over the interior.
double interiorCorrelation(const test::Rendered& a, const test::Rendered& b, int margin, int dx = 0, int dy = 0) {
    std::vector<double> x, y;
    for (int j = margin; j < a.height - margin; ++j)
        for (int i = margin; i < a.width - margin; ++i) {
            x.push_back(a.f(i, j));
            y.push_back(b.f(i + dx, j + dy));
        }
    return test::pearson(x, y);
}

// Best correlation over shifts up to `r` pixels: an Euler pathline's later part is offset
// by its first steps.
double bestShiftedCorrelation(const test::Rendered& a, const test::Rendered& b, int margin, int r) {
    double best = -1.0;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) best = std::max(best, interiorCorrelation(a, b, margin, dx, dy));
    return best;
}

}  // namespace

// The field turns from x to y just after t0 = 0.99: a particle's forward half runs into
// the y flow, so the pathline LIC shares its forward half with the LIC of the y field
// (shifted by the first step, taken along x), while the streamline LIC of the field at t0
// (along x) shares one sample at any shift.
TEST(HybridUnsteady, PathlinesFollowTheFieldOfLaterTimes) {
    core::DatasetSteps steps(planeSeries({{0.0, 0.0f}, {0.99, 0.0f}, {1.01, glm::half_pi<float>()},
                                          {2.0, glm::half_pi<float>()}}));
    core::StepStream stream(steps);
    methods::TimeLevelSource source(stream, "velocity");
    const core::Viewport vp{160, 160};
    const core::Camera cam = test::orthoFront(1.6f);
    const double tau = 1.0 / 15.0;  // the 15 forward steps reach t = 1.99
    test::Rendered path = hybridAt(stream, source, 0.99, tau, vp, cam);
    test::Rendered stream0 = hybridAt(stream, source, 0.99, 0.0, vp, cam);
    test::Rendered alongY = hybridAt(stream, source, 2.0, 0.0, vp, cam);
    test::Rendered alongX = hybridAt(stream, source, 0.0, 0.0, vp, cam);
    const double pathY = bestShiftedCorrelation(path, alongY, 40, 5);
    const double streamY = bestShiftedCorrelation(stream0, alongY, 40, 5);
    const double pathX = interiorCorrelation(path, alongX, 40), streamX = interiorCorrelation(stream0, alongX, 40);
    std::printf("correlation with the LIC along y (best shift): pathline %.3f, streamline %.3f; along x: %.3f, %.3f\n",
                pathY, streamY, pathX, streamX);
    EXPECT_GE(pathY, 0.4);
    EXPECT_LE(streamY, 0.25);
    EXPECT_GE(pathX, 0.4);     // the backward half still runs along x
    EXPECT_LE(pathX, 0.85);
    EXPECT_GE(streamX, 0.95);  // the streamline LIC is the x field's
}

// A series whose steps all carry the same field (the spinning sphere, in perspective): the
// pathline LIC equals the steady LIC (the velocity levels reproduce the seeds' velocity
// image; 16-bit levels).
TEST(HybridUnsteady, SteadySeriesGivesTheSteadyTexture) {
    core::Dataset sphere = core::makeBuiltin("builtin:sphere");
    for (double t : {1.0, 2.0}) sphere.steps.push_back({t, sphere.steps[0].mesh});
    core::DatasetSteps steps(sphere);
    core::StepStream stream(steps);
    methods::TimeLevelSource source(stream, "velocity");
    const core::Viewport vp{128, 128};
    const core::Camera cam = core::fitCamera(sphere.bounds(), vp, {0.3f, 0.4f, 1.0f});
    test::Rendered path = hybridAt(stream, source, 1.0, 0.1, vp, cam);
    test::Rendered steady = hybridAt(stream, source, 1.0, 0.0, vp, cam);
    std::vector<double> a, b;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x)
            if (steady.onSurface(x, y)) {
                a.push_back(path.f(x, y));
                b.push_back(steady.f(x, y));
            }
    ASSERT_GT(a.size(), 4000u);
    const double c = test::pearson(a, b);
    std::printf("pathline vs steady LIC on a steady series: correlation %.4f over %zu surface pixels\n", c, a.size());
    EXPECT_GE(c, 0.99);
}

// Time levels across the piston's topology changes hold the field of steps that agree
// with the frame's triangles: every level has a field, and the hybrid renders textured
// frames over the whole cycle without GL errors.
TEST(HybridUnsteady, TopologyChangesInsideTheWindowHoldTheField) {
    core::Dataset data = core::makeBuiltin("builtin:piston");
    core::DatasetSteps steps(data);
    core::StepStream stream(steps);
    methods::TimeLevelSource source(stream, "velocity");
    const core::Viewport vp{96, 96};
    core::Camera cam = core::fitCamera(data.bounds(), vp, {0.5f, -0.8f, 0.4f});
    cam.up = {0, 0, 1};
    methods::MethodParams p;
    auto m = methods::makeMethod("hybrid", p, vp);
    int framesWithLevels = 0;
    for (int k = 0; k <= 12; ++k) {
        const double t = double(k) / 12.0;
        const core::SurfaceMesh& mesh = stream.meshAt(t);
        methods::SurfaceGpu surface(mesh, "velocity", p.common);
        const methods::TimeLevels& levels = source.at(t, 0.01, (p.hybrid.filterLength - 1) / 2);
        for (const auto& l : levels.levels) {
            ASSERT_NE(l.fieldA, 0u);
            ASSERT_NE(l.fieldB, 0u);
            GLint64 bytes = 0;
            glGetNamedBufferParameteri64v(l.fieldA, GL_BUFFER_SIZE, &bytes);
            EXPECT_EQ(size_t(bytes), mesh.vertexCount() * sizeof(glm::vec3));  // the frame's vertices
        }
        framesWithLevels += !levels.empty();
        m->renderFrame({&surface, cam, uint32_t(k), levels.empty() ? nullptr : &levels});
        ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        // The same frame again (time held, view unchanged): the static case reuses the
        // seed and level textures.
        m->renderFrame({&surface, cam, uint32_t(k), levels.empty() ? nullptr : &levels});
        EXPECT_FALSE(m->lastFrameDynamic()) << "frame " << k;
        test::Rendered r = test::readBack(*m, vp);
        double sum = 0, sum2 = 0;
        int n = 0;
        for (int y = 0; y < vp.height; ++y)
            for (int x = 0; x < vp.width; ++x)
                if (r.onSurface(x, y)) {
                    sum += r.f(x, y);
                    sum2 += double(r.f(x, y)) * r.f(x, y);
                    ++n;
                }
        ASSERT_GT(n, 500);
        EXPECT_GT(std::sqrt(sum2 / n - (sum / n) * (sum / n)), 0.03) << "frame " << k << " has no texture";
    }
    EXPECT_GE(framesWithLevels, 11);
}
