// Sort-last parallel rendering (parallel/process_group.h) without MPI: the surface is
// cut into pieces, each piece rendered by its own thread with its own GL context, and the
// threads merge their buffers through an in-process ProcessGroup. The image of every
// process must equal the one-process image of the whole surface — the property the
// ParaView plugin relies on under mpiexec (tests/paraview checks it there too).
#include "core/builtin_scenes.h"
#include "core/camera.h"
#include "core/time_series.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "gl_test_util.h"
#include "methods/make_renderer.h"
#include "parallel/process_group.h"
#include "parallel/screen_split.h"
#include "parallel/screen_tiles.h"
#include "parallel/thread_group.h"
#include "parallel_util.h"
#include "raster/surface_gpu.h"
#include "session/options/options.h"
#include "session/playback.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <thread>

using namespace flowsurf;

namespace {

using test::depthComposite;
using test::difference;
using test::Images;
using test::inThreads;
using core::pieceOf;

Images renderWith(const std::string& method, const core::SurfaceMesh& mesh,
                  const std::function<core::Camera(int)>& cameraAt, const core::Viewport& vp, int frames,
                  methods::ProcessGroup* group, const methods::MethodParams& params = {}) {
    std::optional<methods::SurfaceStatistics> whole;
    std::optional<methods::PieceSeams> seams;
    if (group) whole = methods::wholeSurfaceStatistics(*group, mesh, "velocity", params.common);
    if (params.ibfvs.edgeMask) seams = methods::pieceSeams(group, mesh);
    methods::SurfaceGpu surface(mesh, "velocity", params.common, params.ibfvs.edgeMask, whole ? &*whole : nullptr,
                                seams ? &*seams : nullptr);
    auto m = methods::makeMethod(method, params, vp, group);
    for (int k = 0; k <= frames; ++k) m->renderFrame({&surface, cameraAt(k), uint32_t(k)});
    test::Rendered r = test::readBack(*m, vp);
    return {r.rgb, r.depth};
}

class ParallelMerge : public ::testing::TestWithParam<std::string> {};

// The spinning sphere cut into 2 and 4 pieces (vertical seams through the view; 4: also a
// horizontal one), 40 frames: every process's image equals the one-process image — mean
// ≤ 1 gray level over the surface and ≤ 3 in every 16 x 16 tile (the bound ParaView's ranks are held to, tests/paraview/parallel_test.py).
TEST_P(ParallelMerge, PiecesGiveTheOneProcessImage) {
    methods::MethodParams replicate;
    replicate.common.parallel = methods::ParallelMode::Replicate;
    const core::Dataset data = core::makeBuiltin("builtin:sphere");
    const core::SurfaceMesh& mesh = data.steps.front().mesh;
    const core::Viewport vp{256, 256};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.3f, 0.4f, 1.0f});
    const int frames = 40;
    const auto still = [&](int) { return cam; };
    const Images one = renderWith(GetParam(), mesh, still, vp, frames, nullptr);

    for (int n : {2, 4}) {
        std::vector<core::SurfaceMesh> pieces;
        for (int r = 0; r < n; ++r)
            pieces.push_back(pieceOf(mesh, [r, n](glm::vec3 c) {
                const int col = c.x < 0.0f ? 0 : 1, row = c.y < 0.1f ? 0 : 1;
                return (n == 2 ? col : col * 2 + row) == r;
            }));
        const std::vector<Images> images = inThreads(n, [&](methods::ProcessGroup& member, int r) {
            return renderWith(GetParam(), pieces[size_t(r)], still, vp, frames, &member, replicate);
        });
        for (int r = 0; r < n; ++r) {
            auto [mean, tile] = difference(one, images[size_t(r)], vp);
            std::printf("%s, %d processes, rank %d: mean %.3f, worst tile %.3f gray levels\n", GetParam().c_str(), n,
                        r, mean, tile);
            EXPECT_LE(mean, 1.0) << n << " processes, rank " << r;
            EXPECT_LE(tile, 3.0) << n << " processes, rank " << r;
        }
        if (n == 2) {  // without the merge a piece shows only itself: the check can fail
            auto [mean, tile] = difference(one, renderWith(GetParam(), pieces[0], still, vp, frames, nullptr), vp);
            std::printf("%s, piece 0 alone: mean %.3f gray levels\n", GetParam().c_str(), mean);
            EXPECT_GT(mean, 5.0);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, ParallelMerge, ::testing::Values("isa", "ibfvs", "hybrid"),
                         [](const auto& info) { return info.param; });

// Contrast enhancement [doc/contrast.md] needs the whole image's percentiles: in the replicate
// mode every process holds the merged image and stretches it as one process does (2
// pieces, the same bounds as above); the tiles mode's colour stretch, which would need the
// whole image's colours, refuses with a message naming the option and the way out (the
// texture's stretch in the tiles mode: TiledParallel.ContrastStretchEqualsTheOneProcessImage).
TEST(ParallelContrast, ReplicateEqualsOneProcessTilesColorRefused) {
    const core::Dataset data = core::makeBuiltin("builtin:sphere");
    const core::SurfaceMesh& mesh = data.steps.front().mesh;
    const core::Viewport vp{160, 160};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.3f, 0.4f, 1.0f});
    const auto still = [&](int) { return cam; };
    methods::MethodParams params = test::testParams();
    params.common.enhanceContrast = methods::EnhanceContrast::Both;
    params.common.parallel = methods::ParallelMode::Replicate;
    std::vector<core::SurfaceMesh> pieces;
    for (int r = 0; r < 2; ++r) pieces.push_back(pieceOf(mesh, [r](glm::vec3 c) { return (c.x < 0.0f ? 0 : 1) == r; }));
    for (const std::string method : {"isa", "hybrid"}) {
        const Images one = renderWith(method, mesh, still, vp, 12, nullptr, params);
        const std::vector<Images> images = inThreads(2, [&](methods::ProcessGroup& member, int r) {
            return renderWith(method, pieces[size_t(r)], still, vp, 12, &member, params);
        });
        for (int r = 0; r < 2; ++r) {
            auto [mean, tile] = difference(one, images[size_t(r)], vp);
            std::printf("%s contrast, replicate, rank %d: mean %.3f, worst tile %.3f gray levels\n", method.c_str(), r,
                        mean, tile);
            EXPECT_LE(mean, 1.0) << method << " rank " << r;
            EXPECT_LE(tile, 3.0) << method << " rank " << r;
        }
    }
    params.common.parallel = methods::ParallelMode::Tiles;
    methods::ThreadGroup group(2);
    std::vector<std::string> errors(2);
    std::vector<std::thread> threads;
    for (int r = 0; r < 2; ++r)
        threads.emplace_back([&, r] {
            try {
                gl::HeadlessContext context;
                methods::ThreadGroup::Member member(group, r);
                renderWith("hybrid", pieces[size_t(r)], still, vp, 1, &member, params);
            } catch (const std::exception& e) {
                errors[size_t(r)] = e.what();
            }
        });
    for (auto& t : threads) t.join();
    for (const std::string& e : errors) {
        EXPECT_NE(e.find("enhance-contrast"), std::string::npos) << e;
        EXPECT_NE(e.find("replicate"), std::string::npos) << e;
    }
}

}  // namespace

