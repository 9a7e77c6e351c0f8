// The compute rasteriser (--surface-raster compute, a visibility buffer) gives the per-pixel
// buffers and the images of the GL rasteriser: on small triangles (the compute pass), on
// large ones and on triangles crossing the eye plane (handed back to GL), with and without
// back-face culling; and the same bytes on every run (order-independent atomics).
#include "core/builtin_scenes.h"
#include "gl/readback.h"
#include "gl_test_util.h"
#include "gpu/gl_path.h"
#include "methods/make_renderer.h"
#include "parallel/process_group.h"
#include "parallel_util.h"
#include "raster/surface_gbuffer.h"
#include "raster/surface_gpu.h"
#include "raster/visibility_buffer.h"
#include "raster_tolerance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace flowsurf;

namespace {

struct Buffers {
    std::vector<float> depth, velocity, shade, position;
};

Buffers renderBuffers(const core::SurfaceMesh& mesh, const core::Camera& camera, const core::Viewport& vp,
                      methods::SurfaceRaster raster, bool cull) {
    methods::SurfaceGpu surface(mesh, "velocity");
    methods::SurfaceGBuffer g(vp, true, cull, true, raster);
    g.render(surface, camera);
    return {gl::readDepth(g.depth()), gl::readRgbaFloat(g.velocity()), gl::readRgbaFloat(g.shade()),
            gl::readRgbaFloat(g.position())};
}

struct BufferDifference {
    double coverageMismatch = 0;  // fraction of pixels on the surface in one and not the other
    float depth = 0, velocity = 0, normal = 0, position = 0;  // largest |a - b| where both cover
    float shift = 0;  // the sub-pixel shift that explains every difference beyond rounding
    size_t covered = 0;
};

// Rounding of each buffer's values (the data are O(1); at grazing angles the depth changes by
// ~0.02 per pixel, so its rounding reaches 1e-5).
constexpr float kDepthRounding = 5e-5f, kValueRounding = 2e-3f;

BufferDifference compare(const Buffers& a, const Buffers& b, const core::Viewport& vp) {
    BufferDifference d;
    const std::vector<char> both = test::bothCover(a.depth, b.depth);
    size_t mismatch = 0;
    for (size_t i = 0; i < a.depth.size(); ++i) {
        if ((a.depth[i] < 1.0f) != (b.depth[i] < 1.0f)) ++mismatch;
        if (!both[i]) continue;
        ++d.covered;
        d.depth = std::max(d.depth, std::abs(a.depth[i] - b.depth[i]));
        for (int c = 0; c < 3; ++c) {
            d.velocity = std::max(d.velocity, std::abs(a.velocity[4 * i + c] - b.velocity[4 * i + c]));
            d.normal = std::max(d.normal, std::abs(a.shade[4 * i + c] - b.shade[4 * i + c]));
            d.position = std::max(d.position, std::abs(a.position[4 * i + c] - b.position[4 * i + c]));
        }
    }
    d.shift = test::explainingShiftPx(a.depth, b.depth, 1, 0, both, vp.width, vp.height, kDepthRounding);
    for (std::vector<float> Buffers::*buffers : {&Buffers::velocity, &Buffers::shade, &Buffers::position})
        for (int c = 0; c < 3; ++c)
            d.shift = std::max(d.shift, test::explainingShiftPx(a.*buffers, b.*buffers, 4, c, both, vp.width, vp.height,
                                                                kValueRounding));
    d.coverageMismatch = double(mismatch) / double(a.depth.size());
    std::printf("covered %zu px, coverage mismatch %.5f, max |diff| depth %.2e velocity %.2e normal %.2e position %.2e, "
                "explained by a shift of %.4f px\n",
                d.covered, d.coverageMismatch, d.depth, d.velocity, d.normal, d.position, d.shift);
    return d;
}

// Same pixels covered but for rounding at a few silhouette pixels (both snap vertices to
// 1/256 pixel, GL by its own rounding), and the same interpolated values up to rounding or to
// a sub-pixel shift of the vertices (raster_tolerance.h: NVIDIA's rasteriser differs so at
// silhouettes, llvmpipe's not at all).
void expectSameBuffers(const BufferDifference& d) {
    EXPECT_GT(d.covered, 1000u);
    EXPECT_LE(d.coverageMismatch, 0.002);
    EXPECT_LE(d.shift, test::kRasterShiftPx);
}

}  // namespace

