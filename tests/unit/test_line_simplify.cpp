// The topology lines simplified for a view (methods/skeleton_layer/line_simplify.h): no
// dropped vertex lies farther than the tolerance from what is drawn, on screen or in depth;
// a line's ends are always drawn; nothing is joined across the eye; pieces wholly outside
// the view go, their neighbours' joins stay; the same camera gives the same pieces.
#include "methods/skeleton_layer/line_simplify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace flowsurf;
using methods::SimplifyParams;
using methods::ViewPiece;
using methods::ViewVertex;

namespace {

// Looking down -z at the origin from (0, 0, 5), 200 x 200 px, 90 degrees: the plane z = 0
// spans +-5 units over the image, 20 px a unit.
core::Camera frontCamera() {
    core::Camera c;
    c.eye = {0, 0, 5};
    c.target = {0, 0, 0};
    c.fovDeg = 90.0f;
    c.nearPlane = 0.5f;
    c.farPlane = 20.0f;
    return c;
}
const core::Viewport kView{200, 200};

skeleton::SkeletonLine line(std::vector<glm::vec3> pointsObj) {
    skeleton::SkeletonLine l;
    l.points = std::move(pointsObj);
    return l;
}

std::vector<glm::vec3> circle(float radius, int n) {
    std::vector<glm::vec3> p;
    for (int i = 0; i <= n; ++i) {
        const float a = 6.2831853f * float(i) / float(n);
        p.emplace_back(radius * std::cos(a), radius * std::sin(a), 0.0f);
    }
    return p;
}

double distanceToSegment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double t = glm::dot(ab, ab) > 0.0 ? std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

}  // namespace

TEST(LineSimplify, AStraightLineIsOnePieceWithBothCaps) {
    std::vector<glm::vec3> p;
    for (int i = 0; i <= 100; ++i) p.emplace_back(-3.0f + 0.06f * float(i), 0.5f + 0.01f * float(i), 0.0f);
    const std::vector<skeleton::SkeletonLine> lines{line(p)};
    const std::vector<ViewPiece> pieces = methods::viewPieces(lines, frontCamera(), kView, {});
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_EQ(pieces[0].a, 0u);
    EXPECT_EQ(pieces[0].b, 100u);
    EXPECT_EQ(pieces[0].prev, pieces[0].a);  // no neighbour: a round cap at each end
    EXPECT_EQ(pieces[0].next, pieces[0].b);
}

// A circle of 60 px radius in 2,000 pieces: about the pieces a 0.5 px sagitta allows
// (2 pi / (2 sqrt(2 x 0.5 / 60)) = 24), every dropped vertex within 0.5 px of its piece.
TEST(LineSimplify, ACircleKeepsWhatTheTolerancePermitsAndNoVertexMovesMore) {
    for (bool ortho : {false, true}) {
        SCOPED_TRACE(ortho ? "orthographic" : "perspective");
        core::Camera camera = frontCamera();
        if (ortho) camera.orthoHeight = 10.0f;  // 20 px a unit as well
        const std::vector<glm::vec3> p = circle(3.0f, 2000);
        const SimplifyParams params;
        const std::vector<ViewVertex> v = methods::projectLine(p, camera, kView);
        const std::vector<uint32_t> kept = methods::keptVertices(v, ortho, params);
        EXPECT_EQ(kept.front(), 0u);
        EXPECT_EQ(kept.back(), 2000u);
        EXPECT_GE(kept.size(), 20u);
        EXPECT_LE(kept.size(), 50u);
        double worst = 0.0;
        for (size_t k = 0; k + 1 < kept.size(); ++k)
            for (uint32_t i = kept[k] + 1; i < kept[k + 1]; ++i) {
                worst = std::max(worst, distanceToSegment(v[i].px, v[kept[k]].px, v[kept[k + 1]].px));
                EXPECT_LE(methods::deviation(v[i], v[kept[k]], v[kept[k + 1]], ortho, params), 1.0);
            }
        EXPECT_LE(worst, params.tolerancePx);
        EXPECT_GT(worst, 0.25 * params.tolerancePx);  // it does use it (Douglas-Peucker splits below it)
    }
}

// In the plane y = 0 every point projects to the image's middle row: a line that bends
// towards the eye is straight on screen, and its bend is kept for the depth test.
TEST(LineSimplify, ABendInDepthStraightOnScreenIsKept) {
    const SimplifyParams params;
    const std::vector<glm::vec3> bent{{-2, 0, 0}, {-1, 0, 0.5f}, {0, 0, 1}, {1, 0, 0.5f}, {2, 0, 0}};
    const std::vector<ViewVertex> v = methods::projectLine(bent, frontCamera(), kView);
    for (const ViewVertex& x : v) EXPECT_NEAR(x.px.y, 100.0, 1e-9);
    EXPECT_EQ(methods::keptVertices(v, false, params), (std::vector<uint32_t>{0, 2, 4}));
    // the same bend of a millionth of the distance goes
    const std::vector<glm::vec3> flat{{-2, 0, 0}, {0, 0, 5e-6f}, {2, 0, 0}};
    EXPECT_EQ(methods::keptVertices(methods::projectLine(flat, frontCamera(), kView), false, params),
              (std::vector<uint32_t>{0, 2}));
}