namespace {

// `parts` pieces of the sphere: sectors of longitude; `empty` more processes hold nothing.
std::vector<core::SurfaceMesh> sectors(const core::SurfaceMesh& mesh, int parts, int empty) {
    std::vector<core::SurfaceMesh> pieces;
    for (int r = 0; r < parts; ++r)
        pieces.push_back(pieceOf(mesh, [r, parts](glm::vec3 c) {
            const float a = std::atan2(c.y, c.x) + 3.14159265f;  // 0 .. 2 pi
            return std::min(parts - 1, int(a / (6.2831853f / float(parts)))) == r;
        }));
    for (int e = 0; e < empty; ++e) pieces.push_back(pieceOf(mesh, [](glm::vec3) { return false; }));
    return pieces;
}

// The test parameters in the tiles mode. The colour map's range is the speeds' 98th
// percentile, which the pieces' shared seam vertices shift in the last bit (the same in
// replicate mode): lit gray here.
methods::MethodParams tiledParams() {
    methods::MethodParams params = test::testParams();
    params.common.parallel = methods::ParallelMode::Tiles;
    params.common.colormap = methods::Colormap::None;
    return params;
}

// `pieces` as one mesh, each seam's vertices in it twice (what ParaView's client renders when
// the server delivers a split surface's geometry).
core::SurfaceMesh appended(const std::vector<core::SurfaceMesh>& pieces) {
    core::SurfaceMesh all = pieces.front();
    for (size_t i = 1; i < pieces.size(); ++i) core::appendMesh(all, pieces[i]);
    return all;
}

// Renders `pieces` on one thread each as one group and composites them by depth.
Images renderInParallel(const std::string& method, const std::vector<core::SurfaceMesh>& pieces,
                        const std::function<core::Camera(int)>& cameraAt, const core::Viewport& vp, int frames,
                        const methods::MethodParams& params) {
    return depthComposite(inThreads(int(pieces.size()),
                                    [&](methods::ProcessGroup& member, int r) {
                                        return renderWith(method, pieces[size_t(r)], cameraAt, vp, frames, &member,
                                                          params);
                                    }),
                          vp);
}

class TiledParallel : public ::testing::TestWithParam<std::string> {};

// parallel = tiles: each process runs the image stages on its own screen tile and shows
// its own fragments; composited by depth, 2, 4 and 8 processes, and 4 of which 2 hold
// nothing, give exactly the one-process image (mean and worst 16 x 16 tile 0.000 gray
// levels), with the camera still (15 frames) and then orbiting 3 degrees a frame (15); with
// either surface rasteriser.
TEST_P(TiledParallel, CompositeEqualsTheOneProcessImage) {
    const core::Dataset data = core::makeBuiltin("builtin:sphere");
    const core::SurfaceMesh& mesh = data.steps.front().mesh;
    const core::Viewport vp{240, 200};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.3f, 0.4f, 1.0f});
    const auto orbit = [cam](int k) {
        core::Camera c = cam;
        const float angle = glm::radians(3.0f * float(std::max(0, k - 15)));
        const glm::vec3 d = c.eye - c.target;
        c.eye = c.target + glm::vec3(std::cos(angle) * d.x - std::sin(angle) * d.y,
                                     std::sin(angle) * d.x + std::cos(angle) * d.y, d.z);
        return c;
    };
    const int frames = 30;
    methods::MethodParams params = tiledParams();
    // GL's rasteriser (auto, on this small sphere) and the visibility buffer (each piece its own).
    for (methods::SurfaceRaster raster : {methods::SurfaceRaster::Auto, methods::SurfaceRaster::Compute}) {
        params.common.surfaceRaster = raster;
        const char* rasterName = raster == methods::SurfaceRaster::Compute ? "compute raster" : "auto raster";
        const Images one = renderWith(GetParam(), mesh, orbit, vp, frames, nullptr, params);
        for (auto [parts, empty] : {std::pair{2, 0}, {4, 0}, {8, 0}, {2, 2}}) {
            const Images all = renderInParallel(GetParam(), sectors(mesh, parts, empty), orbit, vp, frames, params);
            auto [mean, tile] = difference(one, all, vp);
            std::printf("%s tiles, %s, %d processes (%d empty): mean %.3f, worst tile %.3f gray levels\n",
                        GetParam().c_str(), rasterName, parts + empty, empty, mean, tile);
            EXPECT_EQ(mean, 0.0) << rasterName << ", " << parts + empty << " processes";
            EXPECT_EQ(tile, 0.0) << rasterName << ", " << parts + empty << " processes";
        }
    }
}

