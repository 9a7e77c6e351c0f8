// IBFVS's polygon pass [L §IV-D.2] with the compute rasteriser (--surface-raster compute):
// the visibility buffer's resolve writes what the GL draw writes per pixel — the advected
// F_a (through t = T(x_i - v_i dt), noperspective), shade, mask and depth — on small and on
// large triangles, with the source view moved (the translate remedy's prevCamera) and still
// (dt = 0), culled and not, on both GL paths. The image-level check is test_surface_raster.cpp.
#include "core/builtin_scenes.h"
#include "gl/readback.h"
#include "gl_test_util.h"
#include "gpu/gpu_bindings.h"
#include "methods/frame.h"
#include "methods/ibfvs/polygon_advection.h"
#include "raster/surface_gpu.h"
#include "raster_tolerance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace flowsurf;

namespace {

struct PassOutputs {
    std::vector<float> flow, shade, mask, depth;
    bool visibility = false;
};

core::Camera orbited(core::Camera c, float degrees) {
    const float a = glm::radians(degrees);
    const glm::vec3 d = c.eye - c.target;
    c.eye = c.target + glm::vec3(std::cos(a) * d.x - std::sin(a) * d.y, std::sin(a) * d.x + std::cos(a) * d.y, d.z);
    return c;
}

// Previous F_a: smooth waves (F_a's difference then measures t's), or a linear ramp, which
// every resampling reproduces exactly.
float waves(int x, int y) { return 0.5f + 0.4f * std::sin(0.45f * float(x)) * std::cos(0.37f * float(y)); }
float ramp(int x, int y) { return 0.2f + 0.002f * float(x) + 0.001f * float(y); }

// One polygon pass over `prevFlow`, without noise (alpha 0): the texture coordinate alone
// decides the flow value.
PassOutputs runPass(const core::SurfaceMesh& mesh, const core::Camera& camera, const core::Camera& prevCamera,
                    const core::Viewport& vp, bool moving, methods::SurfaceRaster raster, methods::GlPath path, bool cull,
                    float (*prevFlow)(int, int) = waves) {
    methods::CommonParams common = test::testParams().common;
    common.surfaceRaster = raster;
    common.glPath = path;
    methods::SurfaceGpu surface(mesh, "velocity", common);
    gl::Texture2D shade(GL_RGBA16F, vp.width, vp.height, GL_NEAREST), mask(GL_R16F, vp.width, vp.height, GL_NEAREST),
        depth(GL_DEPTH_COMPONENT32F, vp.width, vp.height, GL_NEAREST);
    const std::initializer_list<methods::FlowPingPong::Attachment> shared{
        {GL_COLOR_ATTACHMENT0 + methods::outputs::kShade, &shade},
        {GL_COLOR_ATTACHMENT0 + methods::outputs::kMask, &mask},
        {GL_DEPTH_ATTACHMENT, &depth}};
    methods::FlowPingPong flow(vp, shared);
    std::vector<float> prev(size_t(vp.width) * vp.height);
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x)
            prev[size_t(y) * vp.width + x] = prevFlow(x, y);
    glTextureSubImage2D(flow.texture(0).id(), 0, 0, 0, vp.width, vp.height, GL_RED, GL_FLOAT, prev.data());
    methods::ibfvs::PolygonAdvection pass(vp, common, shared);
    const float dt = moving ? methods::dtForStep({&surface, camera, 0}, vp, 3.0f) : 0.0f;
    pass.apply(surface, camera, prevCamera, vp, dt, flow.texture(0), flow.texture(1), flow.fbo(1), depth, 0.5f, cull,
               {0, 0.0f, common.noise});
    return {gl::readChannel(flow.texture(1), 0), gl::readRgbaFloat(shade), gl::readChannel(mask, 0), gl::readDepth(depth),
            pass.lastUsedVisibility()};
}

float nanSafeDiff(float a, float b) {
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) == std::isnan(b) ? 0.0f : 1e30f;
    return std::abs(a - b);
}

