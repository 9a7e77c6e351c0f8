// Projection T(x) and camera helpers against hand-computed values.
#include "core/camera.h"

#include <gtest/gtest.h>

#include <vector>

using namespace flowsurf::core;

TEST(Camera, OrthographicProjectionMapsToPixels) {
    Camera c;
    c.eye = {0, 0, 5};
    c.target = {0, 0, 0};
    c.orthoHeight = 2.0f;
    c.nearPlane = 1.0f;
    c.farPlane = 9.0f;
    Viewport vp{200, 100};  // view 4 x 2 units: 50 px per unit
    glm::vec3 p = projectToPixels(c, vp, {1.0f, 0.5f, 0.0f});
    EXPECT_NEAR(p.x, 150.0f, 1e-3f);
    EXPECT_NEAR(p.y, 75.0f, 1e-3f);
    EXPECT_NEAR(p.z, 0.5f, 1e-5f);  // z=0 is 5 from the eye: half way from 1 to 9
    EXPECT_NEAR(maxPixelsPerUnit(c, vp, Bounds{{-1, -1, -1}, {1, 1, 1}}), 50.0f, 1e-4f);
}

TEST(Camera, PerspectiveCentreAndFovEdge) {
    Camera c;
    c.eye = {0, 0, 10};
    c.fovDeg = 90.0f;
    c.nearPlane = 1.0f;
    c.farPlane = 100.0f;
    Viewport vp{100, 100};
    glm::vec3 centre = projectToPixels(c, vp, {0, 0, 0});
    EXPECT_NEAR(centre.x, 50.0f, 1e-4f);
    EXPECT_NEAR(centre.y, 50.0f, 1e-4f);
    // With a 90 degree fov, y = distance lands on the top edge.
    EXPECT_NEAR(projectToPixels(c, vp, {0, 10, 0}).y, 100.0f, 1e-3f);
    EXPECT_NEAR(projectToPixels(c, vp, {0, 5, 0}).y, 75.0f, 1e-3f);
}

// A camera inside the bounds (walking through a street canyon, an engine port): the
// nearest corner is behind it, so the scale comes from the nearest visible surface point
// (at half its depth, a margin for points between the samples). Points behind the camera
// or outside the view do not count; without any, the near plane's scale is the bound.
TEST(Camera, ScaleInsideTheBoundsFollowsTheNearestVisibleSurface) {
    Camera c;
    c.eye = {0, 0, 0};
    c.target = {0, 0, -1};
    c.fovDeg = 90.0f;
    c.nearPlane = 0.01f;
    c.farPlane = 100.0f;
    Viewport vp{100, 100};
    const Bounds box{{-50, -50, -50}, {50, 50, 50}};
    const std::vector<glm::vec3> samples = {
        {0, 0, -20}, {3, 0, -10},  // visible: the nearest is 10 deep
        {0, 0, 5},                 // behind the camera
        {9, 0, -2},                // 2 deep but far outside the view
    };
    // At depth 10 / 2 a 90 degree view is 10 units high: 10 px per unit.
    EXPECT_NEAR(maxPixelsPerUnit(c, vp, box, samples), 10.0f, 1e-3f);
    EXPECT_NEAR(maxPixelsPerUnit(c, vp, box), 100.0f / (2.0f * 0.01f), 1e-1f);
    // Outside the bounds, with the surface as near as the box, the corner rule holds.
    c.eye = {0, 0, 60};
    c.target = {0, 0, 0};
    const std::vector<glm::vec3> face = {{0, 0, 50}, {20, 10, 50}};
    EXPECT_EQ(maxPixelsPerUnit(c, vp, box, face), maxPixelsPerUnit(c, vp, box));
}

TEST(Camera, FitKeepsBoundsInsideTheImage) {
    Bounds b{{-3, -1, -2}, {5, 2, 1}};
    Viewport vp{640, 360};
    Camera c = fitCamera(b, vp, {0.3f, 0.5f, 1.0f});
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z);
        glm::vec3 p = projectToPixels(c, vp, corner);
        EXPECT_GE(p.x, 0.0f);
        EXPECT_LE(p.x, 640.0f);
        EXPECT_GE(p.y, 0.0f);
        EXPECT_LE(p.y, 360.0f);
        EXPECT_GT(p.z, 0.0f);  // inside the clip planes
        EXPECT_LT(p.z, 1.0f);
    }
}

TEST(Camera, OrbitKeepsDistanceAndTurnsAboutUp) {
    Camera c;
    c.eye = {0, 1, 4};
    Camera o = orbitCamera(c, 90.0f);
    EXPECT_NEAR(glm::length(o.eye - o.target), glm::length(c.eye - c.target), 1e-5f);
    EXPECT_NEAR(o.eye.x, 4.0f, 1e-5f);  // +90 degrees about +y takes +z to +x
    EXPECT_NEAR(o.eye.y, 1.0f, 1e-5f);
    EXPECT_NEAR(o.eye.z, 0.0f, 1e-5f);
}

#include "core/camera_path.h"
#include "core/errors.h"

TEST(CameraPath, InterpolatesLinearlyAndHoldsAtTheEnds) {
    Camera a, b;
    a.eye = {0, 0, 4};
    b.eye = {4, 0, 0};
    b.fovDeg = 50.0f;
    CameraPath path({{20, b}, {10, a}});  // any order
    EXPECT_EQ(path.at(0).eye, a.eye);
    EXPECT_EQ(path.at(99).eye, b.eye);
    Camera mid = path.at(15);
    EXPECT_NEAR(mid.eye.x, 2.0f, 1e-6f);
    EXPECT_NEAR(mid.eye.z, 2.0f, 1e-6f);
    EXPECT_NEAR(mid.fovDeg, 40.0f, 1e-5f);
    EXPECT_THROW(CameraPath({{3, a}, {3, b}}), flowsurf::ConfigError);
}
