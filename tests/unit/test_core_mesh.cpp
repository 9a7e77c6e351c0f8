// Tangential projection, normals, mesh validation and the built-in scenes.
#include "core/builtin_scenes.h"
#include "core/errors.h"
#include "core/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace flowsurf;
using namespace flowsurf::core;

// A wall result's U is zero on the wall: the default is the first field with flow.
TEST(Mesh, DefaultFieldSkipsFieldsThatAreZeroEverywhere) {
    SurfaceMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}};
    m.fields = {{"U", {{0, 0, 0}, {0, 0, 0}}}, {"wallShearStress", {{0, 0, 0}, {1e-4f, 0, 0}}}, {"V", {{1, 0, 0}, {1, 0, 0}}}};
    ASSERT_NE(m.defaultField(), nullptr);
    EXPECT_EQ(m.defaultField()->name, "wallShearStress");
    m.fields.erase(m.fields.begin() + 1, m.fields.end());
    EXPECT_EQ(m.defaultField()->name, "U");  // nothing better: the first
    m.fields.clear();
    EXPECT_EQ(m.defaultField(), nullptr);
}

TEST(Mesh, MakeTangentialRemovesNormalComponent) {
    std::vector<glm::vec3> v = {{1, 2, 3}, {0, 0, 5}};
    std::vector<glm::vec3> n = {{0, 0, 1}, glm::normalize(glm::vec3(1, 1, 0))};
    makeTangential(v, n);
    EXPECT_FLOAT_EQ(v[0].x, 1.0f);
    EXPECT_FLOAT_EQ(v[0].y, 2.0f);
    EXPECT_FLOAT_EQ(v[0].z, 0.0f);
    EXPECT_NEAR(glm::dot(v[1], n[1]), 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(v[1].z, 5.0f);
}

TEST(Mesh, ComputedNormalsFollowWinding) {
    std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    auto n = computeVertexNormals(p, {{0, 1, 2}});
    for (const auto& v : n) EXPECT_NEAR(v.z, 1.0f, 1e-6f);
}

namespace {
SurfaceMesh triangleMesh() {
    SurfaceMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    m.triangles = {{0, 1, 2}, {1, 3, 2}};
    m.fields = {{"U", {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}}}};
    return m;
}
}  // namespace

TEST(Mesh, ValidateRefusesBadInputNamingTheProblem) {
    {
        SurfaceMesh m = triangleMesh();
        m.fields[0].values[2].y = std::numeric_limits<float>::quiet_NaN();
        try {
            validateMesh(m, "f.vtp");
            FAIL();
        } catch (const FormatError& e) {
            EXPECT_NE(std::string(e.what()).find("f.vtp"), std::string::npos);
            EXPECT_NE(std::string(e.what()).find("point 2"), std::string::npos);
        }
    }
    {
        SurfaceMesh m = triangleMesh();
        m.fields[0].values[1].x = std::numeric_limits<float>::infinity();
        EXPECT_THROW(validateMesh(m, "f"), FormatError);
    }
    {
        SurfaceMesh m = triangleMesh();
        m.triangles[1].y = 17;
        EXPECT_THROW(validateMesh(m, "f"), FormatError);
    }
    {
        SurfaceMesh m = triangleMesh();
        m.fields[0].values.pop_back();
        EXPECT_THROW(validateMesh(m, "f"), FormatError);
    }
    EXPECT_THROW(validateMesh(*new SurfaceMesh(), "f"), FormatError);
}

TEST(Mesh, DegenerateTrianglesAreDroppedAndCounted) {
    SurfaceMesh m = triangleMesh();
    m.triangles.push_back({0, 0, 1});
    m.positions.push_back({2, 0, 0});
    m.positions.push_back({3, 0, 0});
    m.fields[0].values.resize(6, glm::vec3(1, 0, 0));
    m.triangles.push_back({1, 4, 5});  // collinear: zero area
    EXPECT_EQ(validateMesh(m, "f"), 2u);
    EXPECT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.normals.size(), m.positions.size());
    SurfaceMesh allBad = triangleMesh();
    allBad.triangles = {{0, 0, 0}};
    EXPECT_THROW(validateMesh(allBad, "f"), FormatError);
}

TEST(Builtins, EveryBuiltinIsValidAndTangential) {
    for (const auto& b : builtinScenes()) {
        Dataset d = makeBuiltin("builtin:" + b.name);
        ASSERT_FALSE(d.steps.empty()) << b.name;
        const auto& m = d.steps.front().mesh;
        ASSERT_EQ(m.fields.size(), 1u);
        EXPECT_EQ(m.fields[0].name, "velocity");
        float maxDot = 0, maxSpeed = 0;
        for (size_t i = 0; i < m.vertexCount(); ++i) {
            maxDot = std::max(maxDot, std::abs(glm::dot(m.fields[0].values[i], m.normals[i])));
            maxSpeed = std::max(maxSpeed, glm::length(m.fields[0].values[i]));
        }
        EXPECT_LT(maxDot, 1e-4f * std::max(maxSpeed, 1.0f)) << b.name;
        EXPECT_GT(maxSpeed, 0.0f) << b.name;
    }
    EXPECT_GT(makeBuiltin("builtin:double-gyre").steps.size(), 2u);
}

TEST(Builtins, TriangleCountAndErrors) {
    Dataset d = makeBuiltin("builtin:sphere:100000");
    size_t tris = d.steps[0].mesh.triangleCount();
    EXPECT_GT(tris, 80000u);
    EXPECT_LT(tris, 125000u);
    EXPECT_THROW(makeBuiltin("builtin:nosuch"), ConfigError);
    EXPECT_THROW(makeBuiltin("builtin:sphere:abc"), ConfigError);
    EXPECT_THROW(makeBuiltin("builtin:sphere:999999999999"), ConfigError);
}