// Same pixels but for rounding at a few silhouette pixels; where both cover, the same values
// up to rounding or a sub-pixel shift of the vertices (raster_tolerance.h): F_a's slope is at
// most 0.19 a pixel, so its rounding 2e-4 allows t 1e-3 px apart (perspective-correct t
// instead of noperspective differs by 1e-3 on the 20k-triangle sphere, 0.1 on 50 px
// triangles); the others as in test_surface_raster.cpp. Everywhere else the gray background.
void expectSamePass(const PassOutputs& g, const PassOutputs& c, const core::Viewport& vp) {
    const std::vector<char> both = test::bothCover(g.depth, c.depth);
    size_t covered = 0, mismatch = 0;
    float flow = 0, normal = 0, color = 0, mask = 0, depth = 0, background = 0;
    for (size_t i = 0; i < g.depth.size(); ++i) {
        const bool cg = g.depth[i] < 1.0f, cc = c.depth[i] < 1.0f;
        if (cg != cc) ++mismatch;
        if (!cg && !cc) background = std::max(background, std::abs(g.flow[i] - c.flow[i]));
        if (!both[i]) continue;
        ++covered;
        flow = std::max(flow, std::abs(g.flow[i] - c.flow[i]));
        for (int k = 0; k < 3; ++k) normal = std::max(normal, std::abs(g.shade[4 * i + k] - c.shade[4 * i + k]));
        color = std::max(color, nanSafeDiff(g.shade[4 * i + 3], c.shade[4 * i + 3]));
        mask = std::max(mask, nanSafeDiff(g.mask[i], c.mask[i]));
        depth = std::max(depth, std::abs(g.depth[i] - c.depth[i]));
    }
    float shift = std::max({test::explainingShiftPx(g.flow, c.flow, 1, 0, both, vp.width, vp.height, 2e-4f),
                            test::explainingShiftPx(g.mask, c.mask, 1, 0, both, vp.width, vp.height, 2e-3f),
                            test::explainingShiftPx(g.depth, c.depth, 1, 0, both, vp.width, vp.height, 5e-5f)});
    for (int k = 0; k < 4; ++k)
        shift = std::max(shift, test::explainingShiftPx(g.shade, c.shade, 4, k, both, vp.width, vp.height, 2e-3f));
    const double mismatchFraction = double(mismatch) / double(g.depth.size());
    std::printf("covered %zu px, coverage mismatch %.5f, max |diff| F_a %.2e normal %.2e colour %.2e mask %.2e depth %.2e, "
                "explained by a shift of %.4f px\n",
                covered, mismatchFraction, flow, normal, color, mask, depth, shift);
    EXPECT_FALSE(g.visibility);
    EXPECT_TRUE(c.visibility) << "the compute raster must replace the GL draw";
    EXPECT_GT(covered, 1000u);
    EXPECT_LE(mismatchFraction, 0.002);
    EXPECT_EQ(background, 0.0f);
    EXPECT_LE(shift, test::kRasterShiftPx);
}

void checkScene(const char* scene, const glm::vec3& direction) {
    const core::Dataset data = core::makeBuiltin(scene);
    const core::Viewport vp{256, 192};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, direction);
    const auto& mesh = data.steps[0].mesh;
    using methods::GlPath;
    using methods::SurfaceRaster;
    for (GlPath path : {GlPath::Fragment, GlPath::Compute})
        for (bool cull : {false, true})
            for (bool moving : {true, false}) {  // moving: dt > 0 and the source view 2 degrees away
                const core::Camera prev = moving ? orbited(cam, 2.0f) : cam;
                SCOPED_TRACE(std::string(scene) + (path == GlPath::Compute ? ", compute path" : ", fragment path") +
                             (cull ? ", culled" : "") + (moving ? ", moving" : ", dt = 0"));
                expectSamePass(runPass(mesh, cam, prev, vp, moving, SurfaceRaster::Gl, path, cull),
                               runPass(mesh, cam, prev, vp, moving, SurfaceRaster::Compute, path, cull), vp);
            }
}

}  // namespace

