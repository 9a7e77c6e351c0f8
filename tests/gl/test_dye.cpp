// Dye [doc/algorithms.md §10] on the analytic sphere in solid-body rotation (builtin:sphere, v = w x p,
// |w| = 1 about (0.3, 1, 0.2)): ink released on the visible side is found where the
// rotation carries it, keeps its area, hides behind the sphere and comes back, draws a
// streakline along the rotation circle, and never shows off the surface; for every method,
// both GL paths and an orbiting camera.
#include "core/builtin_scenes.h"
#include "dye/dye.h"
#include "gl/readback.h"
#include "session/playback.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtx/rotate_vector.hpp>

#include <cmath>
#include <cstdio>
#include <string>

using namespace flowsurf;

namespace {

const glm::vec3 kAxis = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));  // of builtin:sphere, |w| = 1
const glm::vec3 kStart = glm::normalize(glm::vec3(-0.6f, 0.0f, 0.8f));  // visible from +z
constexpr int kQuarter = 16;                                            // frames per quarter turn

session::RenderOptions dyeOptions(const std::string& method, int size) {
    session::RenderOptions o;
    o.input = "builtin:sphere:20000";
    session::setOption(o, "method", method);
    o.size = {size, size};
    o.eye = glm::vec3(0.0f, 0.0f, 5.0f);
    o.target = glm::vec3(0.0f);
    o.params.common.overlay = methods::OverlayScheme::Gray;
    o.params.common.lighting = false;  // red minus green is then the dye's concentration
    o.params.common.background = glm::vec3(0.0f);
    o.timePerFrame = glm::half_pi<double>() / kQuarter;
    session::setOption(o, "dye", std::to_string(kStart.x) + "," + std::to_string(kStart.y) + "," +
                                     std::to_string(kStart.z) + ":0.12:red");
    o.dyeRelease = 1;  // one frame: a blob
    return o;
}

struct Blob {
    double mass = 0.0;       // sum of concentration over the image (pixels)
    glm::dvec2 centroid{0};  // pixels, origin bottom-left, centres at half-integers
};

// The dye seen in the image: red minus green is the concentration with a red dye on the
// gray scheme without lighting. The centroid is taken on the sphere (each pixel unprojected
// onto it, the mean put back on it) and projected, so that the foreshortening of a blob
// near the silhouette does not pull it towards the centre of the image.
Blob measure(session::Playback& p) {
    int w = 0, h = 0;
    const std::vector<uint8_t> rgb = p.readImage(&w, &h);
    const core::Camera cam = p.lastFrame().camera;
    const glm::mat4 inv = glm::inverse(cam.viewProjection(p.options().size.aspect()));
    Blob b;
    glm::dvec3 onSphere(0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const uint8_t* c = &rgb[(size_t(y) * w + x) * 3];
            const double a = std::max(0, int(c[0]) - int(c[1])) / 255.0;
            if (a < 0.1) continue;
            // The ray through the pixel centre, and its first hit of the unit sphere.
            const glm::vec2 ndc = (glm::vec2(x + 0.5f, h - 1 - y + 0.5f) / glm::vec2(w, h)) * 2.0f - 1.0f;
            const glm::vec4 far = inv * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 d = glm::normalize(glm::vec3(far) / far.w - cam.eye);
            const float bq = glm::dot(cam.eye, d), cq = glm::dot(cam.eye, cam.eye) - 1.0f;
            const float disc = std::max(bq * bq - cq, 0.0f);
            b.mass += a;
            onSphere += a * glm::dvec3(cam.eye + (-bq - std::sqrt(disc)) * d);
        }
    if (b.mass > 0.0)
        b.centroid = glm::dvec2(core::projectToPixels(cam, p.options().size, glm::normalize(glm::vec3(onSphere))));
    return b;
}

glm::dvec2 expectedPx(const session::Playback& p, float turn) {
    const glm::vec3 q = glm::rotate(kStart, turn, kAxis);
    return glm::dvec2(core::projectToPixels(p.lastFrame().camera, p.options().size, q));
}

// Band voxels holding more than half the ink: the blob's area on the surface, in voxels.
size_t inkedVoxels(const session::Playback& p) {
    size_t n = 0;
    for (const glm::vec4& v : p.dye().field()->readValues()) n += v.a > 0.5f;
    return n;
}

}  // namespace

// A quarter, a half and a whole turn of the blob at 512 x 512.
TEST(Dye, BlobFollowsTheRotationHidesAndComesBack) {
    core::DatasetSteps steps(core::makeBuiltin("builtin:sphere:20000"));
    session::Playback p(dyeOptions("isa", 512));
    p.open(steps);
    p.start(false);
    p.advance();  // frame 0: released
    const Blob b0 = measure(p);
    const size_t area0 = inkedVoxels(p);
    ASSERT_GT(b0.mass, 100.0);
    EXPECT_LT(glm::distance(b0.centroid, expectedPx(p, 0.0f)), 2.0);
    for (int f = 1; f <= kQuarter; ++f) p.advance();
    const Blob b1 = measure(p);
    EXPECT_LT(glm::distance(b1.centroid, expectedPx(p, glm::half_pi<float>())), 2.0)
        << "at " << b1.centroid.x << "," << b1.centroid.y;
    const double areaRatio = double(inkedVoxels(p)) / double(area0);
    EXPECT_GT(areaRatio, 0.7);
    EXPECT_LT(areaRatio, 1.3);
    for (int f = kQuarter + 1; f <= 2 * kQuarter; ++f) p.advance();
    EXPECT_LT(measure(p).mass, 0.5) << "half a turn: behind the sphere";
    EXPECT_GT(inkedVoxels(p), area0 / 2) << "and still there";
    for (int f = 2 * kQuarter + 1; f <= 4 * kQuarter; ++f) p.advance();
    const Blob b4 = measure(p);
    std::printf("dye blob: quarter turn %.2f px off, area x%.2f; whole turn %.2f px off\n",
                glm::distance(b1.centroid, expectedPx(p, glm::half_pi<float>())), areaRatio,
                glm::distance(b4.centroid, b0.centroid));
    EXPECT_GT(b4.mass, 0.5 * b0.mass);
    EXPECT_LT(glm::distance(b4.centroid, b0.centroid), 3.0) << "a whole turn: back at the start";
}