// The rasteriser changes pixels (by under a gray level), so a group rasterises alike: when
// one process would take the visibility buffer and the others GL's rasteriser (as ranks
// that read different renderers or LP_NUM_THREADS would), all take GL's and the composite is
// exactly the one-process GL image (and depth), the camera still and then orbiting.
TEST_P(TiledParallel, TheGroupAgreesOnTheRasteriser) {
    const core::Dataset data = core::makeBuiltin("builtin:sphere");
    const core::SurfaceMesh& mesh = data.steps.front().mesh;
    const core::Viewport vp{200, 160};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.3f, 0.4f, 1.0f});
    const auto orbit = [cam](int k) { return core::orbitCamera(cam, 3.0f * float(std::max(0, k - 6))); };
    methods::MethodParams gl = tiledParams();
    gl.common.surfaceRaster = methods::SurfaceRaster::Gl;
    methods::MethodParams compute = gl;
    compute.common.surfaceRaster = methods::SurfaceRaster::Compute;
    const int frames = 12;
    const Images oneGl = renderWith(GetParam(), mesh, orbit, vp, frames, nullptr, gl);
    const Images oneCompute = renderWith(GetParam(), mesh, orbit, vp, frames, nullptr, compute);
    // The depths tell the rasterisers apart where the 8-bit images may not (the hybrid's).
    ASSERT_NE(oneGl.depth, oneCompute.depth) << "the two rasterisers must differ for this test to see";
    const std::vector<core::SurfaceMesh> pieces = sectors(mesh, 3, 0);
    const Images all = depthComposite(inThreads(3,
                                                [&](methods::ProcessGroup& member, int r) {
                                                    return renderWith(GetParam(), pieces[size_t(r)], orbit, vp, frames,
                                                                      &member, r == 1 ? compute : gl);
                                                }),
                                      vp);
    auto [mean, tile] = difference(oneGl, all, vp);
    std::printf("%s tiles, one of 3 processes asking for the visibility buffer: mean %.3f, worst tile %.3f gray "
                "levels against the GL image\n",
                GetParam().c_str(), mean, tile);
    EXPECT_EQ(mean, 0.0);
    EXPECT_EQ(tile, 0.0);
    EXPECT_EQ(all.depth, oneGl.depth) << "every piece rasterised by GL";
}