TEST(IbfvsSurfaceRaster, SmallTrianglesGiveTheDrawsOutputs) { checkScene("builtin:sphere:20000", {0.3f, 0.5f, 1.0f}); }

// Triangles of ~50 px: the visibility buffer hands them back to the GL rasteriser.
TEST(IbfvsSurfaceRaster, LargeTrianglesGiveTheDrawsOutputs) { checkScene("builtin:overlap-planes:50", {0.2f, 0.3f, 1.0f}); }


// Cameras inside the scene: triangles cut by the near plane, and (grazing along a plane from
// just above it) triangles reaching behind the eye, whose vertices there have no projection
// T(x_i - v_i dt). The GL draw interpolates t over the clipped triangle from its clip
// vertices (perspective-linear, not linear in the window); the resolve interpolates in the
// window over the whole triangle, and behind the eye evaluates eq. 13 at the pixel's surface
// point. So with the camera still and dt = 0 every pixel reads the previous F_a at itself: a
// ramp comes back unchanged (the GL draw misses that where it clips).
void expectRampReadBack(const core::SurfaceMesh& mesh, const core::Camera& camera, const core::Viewport& vp) {
    for (methods::SurfaceRaster raster : {methods::SurfaceRaster::Gl, methods::SurfaceRaster::Compute}) {
        const PassOutputs out = runPass(mesh, camera, camera, vp, false, raster, methods::GlPath::Fragment, false, ramp);
        size_t covered = 0, off = 0;
        for (int y = 3; y < vp.height - 3; ++y)  // away from the border, where F_a is clamped
            for (int x = 3; x < vp.width - 3; ++x) {
                const size_t i = size_t(y) * vp.width + x;
                if (out.depth[i] >= 1.0f) continue;
                ++covered;
                off += std::abs(out.flow[i] - ramp(x, y)) > 1e-4f;  // t within 0.05 px of the pixel
            }
        std::printf("%s raster: %zu of %zu covered pixels do not read themselves\n",
                    raster == methods::SurfaceRaster::Compute ? "compute" : "GL", off, covered);
        EXPECT_GT(covered, 10000u);
        if (raster == methods::SurfaceRaster::Compute) {
            EXPECT_EQ(off, 0u);
        }
    }
}

TEST(IbfvsSurfaceRaster, ClippedTrianglesReadThePixelItself) {
    const core::Viewport vp{256, 192};
    const core::Dataset data = core::makeBuiltin("builtin:overlap-planes:50");
    const core::Bounds b = data.bounds();
    const core::Camera fit = core::fitCamera(b, vp, {0.2f, 0.3f, 1.0f});
    core::Camera inside = fit;
    inside.eye = b.center() + 0.6f * (fit.eye - b.center()) * (b.radius() / glm::length(fit.eye - b.center()));
    inside.eye.x += 0.4f * b.radius();
    inside.nearPlane = 0.05f * b.radius();
    expectRampReadBack(data.steps[0].mesh, inside, vp);
    // Two triangles making the plane z = 0 over [-1, 1]^2, seen from just above it: the one
    // under the eye reaches behind it and covers the bottom of the image.
    core::SurfaceMesh plane;
    plane.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    plane.normals.assign(4, {0, 0, 1});
    plane.triangles = {{0, 1, 2}, {0, 2, 3}};
    plane.fields = {{"velocity", std::vector<glm::vec3>(4, {1, 0, 0})}};
    core::Camera grazing;
    grazing.eye = {0.1f, -0.3f, 0.05f};
    grazing.target = {0.1f, 1.0f, -0.1f};
    grazing.up = {0.0f, 0.0f, 1.0f};
    grazing.nearPlane = 0.01f;
    grazing.farPlane = 5.0f;
    expectRampReadBack(plane, grazing, vp);
}