// A continuous source draws a streakline: ink along the circle the rotation moves the
// source on, over the arc covered, and nowhere else.
TEST(Dye, ContinuousSourceDrawsAStreaklineAlongTheCircle) {
    core::DatasetSteps steps(core::makeBuiltin("builtin:sphere:20000"));
    session::RenderOptions o = dyeOptions("isa", 256);
    o.dyeRelease = 0;
    session::Playback p(o);
    p.open(steps);
    p.start(false);
    for (int f = 0; f <= kQuarter; ++f) p.advance();
    const methods::DyeBand& band = p.dye().field()->band();
    const std::vector<glm::vec4> v = p.dye().field()->readValues();
    const glm::vec3 src = glm::normalize(kStart);
    const float height = glm::dot(src, kAxis);  // the circle: dot(p, axis) = height
    const glm::vec3 u = glm::normalize(src - height * kAxis), w = glm::cross(kAxis, u);
    float maxAngle = 0.0f, worst = 0.0f;
    for (size_t i = 0; i < band.size(); ++i) {
        if (v[i].a < 0.5f) continue;
        const glm::vec3 q = glm::normalize(band.closest[i]);
        worst = std::max(worst, std::abs(glm::dot(q, kAxis) - height));
        maxAngle = std::max(maxAngle, std::atan2(glm::dot(q, w), glm::dot(q, u)));
    }
    EXPECT_LT(worst, 0.12f + 0.03f) << "ink off the circle (source radius 0.12)";
    // The first ink has turned a quarter (minus the source's own half-width).
    EXPECT_GT(maxAngle, glm::half_pi<float>() - 0.12f - 0.1f);
    EXPECT_LT(maxAngle, glm::half_pi<float>() + 0.12f + 0.1f);
}

class DyeMethods : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(Methods, DyeMethods, ::testing::Values("isa", "ibfvs", "hybrid"),
                         [](const auto& info) { return info.param; });

// Every method shows the blob where the rotation carries it, seen by an orbiting camera,
// never on the background; the compute and fragment overlays agree.
TEST_P(DyeMethods, BlobUnderAnOrbitingCameraOnEveryMethodAndPath) {
    core::DatasetSteps steps(core::makeBuiltin("builtin:sphere:20000"));
    session::RenderOptions o = dyeOptions(GetParam(), 256);
    o.orbit = -2.0f;  // degrees per frame about the up axis
    std::vector<uint8_t> images[2];
    for (int path = 0; path < 2; ++path) {
        session::setOption(o, "gl-path", path == 0 ? "compute" : "fragment");
        session::Playback p(o);
        p.open(steps);
        p.start(false);
        for (int f = 0; f <= kQuarter / 2; ++f) p.advance();
        const Blob b = measure(p);
        ASSERT_GT(b.mass, 20.0);
        EXPECT_LT(glm::distance(b.centroid, expectedPx(p, glm::quarter_pi<float>())), 2.0);
        int w = 0, h = 0;
        images[path] = p.readImage(&w, &h);
        // Dye never off the surface: where the depth says background, the background colour.
        const std::vector<float> depth = gl::readDepth(p.views()[0]->surfaceDepth());  // rows bottom to top
        const std::vector<uint8_t>& img = images[path];
        size_t off = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (depth[size_t(h - 1 - y) * w + x] >= 1.0f) off += img[(size_t(y) * w + x) * 3] != 0;
        EXPECT_EQ(off, 0u);
    }
    EXPECT_EQ(images[0], images[1]);
}

// A time series (the double gyre, steps interpolated): the dye goes on over the steps with
// each step's field (the band is kept: interpolated positions of a fixed mesh round, but
// stay within a tenth of a voxel) and a continuous source draws a growing streak.
TEST(Dye, TimeSeriesCarriesDyeOverTheSteps) {
    core::DatasetSteps steps(core::makeBuiltin("builtin:double-gyre"));
    session::RenderOptions o;
    o.input = "builtin:double-gyre";
    o.size = {160, 100};
    o.frames = 40;
    session::setOption(o, "dye", "0.5,0.15,0:0.04:red");
    session::Playback p(o);
    p.open(steps);
    p.start(false);
    p.advance();
    const methods::DyeField* first = p.dye().field();
    const size_t area0 = inkedVoxels(p);
    for (int f = 1; f <= 40; ++f) p.advance();
    EXPECT_EQ(p.dye().field(), first) << "the band was made again: the dye started over";
    EXPECT_GT(inkedVoxels(p), 4 * area0);
}