// Many small triangles: the compute pass rasterises all of them.
TEST(SurfaceRaster, SmallTrianglesGiveTheGlBuffers) {
    const core::Dataset data = core::makeBuiltin("builtin:sphere:20000");
    const core::Viewport vp{256, 192};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.3f, 0.5f, 1.0f});
    const auto& mesh = data.steps[0].mesh;
    for (bool cull : {false, true}) {
        Buffers g = renderBuffers(mesh, cam, vp, methods::SurfaceRaster::Gl, cull);
        Buffers c = renderBuffers(mesh, cam, vp, methods::SurfaceRaster::Compute, cull);
        expectSameBuffers(compare(g, c, vp));
        if (cull) continue;
        // What the measure makes of an error: the compute raster's buffers a pixel to the right.
        for (std::vector<float> Buffers::*buffer : {&Buffers::depth, &Buffers::velocity, &Buffers::shade, &Buffers::position}) {
            std::vector<float>& b = c.*buffer;
            const size_t row = b.size() / size_t(vp.height);
            const size_t px = row / size_t(vp.width);
            for (size_t y = 0; y < size_t(vp.height); ++y)
                std::copy_backward(b.begin() + y * row, b.begin() + (y + 1) * row - px, b.begin() + (y + 1) * row);
        }
        EXPECT_GT(compare(g, c, vp).shift, 0.5f) << "a pixel's offset must not pass as a rasteriser's difference";
    }
}

// A few large triangles, and a camera inside the scene whose near plane cuts triangles:
// those go to the GL rasteriser, into the same visibility buffer.
TEST(SurfaceRaster, LargeAndClippedTrianglesGiveTheGlBuffers) {
    const core::Dataset data = core::makeBuiltin("builtin:overlap-planes:50");  // triangles of ~50 px
    const core::Viewport vp{256, 192};
    const auto& mesh = data.steps[0].mesh;
    const core::Bounds b = data.bounds();
    core::Camera fit = core::fitCamera(b, vp, {0.2f, 0.3f, 1.0f});
    core::Camera inside = fit;
    inside.eye = b.center() + 0.6f * (fit.eye - b.center()) * (b.radius() / glm::length(fit.eye - b.center()));
    inside.eye.x += 0.4f * b.radius();
    inside.nearPlane = 0.05f * b.radius();
    for (const core::Camera& cam : {fit, inside}) {
        Buffers g = renderBuffers(mesh, cam, vp, methods::SurfaceRaster::Gl, false);
        Buffers c = renderBuffers(mesh, cam, vp, methods::SurfaceRaster::Compute, false);
        expectSameBuffers(compare(g, c, vp));
    }
    // Grazing along a plane from just above it: its triangles reach behind the eye.
    const core::Dataset plane = core::makeBuiltin("builtin:uniform-plane");
    const core::Bounds pb = plane.bounds();
    const float size = glm::length(pb.hi - pb.lo);
    core::Camera grazing;
    grazing.eye = pb.center() + glm::vec3(0.0f, -0.2f * size, 0.03f * size);
    grazing.target = pb.center() + glm::vec3(0.0f, 0.5f * size, 0.0f);
    grazing.up = {0.0f, 0.0f, 1.0f};
    grazing.nearPlane = 0.001f * size;
    grazing.farPlane = 4.0f * size;
    Buffers g = renderBuffers(plane.steps[0].mesh, grazing, vp, methods::SurfaceRaster::Gl, false);
    Buffers c = renderBuffers(plane.steps[0].mesh, grazing, vp, methods::SurfaceRaster::Compute, false);
    expectSameBuffers(compare(g, c, vp));
}

// The images of every method: mean <= 1 gray level, as between the GL paths (test_gl_path.cpp).
class SurfaceRasterSameImage : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(Methods, SurfaceRasterSameImage, ::testing::Values("isa", "ibfvs", "hybrid"),
                         [](const auto& info) { return info.param; });

