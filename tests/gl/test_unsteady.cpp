// Unsteady flow and dynamic meshes [L §I, Fig. 11]: the texture follows the field of the
// current data time; a changing topology never shows stale geometry; memory stays flat.
#include "core/builtin_scenes.h"
#include "core/step_stream.h"
#include "gl/readback.h"
#include "gl_test_util.h"

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
    test::Rendered r;
    r.width = vp.width;
    r.height = vp.height;
    r.flow = gl::readChannel(m->flowTexture());
    r.depth = gl::readDepth(m->surfaceDepth());
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

// A 2000-frame run over a series keeps resident memory flat after warm-up.
TEST(Unsteady, LongRunKeepsMemoryFlat) {
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
