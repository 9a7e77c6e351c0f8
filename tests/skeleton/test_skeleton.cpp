// The flow topology of analytic fields whose answers are known exactly: every point type
// on a plane, closed surfaces (index sum = Euler characteristic), patches with duplicated
// seam vertices, open separation and attachment, the saddle's separatrices, and the same
// answers under white noise of 2 % of the 99th-percentile speed at every vertex.
#include "core/builtin_scenes.h"
#include "core/errors.h"
#include "core/noise.h"
#include "skeleton/skeleton.h"
#include "skeleton/surface_graph.h"
#include "skeleton/tangent_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

using namespace flowsurf;
using skeleton::PointType;

namespace {

// The square [-1, 1]^2 in z = 0, n x n cells.
core::SurfaceMesh square(int n = 60) {
    return core::makeRectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0f, 2.0f, n, n);
}

std::vector<glm::vec3> sample(const core::SurfaceMesh& m, const std::function<glm::vec2(glm::vec2)>& f) {
    std::vector<glm::vec3> v;
    for (const glm::vec3& p : m.positions) {
        const glm::vec2 w = f({p.x, p.y});
        v.push_back({w.x, w.y, 0.0f});
    }
    return v;
}

// White noise of `fraction` of the 99th-percentile speed, uniform in direction, fixed seed.
void addNoise(std::vector<glm::vec3>& field, const std::vector<glm::vec3>& normals, float fraction) {
    std::vector<float> speed;
    for (const auto& v : field) speed.push_back(glm::length(v));
    std::nth_element(speed.begin(), speed.begin() + long(0.99 * double(speed.size())), speed.end());
    const float amp = fraction * speed[size_t(0.99 * double(speed.size()))];
    std::mt19937 rng(7);
    std::normal_distribution<float> g(0.0f, 1.0f);
    for (size_t i = 0; i < field.size(); ++i) {
        glm::vec3 r(g(rng), g(rng), g(rng));
        r -= glm::dot(r, normals[i]) * normals[i];
        if (glm::length(r) > 0.0f) field[i] += amp * glm::normalize(r);
    }
}

skeleton::Skeleton run(const core::SurfaceMesh& m, const std::vector<glm::vec3>& f,
                       skeleton::SkeletonParams p = {}) {
    return skeleton::analyze(m, f, p, "test");
}

// The line tests' fields converge at a few e-folds over the square, below the default
// strength (chosen on the project's CFD surfaces, whose features are far stronger).
skeleton::SkeletonParams lineParams() {
    skeleton::SkeletonParams p;
    p.lineStrength = 1.0f;
    return p;
}

const glm::vec2 kAt{0.113f, -0.071f};  // off the grid's vertices

struct Case {
    const char* name;
    std::function<glm::vec2(glm::vec2)> field;
    PointType type;
    int index;
};

std::vector<Case> linearCases() {
    auto at = [](glm::vec2 p) { return p - kAt; };
    return {
        {"source", [=](glm::vec2 p) { glm::vec2 d = at(p); return glm::vec2(d.x, 2.0f * d.y); }, PointType::Source, 1},
        {"sink", [=](glm::vec2 p) { glm::vec2 d = at(p); return glm::vec2(-2.0f * d.x, -d.y); }, PointType::Sink, 1},
        {"star-sink", [=](glm::vec2 p) { return -at(p); }, PointType::Sink, 1},
        {"saddle", [=](glm::vec2 p) { glm::vec2 d = at(p); return glm::vec2(d.x, -d.y); }, PointType::Saddle, -1},
        {"center", [=](glm::vec2 p) { glm::vec2 d = at(p); return glm::vec2(-d.y, d.x); }, PointType::Center, 1},
        {"repelling-focus", [=](glm::vec2 p) { glm::vec2 d = at(p); return glm::vec2(0.4f * d.x - d.y, d.x + 0.4f * d.y); },
         PointType::RepellingFocus, 1},
        {"attracting-focus",
         [=](glm::vec2 p) { glm::vec2 d = at(p); return glm::vec2(-0.4f * d.x - d.y, d.x - 0.4f * d.y); },
         PointType::AttractingFocus, 1},
    };
}

}  // namespace