TEST_P(SurfaceRasterSameImage, Tori) {
    const core::Dataset data = core::makeBuiltin("builtin:tori");
    const core::Viewport vp{200, 150};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.2f, 0.6f, 1.0f});
    methods::MethodParams p = test::testParams();
    p.common.surfaceRaster = methods::SurfaceRaster::Gl;
    const test::Rendered g = test::renderScene(data, GetParam(), p, vp, cam, 30);
    p.common.surfaceRaster = methods::SurfaceRaster::Compute;
    const test::Rendered c = test::renderScene(data, GetParam(), p, vp, cam, 30);
    const test::Rendered c2 = test::renderScene(data, GetParam(), p, vp, cam, 30);
    double mean = 0;
    for (size_t i = 0; i < g.rgb.size(); ++i) mean += std::abs(int(g.rgb[i]) - int(c.rgb[i]));
    mean /= double(g.rgb.size());
    std::printf("%s: compute vs GL raster: composite mean %.4f gray levels\n", GetParam().c_str(), mean);
    EXPECT_LE(mean, 1.0);
    EXPECT_EQ(c.rgb, c2.rgb) << "the compute rasteriser must not depend on the order triangles run in";
}

// Many small triangles (a 100k-triangle sphere, ~3 a pixel) and large ones (~50 px, handed
// back to GL), the camera still and then orbiting 3 degrees a frame: the same image within
// 1 gray level, and the same bytes on every run. IBFVS also with the freeze remedy, whose
// source view lags the camera (its texture coordinates come from another view).
TEST_P(SurfaceRasterSameImage, SmallAndLargeTrianglesStillAndOrbiting) {
    const core::Viewport vp{200, 150};
    std::vector<methods::CameraMoveRemedy> remedies{methods::CameraMoveRemedy::Translate};
    if (GetParam() == "ibfvs") remedies.push_back(methods::CameraMoveRemedy::Freeze);
    for (const char* scene : {"builtin:sphere:100000", "builtin:overlap-planes:50"}) {
        const core::Dataset data = core::makeBuiltin(scene);
        methods::SurfaceGpu surface(data.steps.front().mesh, "velocity");
        const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.2f, 0.4f, 1.0f});
        const auto cameraAt = [cam](int k) {
            core::Camera c = cam;
            const float angle = glm::radians(3.0f * float(std::max(0, k - 10)));
            const glm::vec3 d = c.eye - c.target;
            c.eye = c.target + glm::vec3(std::cos(angle) * d.x - std::sin(angle) * d.y,
                                         std::sin(angle) * d.x + std::cos(angle) * d.y, d.z);
            return c;
        };
        for (methods::CameraMoveRemedy remedy : remedies) {
            methods::MethodParams p = test::testParams();
            p.common.onCameraMove = remedy;
            const auto render = [&](methods::SurfaceRaster raster, int frames) {
                p.common.surfaceRaster = raster;
                auto m = methods::makeMethod(GetParam(), p, vp);
                for (int k = 0; k <= frames; ++k) m->renderFrame({&surface, cameraAt(k), uint32_t(k)});
                return test::readBack(*m, vp).rgb;
            };
            for (int frames : {10, 20}) {  // still, then orbiting
                const auto g = render(methods::SurfaceRaster::Gl, frames);
                const auto c = render(methods::SurfaceRaster::Compute, frames);
                double mean = 0;
                for (size_t i = 0; i < g.size(); ++i) mean += std::abs(int(g[i]) - int(c[i]));
                mean /= double(g.size());
                std::printf("%s, %s, %s, %d frames: compute vs GL raster: composite mean %.4f gray levels\n",
                            GetParam().c_str(), scene, remedy == methods::CameraMoveRemedy::Freeze ? "freeze" : "translate",
                            frames, mean);
                EXPECT_LE(mean, 1.0) << scene << ", " << frames << " frames";
                EXPECT_EQ(c, render(methods::SurfaceRaster::Compute, frames)) << scene << ": order-independent";
            }
        }
    }
}