// Pieces one behind another (sectors of the sphere seen from the side, the visibility buffer):
// each process drops its pixels that a nearer piece covers (VisibilityBuffer::dropOccluded),
// so that together they show hardly more pixels than the one-process image has, where each
// would otherwise show its own far side too; the composite is still exactly the one-process
// image, the camera still and then orbiting.
TEST_P(TiledParallel, PiecesBehindOthersDropTheirPixels) {
    const core::Dataset data = core::makeBuiltin("builtin:sphere");
    const core::SurfaceMesh& mesh = data.steps.front().mesh;
    const core::Viewport vp{320, 256};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {1.0f, 0.3f, 0.2f});
    const auto orbit = [cam](int k) { return core::orbitCamera(cam, 3.0f * float(std::max(0, k - 6))); };
    methods::MethodParams params = tiledParams();
    params.common.surfaceRaster = methods::SurfaceRaster::Compute;
    const int frames = 12;
    const Images one = renderWith(GetParam(), mesh, orbit, vp, frames, nullptr, params);
    const std::vector<core::SurfaceMesh> pieces = sectors(mesh, 4, 0);
    const std::vector<Images> own = inThreads(4, [&](methods::ProcessGroup& member, int r) {
        return renderWith(GetParam(), pieces[size_t(r)], orbit, vp, frames, &member, params);
    });
    const auto covered = [](const Images& i) { return std::count_if(i.depth.begin(), i.depth.end(), [](float d) { return d < 1.0f; }); };
    long shown = 0, farSides = 0;
    for (const Images& i : own) shown += covered(i);
    for (const core::SurfaceMesh& piece : pieces)  // each piece alone shows its far side too
        farSides += covered(renderWith(GetParam(), piece, orbit, vp, 1, nullptr, params));
    auto [mean, tile] = difference(one, depthComposite(own, vp), vp);
    std::printf("%s tiles, 4 sectors from the side: mean %.3f, worst tile %.3f gray levels; pixels shown %ld, "
                "one process %ld, the pieces each alone %ld\n",
                GetParam().c_str(), mean, tile, shown, covered(one), farSides);
    EXPECT_EQ(mean, 0.0);
    EXPECT_EQ(tile, 0.0);
    EXPECT_GT(farSides, 3 * covered(one) / 2) << "the scene must have pieces behind others";
    EXPECT_LT(shown, 5 * covered(one) / 4) << "hidden pixels are dropped (all but those in partly covered cells)";
}

// The texture's contrast stretch in the tiles mode [doc/contrast.md]: the processes' tile
// histograms summed over the group give every process the one-process range, so the
// composite is again exactly the one-process image (2 and 4 processes, one of them empty),
// the camera still and then orbiting.
TEST_P(TiledParallel, ContrastStretchEqualsTheOneProcessImage) {
    const core::Dataset data = core::makeBuiltin("builtin:sphere");
    const core::SurfaceMesh& mesh = data.steps.front().mesh;
    const core::Viewport vp{200, 160};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.3f, 0.4f, 1.0f});
    const auto orbit = [cam](int k) {
        core::Camera c = cam;
        const float angle = glm::radians(3.0f * float(std::max(0, k - 8)));
        const glm::vec3 d = c.eye - c.target;
        c.eye = c.target + glm::vec3(std::cos(angle) * d.x - std::sin(angle) * d.y,
                                     std::sin(angle) * d.x + std::cos(angle) * d.y, d.z);
        return c;
    };
    methods::MethodParams params = tiledParams();
    params.common.enhanceContrast = methods::EnhanceContrast::Texture;
    const Images one = renderWith(GetParam(), mesh, orbit, vp, 16, nullptr, params);
    for (auto [parts, empty] : {std::pair{2, 0}, {3, 1}}) {
        const Images all = renderInParallel(GetParam(), sectors(mesh, parts, empty), orbit, vp, 16, params);
        auto [mean, tile] = difference(one, all, vp);
        std::printf("%s tiles, contrast stretch, %d processes (%d empty): mean %.3f, worst tile %.3f gray levels\n",
                    GetParam().c_str(), parts + empty, empty, mean, tile);
        EXPECT_EQ(mean, 0.0) << parts + empty << " processes";
        EXPECT_EQ(tile, 0.0) << parts + empty << " processes";
    }
}