TEST(Skeleton, EveryPointTypeOnAPlaneAtItsPlace) {
    const core::SurfaceMesh m = square();
    for (const Case& c : linearCases()) {
        SCOPED_TRACE(c.name);
        const skeleton::Skeleton s = run(m, sample(m, c.field));
        ASSERT_EQ(s.criticalPoints.size(), 1u);
        const skeleton::CriticalPoint& p = s.criticalPoints[0];
        EXPECT_EQ(p.type, c.type);
        EXPECT_EQ(p.index, c.index);
        EXPECT_NEAR(p.position.x, kAt.x, 1e-3f);  // the linear interpolant is exact for a linear field
        EXPECT_NEAR(p.position.y, kAt.y, 1e-3f);
        EXPECT_EQ(s.eulerCharacteristic, 1);  // a disc
        EXPECT_FALSE(s.closed);
    }
}

TEST(Skeleton, WhiteNoiseOfTwoPercentGivesTheCleanAnswer) {
    const core::SurfaceMesh m = square(80);
    for (const Case& c : linearCases()) {
        SCOPED_TRACE(c.name);
        std::vector<glm::vec3> f = sample(m, c.field);
        addNoise(f, m.normals, 0.02f);
        const skeleton::Skeleton s = run(m, f);
        ASSERT_EQ(s.criticalPoints.size(), 1u) << s.zeros << " zeros before merging";
        EXPECT_EQ(s.criticalPoints[0].type, c.type);
        EXPECT_LT(glm::length(glm::vec2(s.criticalPoints[0].position) - kAt), 0.05f);
    }
}

TEST(Skeleton, WithoutCancellationNoiseMakesSpuriousPairs) {
    // The property the cancellation rule exists for: the same noisy field read without it
    // finds more zeros, and their index still sums to the clean one.
    const core::SurfaceMesh m = square(80);
    std::vector<glm::vec3> f = sample(m, linearCases()[3].field);
    addNoise(f, m.normals, 0.2f);
    skeleton::SkeletonParams p;
    p.cancelSpeed = 0.0f;
    p.scale = 1e-6f;  // no smoothing
    const skeleton::Skeleton s = run(m, f, p);
    EXPECT_GT(s.criticalPoints.size(), 1u);
    EXPECT_EQ(s.indexSum, -1);
}

TEST(Skeleton, ClosedSurfacesIndexSumIsTheEulerCharacteristic) {
    // The sphere's tangential part of a constant direction: a source at one pole, a sink at the other.
    core::SurfaceMesh sphere = core::makeUvSphere(1.0f, 64, 32);
    std::vector<glm::vec3> f;
    for (const glm::vec3& n : sphere.normals) f.push_back(glm::vec3(0, 0, 1) - n.z * n);
    skeleton::Skeleton s = run(sphere, f);
    EXPECT_TRUE(s.closed);
    EXPECT_EQ(s.eulerCharacteristic, 2);
    EXPECT_EQ(s.indexSum, 2);
    ASSERT_EQ(s.criticalPoints.size(), 2u);
    for (const auto& p : s.criticalPoints) {
        EXPECT_NEAR(std::abs(p.position.z), 1.0f, 0.02f);
        EXPECT_EQ(p.type, p.position.z > 0 ? PointType::Sink : PointType::Source);
    }
    // Solid-body rotation about z: two centres.
    f.clear();
    for (const glm::vec3& p : sphere.positions) f.push_back({-p.y, p.x, 0.0f});
    s = run(sphere, f);
    ASSERT_EQ(s.criticalPoints.size(), 2u);
    for (const auto& p : s.criticalPoints) EXPECT_EQ(p.type, PointType::Center);
    // And with noise: the index sum stays 2 and no spurious pair survives.
    addNoise(f, sphere.normals, 0.02f);
    s = run(sphere, f);
    EXPECT_EQ(s.indexSum, 2);
    EXPECT_EQ(s.criticalPoints.size(), 2u);

    // A torus (axis y) with flow around its tube's big circle: no zero, index sum 0 = chi.
    core::SurfaceMesh torus = core::makeTorus({0, 0, 0}, 1.0f, 0.3f, 64, 24);
    f.clear();
    for (const glm::vec3& p : torus.positions) f.push_back({p.z, 0.0f, -p.x});
    s = run(torus, f);
    EXPECT_TRUE(s.closed);
    EXPECT_EQ(s.eulerCharacteristic, 0);
    EXPECT_EQ(s.indexSum, 0);
    EXPECT_TRUE(s.criticalPoints.empty());
}