// The rule behind auto: compute only on a listed renderer (a software one, or a GPU with few
// graphics units) and only from its triangles per pixel on; an explicit choice is taken as given.
TEST(SurfaceRaster, AutoRule) {
    using methods::SurfaceRaster;
    const std::string lp = "llvmpipe (LLVM 15.0.6, 256 bits)";
    const methods::RendererInfo llvmpipe{lp, 2}, llvmpipe16{lp, 16}, llvmpipe1{lp, 1}, h100{"NVIDIA H100 80GB HBM3/PCIe/SSE2"},
        h200{"NVIDIA H200/PCIe/SSE2"}, desktop{"NVIDIA GeForce RTX 4090/PCIe/SSE2"};
    const size_t pixels = 512 * 512;
    EXPECT_FALSE(methods::useComputeRaster(SurfaceRaster::Auto, llvmpipe, 10000, pixels));
    EXPECT_TRUE(methods::useComputeRaster(SurfaceRaster::Auto, llvmpipe, 1000000, pixels));
    EXPECT_TRUE(methods::useComputeRaster(SurfaceRaster::Auto, llvmpipe16, 1000000, pixels));
    EXPECT_FALSE(methods::useComputeRaster(SurfaceRaster::Auto, llvmpipe, 100000, pixels));  // 0.38 per pixel
    // One core (a ParaView rank bound to its core): nothing for the compute pass to spread
    // the triangles over; GL up to 3 triangles per pixel.
    EXPECT_FALSE(methods::useComputeRaster(SurfaceRaster::Auto, llvmpipe1, 1000000, 1024 * 1024));
    EXPECT_FALSE(methods::useComputeRaster(SurfaceRaster::Auto, llvmpipe1, 500000, pixels));  // 1.9 per pixel
    EXPECT_TRUE(methods::useComputeRaster(SurfaceRaster::Auto, llvmpipe1, 1000000, pixels));  // 3.8 per pixel
    EXPECT_TRUE(methods::useComputeRaster(SurfaceRaster::Auto, h100, 100000, pixels));
    EXPECT_TRUE(methods::useComputeRaster(SurfaceRaster::Auto, h200, 1000000, 1920 * 1080));
    EXPECT_FALSE(methods::useComputeRaster(SurfaceRaster::Auto, h200, 1000000, 3840 * 2160));
    EXPECT_FALSE(methods::useComputeRaster(SurfaceRaster::Auto, desktop, 1000000, pixels));
    EXPECT_TRUE(methods::useComputeRaster(SurfaceRaster::Compute, desktop, 10, pixels));
    EXPECT_TRUE(methods::useComputeRaster(SurfaceRaster::Compute, llvmpipe1, 10, pixels));
    EXPECT_FALSE(methods::useComputeRaster(SurfaceRaster::Gl, llvmpipe, 1000000, pixels));
}

// The cores the auto rule reads for llvmpipe: LP_NUM_THREADS when it is a count (0, llvmpipe's
// "no threads", counts as 1), never more than the machine's CPUs.
TEST(SurfaceRaster, LlvmpipeCoresFollowLpNumThreads) {
    const methods::RendererInfo here = methods::currentRendererInfo();
    if (here.name.find(methods::kLlvmpipe) == std::string::npos) GTEST_SKIP() << "not llvmpipe: " << here.name;
    const char* saved = std::getenv("LP_NUM_THREADS");
    const std::string restore = saved ? saved : "";
    const auto coresWith = [](const char* value) {
        if (value) setenv("LP_NUM_THREADS", value, 1);
        else unsetenv("LP_NUM_THREADS");
        return methods::currentRendererInfo().cores;
    };
    const int all = coresWith(nullptr);
    EXPECT_GE(all, 1);
    EXPECT_EQ(coresWith("1"), 1);
    EXPECT_EQ(coresWith("0"), 1);
    EXPECT_EQ(coresWith("100000"), all);
    EXPECT_EQ(coresWith("two"), all) << "not a count: ignored, as llvmpipe does";
    if (saved) setenv("LP_NUM_THREADS", restore.c_str(), 1);
    else unsetenv("LP_NUM_THREADS");
}

// More work groups than one dispatch dimension allows (10M triangles: 156,250 groups of 64,
// llvmpipe allows 65,535 along x) go in rows: every group exists, the fewest rows, and fewer
// spare groups than rows (a spare group costs llvmpipe about a full one).
TEST(SurfaceRaster, WorkGroupGridCoversEveryGroup) {
    struct Case { size_t groups, maxX; glm::uvec2 grid; };
    for (const Case& c : {Case{156250, 65535, {52084, 3}}, Case{78125, 65535, {39063, 2}}, Case{10, 65535, {10, 1}},
                          Case{0, 65535, {0, 0}}, Case{65535, 65535, {65535, 1}}, Case{65536, 65535, {32768, 2}},
                          Case{7, 1, {1, 7}}}) {
        const glm::uvec2 g = methods::workGroupGrid(c.groups, c.maxX);
        EXPECT_EQ(g, c.grid) << c.groups << " groups, at most " << c.maxX << " along x";
        EXPECT_LE(g.x, c.maxX);
        EXPECT_GE(size_t(g.x) * g.y, c.groups);
        if (c.groups) {
            EXPECT_LT(size_t(g.x) * g.y - c.groups, g.y) << c.groups << " groups: spare groups";
        }
    }
}