// A line from in front of the eye to behind it and back: the vertices behind and their
// neighbours kept (no piece bridges the eye), the pieces touching them not drawn.
TEST(LineSimplify, NothingIsJoinedAcrossTheEye) {
    std::vector<glm::vec3> p;
    for (int i = 0; i <= 20; ++i) p.emplace_back(0.1f, 0.1f, 4.0f + 0.1f * float(i > 10 ? 20 - i : i) * 3.0f);
    // z from 4 to 7 (behind the eye at z = 5 from i = 4 on) and back to 4
    const std::vector<ViewVertex> v = methods::projectLine(p, frontCamera(), kView);
    const std::vector<uint32_t> kept = methods::keptVertices(v, false, {});
    for (size_t i = 0; i < v.size(); ++i)
        if (!v[i].inFront) {
            EXPECT_NE(std::find(kept.begin(), kept.end(), uint32_t(i)), kept.end()) << i;
            if (i > 0 && v[i - 1].inFront) {
                EXPECT_NE(std::find(kept.begin(), kept.end(), uint32_t(i - 1)), kept.end());
            }
            if (i + 1 < v.size() && v[i + 1].inFront) {
                EXPECT_NE(std::find(kept.begin(), kept.end(), uint32_t(i + 1)), kept.end());
            }
        }
    const std::vector<skeleton::SkeletonLine> lines{line(p)};
    for (const ViewPiece& q : methods::viewPieces(lines, frontCamera(), kView, {}))
        EXPECT_TRUE(v[q.a].inFront && v[q.b].inFront) << q.a << "-" << q.b;
}

// A zigzag from far left of the view into it: the pieces wholly beyond the left edge (and
// reachPx) go, the first one drawn still joins its kept neighbour off screen; the right end
// in view keeps its cap.
TEST(LineSimplify, PiecesOutsideTheViewGoTheirNeighboursJoinsStay) {
    std::vector<glm::vec3> p;
    for (int i = 0; i <= 40; ++i) p.emplace_back(-12.0f + 0.3f * float(i), (i % 2) ? 0.5f : -0.5f, 0.0f);
    const std::vector<skeleton::SkeletonLine> lines{line(p)};
    SimplifyParams params;
    const std::vector<ViewPiece> pieces = methods::viewPieces(lines, frontCamera(), kView, params);
    const std::vector<ViewVertex> v = methods::projectLine(p, frontCamera(), kView);
    ASSERT_FALSE(pieces.empty());
    EXPECT_LT(pieces.size(), 40u);
    for (const ViewPiece& q : pieces) EXPECT_FALSE(v[q.a].px.x < -params.reachPx && v[q.b].px.x < -params.reachPx);
    EXPECT_NE(pieces.front().prev, pieces.front().a);
    EXPECT_LT(v[pieces.front().a].px.x, 0.0);  // the first drawn starts off screen: no gap at the edge
    EXPECT_EQ(pieces.back().b, 40u);
    EXPECT_EQ(pieces.back().next, 40u);
    for (size_t k = 0; k + 1 < pieces.size(); ++k) {  // consecutive, each the next's neighbour
        EXPECT_EQ(pieces[k].b, pieces[k + 1].a);
        EXPECT_EQ(pieces[k].next, pieces[k + 1].b);
        EXPECT_EQ(pieces[k + 1].prev, pieces[k].a);
    }
}

TEST(LineSimplify, TheSameCameraGivesTheSamePiecesEveryLineItsEnds) {
    std::vector<skeleton::SkeletonLine> lines{line(circle(2.0f, 500)), line(circle(1.0f, 300))};
    for (glm::vec3& x : lines[1].points) x = glm::vec3(x.x + 0.5f, x.y, 0.3f * x.x);
    lines[1].points.resize(200);  // an open arc
    core::Camera camera = frontCamera();
    camera.eye = {1.0f, 2.0f, 4.0f};
    const std::vector<ViewPiece> a = methods::viewPieces(lines, camera, kView, {});
    const std::vector<ViewPiece> b = methods::viewPieces(lines, camera, kView, {});
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].line, b[i].line);
        EXPECT_EQ(a[i].a, b[i].a);
        EXPECT_EQ(a[i].b, b[i].b);
    }
    for (uint32_t l = 0; l < 2; ++l) {
        const uint32_t last = uint32_t(lines[l].points.size() - 1);
        bool first = false, end = false;
        for (const ViewPiece& q : a) {
            first |= q.line == l && q.a == 0 && q.prev == 0;
            end |= q.line == l && q.b == last && q.next == last;
        }
        EXPECT_TRUE(first && end) << "line " << l;
    }
}
