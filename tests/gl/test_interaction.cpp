// IBFVS boundary treatment and the interaction remedies [L §IV-E.2, §IV-F, §IV-I].
#include "core/builtin_scenes.h"
#include "gl/readback.h"
#include "gl_test_util.h"
#include "methods/make_renderer.h"
#include "raster/surface_gpu.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <queue>

using namespace flowsurf;

namespace {

// Chamfer-free distance (4-neighbour BFS, pixels) from each surface pixel to the
// nearest background pixel.
std::vector<int> distanceToBackground(const test::Rendered& r) {
    std::vector<int> d(r.depth.size(), -1);
    std::queue<int> q;
    for (int i = 0; i < int(d.size()); ++i)
        if (r.depth[i] >= 1.0f) {
            d[i] = 0;
            q.push(i);
        }
    while (!q.empty()) {
        int i = q.front();
        q.pop();
        int x = i % r.width, y = i / r.width;
        const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
        for (int k = 0; k < 4; ++k) {
            if (nx[k] < 0 || ny[k] < 0 || nx[k] >= r.width || ny[k] >= r.height) continue;
            int j = ny[k] * r.width + nx[k];
            if (d[j] < 0) {
                d[j] = d[i] + 1;
                q.push(j);
            }
        }
    }
    return d;
}

double stddev(const std::vector<float>& v) {
    double s = 0, s2 = 0;
    for (float x : v) {
        s += x;
        s2 += double(x) * x;
    }
    return std::sqrt(std::max(0.0, s2 / v.size() - (s / v.size()) * (s / v.size())));
}

}  // namespace

// With the gray flow background, inflow at silhouettes is nearly invisible: the texture
// contrast in a band just inside the silhouette is at least 80 % of the interior's.
TEST(IbfvsBoundary, ContrastNearSilhouetteStaysHigh) {
    core::Dataset d = core::makeBuiltin("builtin:sphere");
    const core::Viewport vp{320, 320};
    core::Camera cam = core::fitCamera(d.bounds(), vp, {0.3f, 0.4f, 1.0f});
    methods::MethodParams p;
    test::Rendered r = test::renderScene(d, "ibfvs", p, vp, cam, 120);
    std::vector<int> dist = distanceToBackground(r);
    std::vector<float> band, interior;
    for (size_t i = 0; i < dist.size(); ++i) {
        if (dist[i] >= 2 && dist[i] <= 6) band.push_back(r.flow[i]);
        if (dist[i] >= 20) interior.push_back(r.flow[i]);
    }
    ASSERT_GT(band.size(), 500u);
    double ratio = stddev(band) / stddev(interior);
    std::printf("contrast near the silhouette: %.2f of the interior's\n", ratio);
    EXPECT_GE(ratio, 0.8);
}

// The silhouette edge mask darkens silhouette pixels and nothing else.
TEST(IbfvsBoundary, EdgeMaskDarkensOnlySilhouettes) {
    core::Dataset d = core::makeBuiltin("builtin:tori");
    const core::Viewport vp{320, 200};
    core::Camera cam = core::fitCamera(d.bounds(), vp, {0.2f, 0.6f, 1.0f});
    methods::MethodParams p;
    p.common.background = {0.0f, 0.0f, 0.0f};
    methods::SurfaceGpu surface(d.steps[0].mesh, "velocity", p.common, true);
    auto render = [&](bool mask) {
        p.ibfvs.edgeMask = mask;
        auto m = methods::makeMethod("ibfvs", p, vp);
        for (int k = 0; k <= 20; ++k) m->renderFrame({&surface, cam, uint32_t(k)});
        return std::make_pair(gl::readRgb8TopDown(m->composite()), gl::readDepth(m->surfaceDepth()));
    };
    auto [plain, depth] = render(false);
    auto [masked, depth2] = render(true);
    // Silhouette edges computed independently on the CPU: boundary edges and edges whose
    // two triangles face opposite ways as seen from the eye, projected to pixels.
    const core::SurfaceMesh& mesh = d.steps[0].mesh;
    std::map<std::pair<uint32_t, uint32_t>, std::vector<bool>> edges;
    for (const auto& t : mesh.triangles) {
        glm::vec3 n = glm::cross(mesh.positions[t.y] - mesh.positions[t.x], mesh.positions[t.z] - mesh.positions[t.x]);
        bool front = glm::dot(n, cam.eye - mesh.positions[t.x]) > 0.0f;
        for (int e = 0; e < 3; ++e)
            edges[{std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])}].push_back(front);
    }
    std::vector<std::pair<glm::vec2, glm::vec2>> segments;
    for (const auto& [e, faces] : edges)
        if (faces.size() == 1 || faces[0] != faces[1])
            segments.emplace_back(glm::vec2(core::projectToPixels(cam, vp, mesh.positions[e.first])),
                                  glm::vec2(core::projectToPixels(cam, vp, mesh.positions[e.second])));
    auto nearJump = [&](int x, int y) {
        glm::vec2 p(x + 0.5f, y + 0.5f);
        for (const auto& [a, b] : segments) {
            glm::vec2 ab = b - a;
            float t = glm::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
            if (glm::length(p - (a + t * ab)) <= 2.5f) return true;
        }
        return false;
    };
    int changed = 0, changedElsewhere = 0, brighter = 0;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            size_t i = (size_t(vp.height - 1 - y) * vp.width + x) * 3;
            int before = plain[i] + plain[i + 1] + plain[i + 2], after = masked[i] + masked[i + 1] + masked[i + 2];
            if (before == after) continue;
            ++changed;
            if (!nearJump(x, y)) ++changedElsewhere;
            if (after > before) ++brighter;
        }
    std::printf("edge mask changed %d pixels, %d away from silhouettes, %d brighter\n", changed, changedElsewhere,
                brighter);
    EXPECT_GT(changed, 300);
    EXPECT_EQ(changedElsewhere, 0);
    EXPECT_EQ(brighter, 0);
}