TEST(Skeleton, PatchesWithDuplicatedSeamVerticesAreOneSurface) {
    // Two halves of the square, each with its own copy of the seam's vertices.
    core::SurfaceMesh left = core::makeRectangle({-0.5f, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0f, 2.0f, 30, 60);
    core::SurfaceMesh right = core::makeRectangle({0.5f, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0f, 2.0f, 30, 60);
    left.fields.clear();
    right.fields.clear();
    core::appendMesh(left, right);
    // a saddle exactly on the seam x = 0
    const std::vector<glm::vec3> f = sample(left, [](glm::vec2 p) { return glm::vec2(p.x, -(p.y - 0.07f)); });
    const skeleton::Skeleton s = run(left, f);
    EXPECT_EQ(s.parts, 1u);
    EXPECT_EQ(s.eulerCharacteristic, 1);
    ASSERT_EQ(s.criticalPoints.size(), 1u);
    EXPECT_EQ(s.criticalPoints[0].type, PointType::Saddle);
}

TEST(Skeleton, FlippedAndDegenerateTrianglesGiveTheSameSurface) {
    // Every other triangle wound the other way, and two zero-area triangles appended: the
    // same edges, boundary, Euler characteristic and saddle as the clean square.
    const core::SurfaceMesh clean = square(40);
    core::SurfaceMesh m = clean;
    for (size_t i = 0; i < m.triangles.size(); i += 2) std::swap(m.triangles[i].y, m.triangles[i].z);
    m.triangles.push_back({0, 0, 1});
    m.triangles.push_back({0, 1, 2});  // three vertices on the bottom edge: a line, no area
    const skeleton::SurfaceGraph a = skeleton::buildSurfaceGraph(clean), b = skeleton::buildSurfaceGraph(m);
    EXPECT_EQ(b.triangles.size(), clean.triangles.size());
    EXPECT_EQ(b.edgeCount, a.edgeCount);
    EXPECT_EQ(b.boundaryEdges, a.boundaryEdges);
    EXPECT_EQ(b.boundaryEdges, 4u * 40u);
    EXPECT_EQ(b.nonManifoldEdges, 0u);
    EXPECT_EQ(b.eulerCharacteristic(), 1);
    EXPECT_EQ(b.neighbours, a.neighbours);
    const auto f = sample(m, [](glm::vec2 p) { return glm::vec2(p.x - 0.11f, -(p.y + 0.07f)); });
    const skeleton::Skeleton s = run(m, f);
    ASSERT_EQ(s.criticalPoints.size(), 1u);
    EXPECT_EQ(s.criticalPoints[0].type, PointType::Saddle);
    EXPECT_NEAR(s.criticalPoints[0].position.x, 0.11f, 1e-3f);
}

TEST(Skeleton, AFanOfManyTrianglesAtOneVertexIsCountedOnce) {
    // A disc of 3000 triangles around one centre vertex: 3000 neighbours there, one part.
    core::SurfaceMesh m;
    const int n = 3000;
    m.positions.push_back({0, 0, 0});
    m.normals.push_back({0, 0, 1});
    for (int i = 0; i < n; ++i) {
        const float a = 6.2831853f * float(i) / float(n);
        m.positions.push_back({std::cos(a), std::sin(a), 0.0f});
        m.normals.push_back({0, 0, 1});
        m.triangles.push_back({0u, uint32_t(1 + i), uint32_t(1 + (i + 1) % n)});
    }
    const skeleton::SurfaceGraph g = skeleton::buildSurfaceGraph(m);
    EXPECT_EQ(g.neighbourStart[1] - g.neighbourStart[0], uint32_t(n));
    EXPECT_EQ(g.edgeCount, size_t(2 * n));
    EXPECT_EQ(g.boundaryEdges, size_t(n));
    EXPECT_EQ(g.eulerCharacteristic(), 1);
}

namespace {

const skeleton::SkeletonLine* longest(const skeleton::Skeleton& s, skeleton::LineKind kind) {
    const skeleton::SkeletonLine* best = nullptr;
    for (const auto& l : s.lines)
        if (l.kind == kind && (!best || l.length > best->length)) best = &l;
    return best;
}

}  // namespace

TEST(Skeleton, OpenSeparationAndAttachmentWithoutACriticalPoint) {
    const core::SurfaceMesh m = square();
    for (bool attach : {false, true}) {
        SCOPED_TRACE(attach ? "attachment" : "separation");
        const float k = attach ? 1.5f : -1.5f;
        std::vector<glm::vec3> f = sample(m, [=](glm::vec2 p) { return glm::vec2(1.0f, k * (p.y - 0.1037f)); });
        for (bool noisy : {false, true}) {
            if (noisy) addNoise(f, m.normals, 0.02f);
            const skeleton::Skeleton s = run(m, f, lineParams());
            EXPECT_TRUE(s.criticalPoints.empty());
            const auto kind = attach ? skeleton::LineKind::Attachment : skeleton::LineKind::Separation;
            const skeleton::SkeletonLine* l = longest(s, kind);
            ASSERT_NE(l, nullptr);
            EXPECT_GT(l->length, 1.6f);  // across most of the square
            for (const glm::vec3& p : l->points) EXPECT_NEAR(p.y, 0.1037f, 0.05f);
            EXPECT_EQ(longest(s, attach ? skeleton::LineKind::Separation : skeleton::LineKind::Attachment), nullptr);
        }
    }
}

TEST(Skeleton, SaddleSeparatricesAreOneLineOfEachKind) {
    const core::SurfaceMesh m = square();
    const skeleton::Skeleton s =
        run(m, sample(m, [](glm::vec2 p) { return glm::vec2(p.x - kAt.x, -(p.y - kAt.y)); }), lineParams());
    // The unstable manifold (along x) gathers the flow, the stable one (along y) spreads it;
    // each kind's lines (the two separatrices, which meet at the saddle) span the square.
    float length[2] = {0.0f, 0.0f};
    for (const auto& l : s.lines) {
        length[size_t(l.kind)] += l.length;
        for (const glm::vec3& p : l.points) {
            if (l.kind == skeleton::LineKind::Separation) EXPECT_NEAR(p.y, kAt.y, 0.05f);
            else EXPECT_NEAR(p.x, kAt.x, 0.05f);
        }
    }
    EXPECT_GT(length[0], 1.7f);
    EXPECT_GT(length[1], 1.7f);
}

TEST(Skeleton, ANodesStrongDirectionIsNoAttachmentLine) {
    // Source with rates 1 along x and 3 along y: the flow leaves along y (strong) and spreads
    // from the x axis (weak): only the x axis is an attachment line.
    const core::SurfaceMesh m = square();
    const skeleton::Skeleton s =
        run(m, sample(m, [](glm::vec2 p) { return glm::vec2(p.x - kAt.x, 3.0f * (p.y - kAt.y)); }), lineParams());
    const skeleton::SkeletonLine* att = longest(s, skeleton::LineKind::Attachment);
    ASSERT_NE(att, nullptr);
    for (const glm::vec3& p : att->points) EXPECT_NEAR(p.y, kAt.y, 0.05f);
    for (const auto& l : s.lines)
        for (const glm::vec3& p : l.points)
            if (std::abs(p.y - kAt.y) > 0.1f) ADD_FAILURE() << "a line off the x axis at " << p.x << "," << p.y;
}

TEST(Skeleton, DivergenceOfALinearFieldIsItsTrace) {
    const core::SurfaceMesh m = square(20);
    const auto f = sample(m, [](glm::vec2 p) { return glm::vec2(2.0f * p.x + p.y, 0.5f * p.y); });
    const skeleton::SurfaceGraph g = skeleton::buildSurfaceGraph(m);
    const std::vector<float> d = skeleton::divergence(g, skeleton::weldValues(g, f));
    ASSERT_EQ(d.size(), m.vertexCount());
    for (float v : d) EXPECT_NEAR(v, 2.5f, 1e-3f);
    // normalised: div(v/|v|) of the radial field in the plane is 1/r
    const auto radial = sample(m, [](glm::vec2 p) { return p; });
    const std::vector<float> nd = skeleton::normalizedDivergence(g, skeleton::weldValues(g, radial));
    for (size_t i = 0; i < m.vertexCount(); ++i) {
        const float r = glm::length(glm::vec2(m.positions[i]));
        if (r > 0.5f) { EXPECT_NEAR(nd[i], 1.0f / r, 0.1f / r); }
        if (r == 0.0f) { EXPECT_TRUE(std::isnan(nd[i])); }
    }
}

TEST(Skeleton, RefusesWhatHasNoTopology) {
    const core::SurfaceMesh m = square(4);
    EXPECT_THROW(run(m, std::vector<glm::vec3>(m.vertexCount(), glm::vec3(0.0f))), FieldError);
    EXPECT_THROW(run(m, std::vector<glm::vec3>(m.vertexCount(), glm::vec3(0, 0, 1))), FieldError);  // normal only
    core::SurfaceMesh empty = m;
    empty.triangles.clear();
    EXPECT_THROW(run(empty, std::vector<glm::vec3>(m.vertexCount(), glm::vec3(1, 0, 0))), FieldError);
    skeleton::SkeletonParams bad;
    bad.cancelSpeed = 2.0f;
    EXPECT_THROW(run(m, std::vector<glm::vec3>(m.vertexCount(), glm::vec3(1, 0, 0)), bad), ConfigError);
}

TEST(Skeleton, ACentreIsToldFromAWeakFocusByTheSpiralRatio) {
    // Re/Im of the eigenvalues: 0.05 is a centre, 0.3 a focus, at the default ratio 0.1.
    const core::SurfaceMesh m = square();
    for (auto [ratio, type] : {std::pair{0.05f, PointType::Center}, std::pair{0.3f, PointType::RepellingFocus},
                               std::pair{-0.3f, PointType::AttractingFocus}}) {
        const skeleton::Skeleton s = run(m, sample(m, [r = ratio](glm::vec2 p) {
            const glm::vec2 d = p - kAt;
            return glm::vec2(r * d.x - d.y, d.x + r * d.y);
        }));
        ASSERT_EQ(s.criticalPoints.size(), 1u);
        EXPECT_EQ(s.criticalPoints[0].type, type) << ratio;
    }
}

TEST(Skeleton, ExtremeParametersAnswerWithoutOverflow) {
    const core::SurfaceMesh m = square(10);
    const auto f = sample(m, [](glm::vec2 p) { return glm::vec2(p.x - kAt.x, -(p.y - kAt.y)); });
    skeleton::SkeletonParams p;
    p.scale = 1e30f;          // the smoothing passes are capped
    p.weldTolerance = 0.0f;   // only exact duplicates weld
    p.cancelSpeed = 1.0f;     // everything slow merges into the net index
    const skeleton::Skeleton s = run(m, f, p);
    EXPECT_EQ(s.indexSum, -1);
    p = {};
    p.scale = 1e-30f;
    p.lineLength = 0.0f;
    p.lineStrength = 0.0f;
    EXPECT_EQ(run(m, f, p).criticalPoints.size(), 1u);
}

TEST(Skeleton, AZeroExactlyOnAVertexIsFoundOnce) {
    // The 60 x 60 square has a vertex at the origin; nodes and a saddle on vertices of a sphere's
    // equator ring (the gradient of (x^2 - y^2) / 2, tangential: zeros at +-x, +-y, +-z).
    const core::SurfaceMesh m = square();
    for (const Case& c : {Case{"source", [](glm::vec2 p) { return glm::vec2(p.x, 2.0f * p.y); }, PointType::Source, 1},
                          Case{"saddle", [](glm::vec2 p) { return glm::vec2(p.x, -p.y); }, PointType::Saddle, -1}}) {
        SCOPED_TRACE(c.name);
        const skeleton::Skeleton s = run(m, sample(m, c.field));
        ASSERT_EQ(s.criticalPoints.size(), 1u);
        EXPECT_EQ(s.criticalPoints[0].type, c.type);
        EXPECT_LT(glm::length(s.criticalPoints[0].position), 0.05f);
    }
    core::SurfaceMesh sphere = core::makeUvSphere(1.0f, 64, 32);  // a vertex ring on the equator
    std::vector<glm::vec3> f;
    for (size_t i = 0; i < sphere.vertexCount(); ++i) {
        const glm::vec3 p = sphere.positions[i], n = sphere.normals[i];
        const glm::vec3 g(p.x, -p.y, 0.0f);
        f.push_back(g - glm::dot(g, n) * n);
    }
    const skeleton::Skeleton s = run(sphere, f);
    EXPECT_EQ(s.indexSum, 2);
    EXPECT_EQ(s.criticalPoints.size(), 6u);
}