// Sort-last occlusion between pieces (VisibilityBuffer::dropOccluded, the tiled mode's
// surface pass): a piece's pixels behind the screen cells another piece covers whole are
// dropped (background in every buffer), the rest of it stays as it was, and the merge by depth
// is the merge without the step; a piece at the very depth of another drops nothing (a tie is
// the merge's to decide, by rank).
TEST(SurfaceRaster, PixelsHiddenByAnotherPieceAreDropped) {
    const core::Viewport vp{128, 128};
    const core::Camera cam = test::orthoFront(2.2f);
    const auto rectangle = [](float z, float size) {
        core::SurfaceMesh m = core::makeRectangle({0.1f, 0, z}, {1, 0, 0}, {0, 1, 0}, size, size, 12, 12);
        m.fields.push_back({"velocity", std::vector<glm::vec3>(m.positions.size(), glm::vec3(1, 0.3f, 0))});
        return m;
    };
    struct PieceImages {
        Buffers alone, inGroup;
    };
    const auto render = [&](const std::vector<core::SurfaceMesh>& pieces) {
        std::vector<PieceImages> out(pieces.size());
        test::inThreads(int(pieces.size()), [&](methods::ProcessGroup& group, int r) {
            methods::SurfaceGpu surface(pieces[size_t(r)], "velocity");
            methods::SurfaceGBuffer g(vp, true, false, true, methods::SurfaceRaster::Compute);
            const auto read = [&] {
                return Buffers{gl::readDepth(g.depth()), gl::readRgbaFloat(g.velocity()), gl::readRgbaFloat(g.shade()),
                               gl::readRgbaFloat(g.position())};
            };
            g.render(surface, cam);
            out[size_t(r)].alone = read();
            g.render(surface, cam, &group);
            out[size_t(r)].inGroup = read();
            return test::Images{};
        });
        return out;
    };

    // A square in front of a larger one: 81 px a side, 116 px.
    const std::vector<PieceImages> p = render({rectangle(0.5f, 1.4f), rectangle(-0.5f, 2.0f)});
    const Buffers &front = p[0].alone, &back = p[1].alone;
    EXPECT_EQ(p[0].inGroup.depth, front.depth) << "the nearer piece hides, loses nothing";
    size_t hidden = 0, dropped = 0, kept = 0;
    for (size_t i = 0; i < back.depth.size(); ++i) {
        const bool behind = front.depth[i] < back.depth[i];
        hidden += behind && back.depth[i] < 1.0f;
        if (back.depth[i] < 1.0f && p[1].inGroup.depth[i] == 1.0f) {
            ++dropped;
            EXPECT_TRUE(behind) << "pixel " << i << " dropped with no nearer fragment of the other piece";
            EXPECT_EQ(p[1].inGroup.velocity[4 * i + 3], 0.0f) << "a dropped pixel is background in the buffers";
        } else if (back.depth[i] < 1.0f) {
            ++kept;
            EXPECT_EQ(p[1].inGroup.depth[i], back.depth[i]);
            for (int c = 0; c < 4; ++c) EXPECT_EQ(p[1].inGroup.velocity[4 * i + c], back.velocity[4 * i + c]);
        }
    }
    std::printf("back piece: %zu px behind the front one, %zu dropped, %zu kept\n", hidden, dropped, kept);
    // Dropped: the cells the front square covers whole (its rim of cells aside).
    const size_t cellPx = methods::kVisOccluderCellPx, wholeCells = 81 / cellPx - 1;
    EXPECT_GT(hidden, 6000u);
    EXPECT_GE(dropped, wholeCells * wholeCells * cellPx * cellPx);

    // The same square twice, at one depth: nothing dropped on either side.
    const std::vector<PieceImages> tie = render({rectangle(0.0f, 1.0f), rectangle(0.0f, 1.0f)});
    for (size_t r = 0; r < tie.size(); ++r) EXPECT_EQ(tie[r].inGroup.depth, tie[r].alone.depth) << "piece " << r;
}