// Under a small orbit, the translate remedy keeps the texture on the surface: the new
// F_a at a surface point correlates with the old F_a where that point was; without a
// remedy the pattern stays in image space and slides.
class CameraMoveRemedy : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(Methods, CameraMoveRemedy, ::testing::Values("isa", "ibfvs"),
                         [](const auto& info) { return info.param; });

TEST_P(CameraMoveRemedy, TranslateFollowsTheSurface) {
    core::Dataset d = core::makeBuiltin("builtin:sphere");
    const core::Viewport vp{256, 256};
    core::Camera cam0 = core::fitCamera(d.bounds(), vp, {0.3f, 0.4f, 1.0f});
    core::Camera cam1 = core::orbitCamera(cam0, 8.0f);
    auto correlationAfterMove = [&](methods::CameraMoveRemedy remedy) {
        methods::MethodParams p;
        p.common.onCameraMove = remedy;
        methods::SurfaceGpu surface(d.steps[0].mesh, "velocity", p.common);
        auto m = methods::makeMethod(GetParam(), p, vp);
        for (int k = 0; k < 60; ++k) m->renderFrame({&surface, cam0, uint32_t(k)});
        std::vector<float> before = gl::readChannel(m->flowTexture());
        std::vector<float> depthBefore = gl::readDepth(m->surfaceDepth());
        m->renderFrame({&surface, cam1, 60});
        std::vector<float> after = gl::readChannel(m->flowTexture());
        std::vector<float> depth = gl::readDepth(m->surfaceDepth());
        glm::mat4 inv1 = glm::inverse(cam1.viewProjection(1.0f));
        std::vector<double> now, then;
        for (int y = 4; y < vp.height - 4; ++y)
            for (int x = 4; x < vp.width - 4; ++x) {
                float z = depth[size_t(y) * vp.width + x];
                if (z >= 1.0f) continue;
                glm::vec4 h = inv1 * glm::vec4((x + 0.5f) / vp.width * 2 - 1, (y + 0.5f) / vp.height * 2 - 1, z * 2 - 1, 1);
                glm::vec3 p0 = core::projectToPixels(cam0, vp, glm::vec3(h) / h.w);
                int px = int(p0.x), py = int(p0.y);
                if (px < 0 || py < 0 || px >= vp.width || py >= vp.height) continue;
                // Only points visible in both views: newly uncovered ones have no history.
                if (std::abs(depthBefore[size_t(py) * vp.width + px] - p0.z) > 2e-3f) continue;
                now.push_back(after[size_t(y) * vp.width + x]);
                then.push_back(before[size_t(py) * vp.width + px]);
            }
        return test::pearson(now, then);
    };
    double translate = correlationAfterMove(methods::CameraMoveRemedy::Translate);
    double none = correlationAfterMove(methods::CameraMoveRemedy::None);
    double freeze = correlationAfterMove(methods::CameraMoveRemedy::Freeze);
    std::printf("%s: texture follows the surface: translate %.2f, freeze %.2f, none %.2f\n", GetParam().c_str(),
                translate, freeze, none);
    EXPECT_GT(translate, 0.8);
    EXPECT_GT(freeze, 0.8);
    EXPECT_LT(none, 0.5);
}

// Back-face culling on a closed, outward-oriented surface changes nothing visible: the
// surface mask and the texture equal those without culling.
TEST(IbfvsBoundary, BackFaceCullingKeepsTheVisibleSurface) {
    core::Dataset d = core::makeBuiltin("builtin:tori");
    const core::Viewport vp{160, 100};
    core::Camera cam = core::fitCamera(d.bounds(), vp, {0.2f, 0.6f, 1.0f});
    methods::MethodParams p;
    test::Rendered plain = test::renderScene(d, "ibfvs", p, vp, cam, 10);
    p.common.cullBackFaces = true;
    test::Rendered culled = test::renderScene(d, "ibfvs", p, vp, cam, 10);
    EXPECT_EQ(plain.depth, culled.depth);
    EXPECT_EQ(plain.flow, culled.flow);
}