// A camera that pans and backs away (the surface slides and shrinks on screen, leaving
// pixels that other pieces covered a frame before inside a tile's guard band): what each
// process merged there last frame must not stand in for the background now (the velocity
// images are merged in place, ScreenTiles::written). 2 and 4 processes, the composite exactly
// the one-process image.
TEST_P(TiledParallel, PanningCameraLeavesNoOtherPiecesBehind) {
    const core::Dataset data = core::makeBuiltin("builtin:sphere");
    const core::SurfaceMesh& mesh = data.steps.front().mesh;
    const core::Viewport vp{200, 160};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.3f, 0.4f, 1.0f});
    const auto pan = [cam](int k) {
        core::Camera c = cam;
        const glm::vec3 back = c.eye - c.target;
        const glm::vec3 right = glm::normalize(glm::cross(c.up, back));
        const float s = float(std::max(0, k - 4));
        const glm::vec3 shift = right * (0.06f * s * glm::length(back) * std::tan(glm::radians(c.fovDeg) / 2.0f));
        c.target += shift;
        c.eye = c.target + back * (1.0f + 0.05f * s);
        return c;
    };
    methods::MethodParams params = tiledParams();
    const int frames = 12;
    const Images one = renderWith(GetParam(), mesh, pan, vp, frames, nullptr, params);
    for (int parts : {2, 4}) {
        const Images all = renderInParallel(GetParam(), sectors(mesh, parts, 0), pan, vp, frames, params);
        auto [mean, tile] = difference(one, all, vp);
        std::printf("%s tiles, panning and backing camera, %d processes: mean %.3f, worst tile %.3f gray levels\n",
                    GetParam().c_str(), parts, mean, tile);
        EXPECT_EQ(mean, 0.0) << parts << " processes";
        EXPECT_EQ(tile, 0.0) << parts << " processes";
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, TiledParallel, ::testing::Values("isa", "ibfvs", "hybrid"),
                         [](const auto& info) { return info.param; });

// The IBFVS silhouette edge mask in parallel: the pieces' seams are not outlined (each is
// found on both sides and drawn once as an interior edge), and each process draws every
// piece's outlines over its own fragments (the outline quads exchanged), so 2 and 4
// processes (and 4 of which 2 hold nothing) give the one-process image exactly — also
// where one piece's outline lies over
// another's farther surface (the tori). Seams outlined: 1.7 - 4.7 gray levels; the
// others' outlines missing: 0.04 - 0.41. One process given the pieces appended (seam
// vertices twice) outlines no seam either.
TEST(TiledParallelEdgeMask, OutlinesEqualTheOneProcessImage) {
    const core::Viewport vp{240, 200};
    methods::MethodParams params = tiledParams();
    params.ibfvs.edgeMask = true;
    for (const char* scene : {"builtin:sphere", "builtin:tori"}) {
        const core::Dataset data = core::makeBuiltin(scene);
        const core::SurfaceMesh& mesh = data.steps.front().mesh;
        const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.3f, 0.4f, 1.0f});
        const auto still = [cam](int) { return cam; };
        const Images one = renderWith("ibfvs", mesh, still, vp, 10, nullptr, params);
        {
            const Images pieces = renderWith("ibfvs", appended(sectors(mesh, 4, 0)), still, vp, 10, nullptr, params);
            auto [mean, tile] = difference(one, pieces, vp);
            std::printf("%s edge mask, one process, 4 pieces appended: mean %.3f, worst tile %.3f gray levels\n", scene,
                        mean, tile);
            EXPECT_EQ(mean, 0.0) << scene << ", pieces appended";
            EXPECT_EQ(tile, 0.0) << scene << ", pieces appended";
        }
        for (auto [parts, empty] : {std::pair{2, 0}, {4, 0}, {2, 2}}) {
            const Images all = renderInParallel("ibfvs", sectors(mesh, parts, empty), still, vp, 10, params);
            auto [mean, tile] = difference(one, all, vp);
            std::printf("%s edge mask, %d processes (%d empty): mean %.3f, worst tile %.3f gray levels\n", scene,
                        parts + empty, empty, mean, tile);
            EXPECT_EQ(mean, 0.0) << scene << ", " << parts << " processes";
            EXPECT_EQ(tile, 0.0) << scene << ", " << parts << " processes";
        }
    }
}

}  // namespace

