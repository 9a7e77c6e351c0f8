// IBFVS's polygon pass [L §IV-D.2] with the compute rasteriser (--surface-raster compute):
// the visibility buffer's resolve writes what the GL draw writes per pixel — the advected
// F_a (through t = T(x_i - v_i dt), noperspective), shade, mask and depth — on small and on
// large triangles, with the source view moved (the translate remedy's prevCamera) and still
// (dt = 0), culled and not, on both GL paths. The image-level check is test_surface_raster.cpp.
#include "core/builtin_scenes.h"
#include "gl/readback.h"
#include "gl_test_util.h"
#include "methods/common/frame.h"
#include "methods/common/gpu_bindings.h"
#include "methods/ibfvs/polygon_advection.h"

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

// One polygon pass over a smooth previous F_a (so that F_a's difference measures t's),
// without noise (alpha 0): the texture coordinate alone decides the flow value.
PassOutputs runPass(const core::SurfaceMesh& mesh, const core::Camera& camera, const core::Camera& prevCamera,
                    const core::Viewport& vp, bool moving, methods::SurfaceRaster raster, methods::GlPath path, bool cull) {
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
            prev[size_t(y) * vp.width + x] = 0.5f + 0.4f * std::sin(0.45f * float(x)) * std::cos(0.37f * float(y));
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
// up to float rounding: F_a's slope is at most 0.19 a pixel, so 2e-4 allows t 1e-3 px apart
// (perspective-correct t instead of noperspective differs by 1e-3 on the 20k-triangle
// sphere, 0.1 on 50 px triangles); the others as in test_surface_raster.cpp. Everywhere
// else the gray background.
void expectSamePass(const PassOutputs& g, const PassOutputs& c) {
    size_t covered = 0, mismatch = 0;
    float flow = 0, normal = 0, color = 0, mask = 0, depth = 0, background = 0;
    for (size_t i = 0; i < g.depth.size(); ++i) {
        const bool cg = g.depth[i] < 1.0f, cc = c.depth[i] < 1.0f;
        if (cg != cc) ++mismatch;
        if (!cg && !cc) background = std::max(background, std::abs(g.flow[i] - c.flow[i]));
        if (!cg || !cc) continue;
        ++covered;
        flow = std::max(flow, std::abs(g.flow[i] - c.flow[i]));
        for (int k = 0; k < 3; ++k) normal = std::max(normal, std::abs(g.shade[4 * i + k] - c.shade[4 * i + k]));
        color = std::max(color, nanSafeDiff(g.shade[4 * i + 3], c.shade[4 * i + 3]));
        mask = std::max(mask, nanSafeDiff(g.mask[i], c.mask[i]));
        depth = std::max(depth, std::abs(g.depth[i] - c.depth[i]));
    }
    const double mismatchFraction = double(mismatch) / double(g.depth.size());
    std::printf("covered %zu px, coverage mismatch %.5f, max |diff| F_a %.2e normal %.2e colour %.2e mask %.2e depth %.2e\n",
                covered, mismatchFraction, flow, normal, color, mask, depth);
    EXPECT_FALSE(g.visibility);
    EXPECT_TRUE(c.visibility) << "the compute raster must replace the GL draw";
    EXPECT_GT(covered, 1000u);
    EXPECT_LE(mismatchFraction, 0.002);
    EXPECT_LE(flow, 2e-4f);
    EXPECT_EQ(background, 0.0f);
    EXPECT_LE(normal, 2e-3f);
    EXPECT_LE(color, 2e-3f);
    EXPECT_LE(mask, 2e-3f);
    EXPECT_LE(depth, 5e-5f);
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
                               runPass(mesh, cam, prev, vp, moving, SurfaceRaster::Compute, path, cull));
            }
}

}  // namespace

TEST(IbfvsSurfaceRaster, SmallTrianglesGiveTheDrawsOutputs) { checkScene("builtin:sphere:20000", {0.3f, 0.5f, 1.0f}); }

// Triangles of ~50 px: the visibility buffer hands them back to the GL rasteriser.
TEST(IbfvsSurfaceRaster, LargeTrianglesGiveTheDrawsOutputs) { checkScene("builtin:overlap-planes:50", {0.2f, 0.3f, 1.0f}); }