namespace {

// The split of the screen: the tiles cover it without overlap, and cut the weight evenly.
TEST(ScreenSplit, TilesCoverTheScreenWithEvenWeight) {
    const int cellsX = 20, cellsY = 12, cell = 16, w = 310, h = 190;  // the last cells partly outside
    std::vector<float> weight(size_t(cellsX * cellsY));
    for (int y = 0; y < cellsY; ++y)
        for (int x = 0; x < cellsX; ++x) weight[size_t(y * cellsX + x)] = x < 10 ? 4.0f : 1.0f;  // left: 4x the work
    for (int parts : {1, 2, 3, 4, 7, 8}) {
        const std::vector<methods::PixelRect> tiles = methods::splitScreen(weight, cellsX, cellsY, cell, w, h, parts);
        ASSERT_EQ(int(tiles.size()), parts);
        std::vector<int> covered(size_t(w * h), 0);
        std::vector<double> load(tiles.size(), 0.0);
        for (size_t t = 0; t < tiles.size(); ++t)
            for (int y = tiles[t].y0; y < tiles[t].y1; ++y)
                for (int x = tiles[t].x0; x < tiles[t].x1; ++x) {
                    ++covered[size_t(y * w + x)];
                    if (x % cell == 0 && y % cell == 0) load[t] += weight[size_t((y / cell) * cellsX + x / cell)];
                }
        for (int c : covered) ASSERT_EQ(c, 1) << parts << " parts: a pixel in no tile or in two";
        const double mean = 600.0 / parts;  // 10 x 12 x 4 + 10 x 12 x 1
        for (double l : load) EXPECT_LE(std::abs(l - mean), 0.25 * mean + 24.0) << parts << " parts";
    }
}

// Load balance from measured costs: a tile that took three times as long as the other
// gets fewer cells, so that the costs it predicts are even.
TEST(ScreenSplit, MeasuredCostsMoveTheCut) {
    const int cellsX = 16, cellsY = 8, cell = 16;
    const std::vector<float> weight(size_t(cellsX * cellsY), 1.0f);
    const auto tiles = methods::splitScreen(weight, cellsX, cellsY, cell, 256, 128, 2);
    ASSERT_EQ(tiles[0].x1, 128);  // even weights: the middle
    const float ms[2] = {30.0f, 10.0f};
    const std::vector<float> costs = methods::costWeights(weight, cellsX, cell, tiles, ms);
    const auto again = methods::splitScreen(costs, cellsX, cellsY, cell, 256, 128, 2);
    // Per cell 30/64 ms left of x = 128, 10/64 right of it: even at 5.33 cells, the cut at 5.
    EXPECT_EQ(again[0].x1, 80);
    EXPECT_EQ(again[1].x0, 80);
}

// Work a process has apart from its tile (drawing its own piece, which no split moves):
// the tiles' shares are set so that the totals come out even, the split cuts by them, and
// a process whose own work is over the mean gets no tile work.
TEST(ScreenSplit, OwnWorkMovesTheCut) {
    {
        const float tile[2] = {20.0f, 20.0f}, own[2] = {30.0f, 10.0f};
        const std::vector<float> shares = methods::tileShares(tile, own);
        ASSERT_EQ(shares.size(), 2u);
        // 40 ms of tile work: 10 + 30 to even 30 + 10 out at 40 each.
        EXPECT_FLOAT_EQ(shares[0], 0.5f);
        EXPECT_FLOAT_EQ(shares[1], 1.5f);
        const int cellsX = 16, cellsY = 8, cell = 16;
        const std::vector<float> weight(size_t(cellsX * cellsY), 1.0f);
        const auto tiles = methods::splitScreen(weight, cellsX, cellsY, cell, 256, 128, 2, shares);
        EXPECT_EQ(tiles[0].x1, 64);  // a quarter of the even weight
        EXPECT_EQ(tiles[1], (methods::PixelRect{64, 0, 256, 128}));
    }
    {
        const float tile[3] = {10.0f, 10.0f, 10.0f}, own[3] = {60.0f, 10.0f, 10.0f};
        const std::vector<float> shares = methods::tileShares(tile, own);
        EXPECT_EQ(shares[0], 0.0f);
        EXPECT_FLOAT_EQ(shares[1], 1.5f);
        EXPECT_FLOAT_EQ(shares[2], 1.5f);
    }
    {
        const float none[2] = {0.0f, 0.0f};
        EXPECT_EQ(methods::tileShares(none, none), (std::vector<float>{1.0f, 1.0f}));
    }
}

}  // namespace

namespace {

// The pixels a piece can cover, from boxes around its vertices (surfaceParts): every
// on-screen point of every triangle inside, from cameras all round and from one so close
// that the surface runs off the image (where vertices off the image still bound what their
// triangles cover); and seen whole, well inside its box's rectangle (what the surface
// passes, the exchange and the composite then skip).
TEST(ScreenSplit, PartsHoldEveryTriangleTighterThanTheBox) {
    const core::Dataset data = core::makeBuiltin("builtin:sphere:20000");
    const core::SurfaceMesh half = core::pieceOf(data.steps[0].mesh, [](glm::vec3 c) { return c.x < 0.1f; });
    const core::Dataset coarse = core::makeBuiltin("builtin:sphere:200");  // triangles larger than a part
    const core::Viewport vp{320, 240};
    for (const core::SurfaceMesh* mesh : {&data.steps[0].mesh, &half, &coarse.steps[0].mesh}) {
        const std::vector<core::Bounds> parts = methods::surfaceParts(*mesh);
        ASSERT_FALSE(parts.empty());
        double partsArea = 0, boxArea = 0;
        for (int k = 0; k <= 12; ++k) {
            const float a = glm::radians(30.0f * float(k));
            core::Camera cam = core::fitCamera(data.bounds(), vp, {std::cos(a), std::sin(a), k % 3 == 0 ? 0.8f : -0.4f});
            if (k == 12) cam.eye = cam.target + 0.35f * (cam.eye - cam.target);  // close: the sphere fills the image
            const glm::mat4 viewProj = cam.viewProjection(vp.aspect());
            const methods::PixelRect r = methods::projectedRect(parts, viewProj, vp.width, vp.height);
            for (const glm::uvec3& t : mesh->triangles)
                for (int i = 0; i <= 4; ++i)
                    for (int j = 0; i + j <= 4; ++j) {
                        const glm::vec3 p = (float(i) * mesh->positions[t.x] + float(j) * mesh->positions[t.y] +
                                             float(4 - i - j) * mesh->positions[t.z]) / 4.0f;
                        const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
                        ASSERT_GT(clip.w, 0.0f);
                        const glm::vec2 px = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(vp.width, vp.height);
                        if (px.x < 0 || px.y < 0 || px.x >= float(vp.width) || px.y >= float(vp.height)) continue;
                        ASSERT_TRUE(px.x >= float(r.x0) && px.x <= float(r.x1) && px.y >= float(r.y0) &&
                                    px.y <= float(r.y1))
                            << "camera " << k << ": a point of a triangle at (" << px.x << ", " << px.y
                            << ") outside the parts' rectangle";
                    }
            if (k == 12) continue;
            partsArea += double(r.area());
            boxArea += double(methods::projectedRect(mesh->bounds(), viewProj, vp.width, vp.height).area());
        }
        std::printf("%zu parts: %.2f of the box's rectangle\n", parts.size(), partsArea / boxArea);
        if (mesh != &coarse.steps[0].mesh) {
            EXPECT_LT(partsArea, 0.85 * boxArea);
        }
    }
}

}  // namespace

namespace {

// The tiles' merge itself (ScreenTiles::distribute), on buffers whose values are known: three
// processes whose coverage overlaps, with ties in depth. Over every process's tile plus
// guard, each layer must hold the nearest process's value (on a tie the lowest rank's) and
// the layer's background where no process has a fragment. Rounds 0 and 1: a float layer
// whose own values off the piece are its background (ownBackground: copied on the GPU, only
// what the others sent merged on the host) and the depth; rounds 2 and 3 add a half layer
// merged in place that holds other values off the piece (the whole region merged). The
// coverage moves every round (a new split; what the last region held is cleared).
struct MergeCase {
    static constexpr int kW = 72, kH = 40;
    static bool covers(int rank, int x, int y, int round) {
        const int shift = 9 * (round % 2);  // the left and right pieces grow towards each other
        const bool in = rank == 0 ? x < 30 + shift : rank == 1 ? x >= 42 - shift : x >= 26 && x < 46 && y < 20;
        return in && (x + 2 * y + 7 * rank) % 5 != 0;
    }
    static float depth(int rank, int x, int y, int round) {  // at even x the same for every rank: ties
        return covers(rank, x, y, round) ? 0.25f + 0.125f * float((3 * x + 5 * y + (x % 2) * rank + round) % 4) : 1.0f;
    }
    static glm::vec4 value(int rank, int x, int y) { return {float(rank + 1), float(x), float(y), 0.5f * float(rank)}; }
    static float half(int rank, int x, int y) { return 0.25f * float(rank + 1) + 0.5f * float((x + y) % 3); }
    static constexpr glm::vec4 kGarbage{7.0f, -3.0f, 11.0f, 5.0f};
};

TEST(ScreenTiles, MergeKeepsTheNearestFragmentAndTheBackgroundElsewhere) {
    const core::Viewport vp{MergeCase::kW, MergeCase::kH};
    const int n = 3, guard = 3;
    const float halfFill = 0.75f;
    test::inThreads(n, [&](methods::ProcessGroup& group, int rank) {
        const int w = vp.width, h = vp.height;
        gl::Texture2D depth(GL_DEPTH_COMPONENT32F, w, h, GL_NEAREST), tileDepth(GL_DEPTH_COMPONENT32F, w, h, GL_NEAREST);
        gl::Texture2D velocity(GL_RGBA32F, w, h, GL_NEAREST), tileVelocity(GL_RGBA32F, w, h, GL_NEAREST);
        gl::Texture2D mask(GL_R16F, w, h, GL_NEAREST);  // merged in place
        methods::ScreenTiles tiles(vp);
        for (int round = 0; round < 4; ++round) {
            const bool withMask = round >= 2;
            std::vector<float> d(size_t(w * h)), m(size_t(w * h));
            std::vector<glm::vec4> v(size_t(w * h));
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const size_t i = size_t(y * w + x);
                    const bool on = MergeCase::covers(rank, x, y, round);
                    d[i] = MergeCase::depth(rank, x, y, round);
                    v[i] = on ? MergeCase::value(rank, x, y) : glm::vec4(0.0f);
                    m[i] = on ? MergeCase::half(rank, x, y) : MergeCase::kGarbage.x;
                }
            glTextureSubImage2D(depth.id(), 0, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, d.data());
            glTextureSubImage2D(velocity.id(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, v.data());
            glTextureSubImage2D(mask.id(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, m.data());
            std::vector<methods::TileLayer> layers{methods::TileLayer::of(velocity, tileVelocity, 0.0f, true),
                                                   methods::TileLayer::of(depth, tileDepth)};
            if (withMask) layers.push_back(methods::TileLayer::of(mask, mask, halfFill));
            tiles.distribute(group, depth, layers, guard, {0, 0, w, h});
            const methods::PixelRect R = tiles.region();
            EXPECT_FALSE(R.empty()) << "rank " << rank;
            std::vector<glm::vec4> gotV(size_t(w * h));
            std::vector<float> gotM(size_t(w * h)), gotD(size_t(w * h));
            glGetTextureImage(tileVelocity.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(gotV.size() * sizeof(glm::vec4)), gotV.data());
            glGetTextureImage(mask.id(), 0, GL_RED, GL_FLOAT, GLsizei(gotM.size() * sizeof(float)), gotM.data());
            glGetTextureImage(tileDepth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(gotD.size() * sizeof(float)),
                              gotD.data());
            int wrong = 0, covered = 0, empty = 0;
            for (int y = R.y0; y < R.y1; ++y)
                for (int x = R.x0; x < R.x1; ++x) {
                    int winner = -1;
                    float best = 1.0f;
                    for (int q = 0; q < n; ++q)
                        if (MergeCase::depth(q, x, y, round) < best) {
                            best = MergeCase::depth(q, x, y, round);
                            winner = q;
                        }
                    const size_t i = size_t(y * w + x);
                    const glm::vec4 wantV = winner < 0 ? glm::vec4(0.0f) : MergeCase::value(winner, x, y);
                    const float wantM = winner < 0 ? halfFill : MergeCase::half(winner, x, y);
                    (winner < 0 ? empty : covered)++;
                    if (gotV[i] != wantV || (withMask && gotM[i] != wantM) || gotD[i] != best) ++wrong;
                }
            EXPECT_EQ(wrong, 0) << "rank " << rank << ", round " << round << ": pixels of the region " << R.x0 << ","
                                << R.y0 << "-" << R.x1 << "," << R.y1 << " that differ from the merge";
            EXPECT_GT(covered, 0) << "rank " << rank;
            EXPECT_GT(empty, 0) << "rank " << rank;  // the background is tested too
        }
        return test::Images{};
    });
}

}  // namespace
