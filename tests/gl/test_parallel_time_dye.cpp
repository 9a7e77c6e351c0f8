// Parallel rendering over time (tiles): the hybrid's pathlines through a series' time
// levels, and dye crossing the pieces' seams, each equal to the one-process image.
#include "core/builtin_scenes.h"
#include "core/camera.h"
#include "core/time_series.h"
#include "gl/readback.h"
#include "gl_test_util.h"
#include "parallel/process_group.h"
#include "parallel_util.h"
#include "session/options/options.h"
#include "session/playback.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace flowsurf;

namespace {

using test::depthComposite;
using test::difference;
using test::Images;
using test::inThreads;
using core::pieceOf;

}  // namespace

namespace {

// Each step of `data` cut to the triangles `keep` accepts: one process's piece of a series.
class PieceSteps final : public core::StepProvider {
public:
    PieceSteps(const core::Dataset& data, std::function<bool(glm::vec3)> keep) : data_(data), keep_(std::move(keep)) {}
    size_t count() const override { return data_.steps.size(); }
    double time(size_t i) const override { return data_.steps[i].time; }
    core::SurfaceMesh load(size_t i) override { return pieceOf(data_.steps[i].mesh, keep_); }
    std::string label(size_t i) const override { return "piece of step " + std::to_string(i); }
    core::Bounds bounds() override { return data_.bounds(); }

private:
    const core::Dataset& data_;
    std::function<bool(glm::vec3)> keep_;
};

// `frames` frames of the hybrid's pathlines through `steps` (perFrame > 0: time levels).
Images playHybrid(core::StepProvider& steps, double perFrame, int frames, methods::ProcessGroup* group) {
    session::RenderOptions o;
    o.input = "pieces";
    session::setOption(o, "method", "hybrid");
    o.size = {160, 160};
    o.params.common.colormap = methods::Colormap::None;  // see CompositeEqualsTheOneProcessImage
    o.params.common.noise.seed = 7;
    session::Playback p(o, {}, group);
    p.open(steps);
    const core::Camera cam = test::orthoFront(2.2f);
    for (int k = 0; k <= frames; ++k) p.render({cam, k * perFrame, perFrame});
    Images im;
    int w = 0, h = 0;
    im.rgb = p.readImage(&w, &h);
    im.depth = gl::readDepth(p.views()[0]->surfaceDepth());
    return im;
}

// The hybrid on unsteady data in parallel (tiles): the time levels travel with the seeds,
// and 2 and 4 processes composited by depth give the one-process pathline image exactly.
TEST(TiledParallelUnsteady, HybridPathlinesEqualTheOneProcessImage) {
    const core::Dataset data = core::makeBuiltin("builtin:turning-plane");
    const double perFrame = 8.0 / 60.0;  // a quarter turn of the field over the 60 frames
    const int frames = 12;
    const core::Viewport vp{160, 160};
    core::DatasetSteps whole(data);
    const Images one = playHybrid(whole, perFrame, frames, nullptr);
    core::DatasetSteps again(data);
    const auto [steadyMean, steadyTile] = difference(one, playHybrid(again, 0.0, frames, nullptr), vp);
    std::printf("hybrid, pathlines against streamlines: mean %.3f gray levels\n", steadyMean);
    EXPECT_GT(steadyMean, 1.0);  // the levels are in use: the check below can fail
    for (int parts : {2, 4}) {
        const std::vector<Images> images = inThreads(parts, [&](methods::ProcessGroup& member, int r) {
            PieceSteps piece(data, [r, parts](glm::vec3 c) {
                const float a = std::atan2(c.y, c.x) + 3.14159265f;
                return std::min(parts - 1, int(a / (6.2831853f / float(parts)))) == r;
            });
            return playHybrid(piece, perFrame, frames, &member);
        });
        auto [mean, tile] = difference(one, depthComposite(images, vp), vp);
        std::printf("hybrid unsteady tiles, %d processes: mean %.3f, worst tile %.3f gray levels\n", parts, mean, tile);
        EXPECT_EQ(mean, 0.0) << parts << " processes";
        EXPECT_EQ(tile, 0.0) << parts << " processes";
    }
}

// `frames` frames of `method` on builtin:sphere (the piece `keep` accepts; all: nullptr)
// with dye released continuously from sources on the pieces' seams: the solid-body rotation
// carries it across them.
// `advected`: the band voxels this process advected in the last step, and the whole band's.
struct DyeShare {
    size_t advected = 0, band = 0, haloBytes = 0;
};
Images playDye(const std::string& method, int parts, int r, int frames, methods::ProcessGroup* group,
               DyeShare* share = nullptr) {
    const core::Dataset data = core::makeBuiltin("builtin:sphere:20000");
    session::RenderOptions o;
    o.input = "pieces";
    session::setOption(o, "method", method);
    o.size = {160, 160};
    o.params.common.colormap = methods::Colormap::None;  // see CompositeEqualsTheOneProcessImage
    o.params.common.noise.seed = 7;
    o.timePerFrame = 0.1;
    // On the seams y = 0 (2 and 4 pieces) and x = 0 (4 pieces), seen from +z; the last one a
    // little off the surface (it snaps to the nearest point of the whole surface).
    session::setOption(o, "dye", "-0.6,0,0.8:0.1:red;0,0.5,0.866:0.1:yellow;0.3,-0.3,1.0:0.08:cyan");
    PieceSteps piece(data, [r, parts](glm::vec3 c) {
        if (parts == 1) return true;
        const float a = std::atan2(c.y, c.x) + 3.14159265f;
        return std::min(parts - 1, int(a / (6.2831853f / float(parts)))) == r;
    });
    session::Playback p(o, {}, group);
    p.open(piece);
    const core::Camera cam = test::orthoFront(2.4f);
    for (int k = 0; k <= frames; ++k) {
        p.render({cam, 0.0, 0.0});
        if (share && p.dye().field()) share->haloBytes += p.dye().field()->haloBytesSent();
    }
    if (share && p.dye().field()) {
        share->advected = p.dye().field()->advectedVoxels();
        share->band = p.dye().field()->band().size();
    }
    Images im;
    int w = 0, h = 0;
    im.rgb = p.readImage(&w, &h);
    im.depth = gl::readDepth(p.views()[0]->surfaceDepth());
    return im;
}

// Dye in parallel (tiles): every process holds the whole surface's band (each piece's
// closest points exchanged) and advects the part its piece touches, with a halo from the
// others, so the ink crosses the seams; 2 and 4 processes composited by depth give the
// one-process image exactly, for every method, each process advecting less than the whole.
TEST(TiledParallelDye, DyeCrossesThePiecesAsInOneProcess) {
    const int frames = 24;
    const core::Viewport vp{160, 160};
    for (const std::string method : {"isa", "ibfvs", "hybrid"}) {
        DyeShare whole;
        const Images one = playDye(method, 1, 0, frames, nullptr, &whole);
        for (int parts : {2, 4}) {
            std::vector<DyeShare> share(static_cast<size_t>(parts));
            const std::vector<Images> images = inThreads(parts, [&](methods::ProcessGroup& member, int r) {
                return playDye(method, parts, r, frames, &member, &share[size_t(r)]);
            });
            auto [mean, tile] = difference(one, depthComposite(images, vp), vp);
            std::printf("%s dye tiles, %d processes: mean %.3f, worst tile %.3f gray levels\n", method.c_str(), parts,
                        mean, tile);
            size_t sum = 0, halo = 0;
            for (const DyeShare& d : share) {
                std::printf("  advected %zu band voxels in the last step (one process: %zu)\n", d.advected,
                            whole.advected);
                EXPECT_LT(d.advected, whole.advected * 3 / 4) << method << ", " << parts << " processes";
                sum += d.advected;
                halo += d.haloBytes;
            }
            EXPECT_GE(sum, whole.advected) << "every active voxel advected by some process";
            EXPECT_GT(halo, 0u) << "the ink crosses the seams through the halo";
            std::printf("  halo: %zu bytes sent over %d steps\n", halo, frames + 1);
            EXPECT_EQ(mean, 0.0) << method << ", " << parts << " processes";
            EXPECT_EQ(tile, 0.0) << method << ", " << parts << " processes";
            if (parts == 2) {  // a piece's own band alone loses the ink at the seam: the check can fail
                const Images alone = depthComposite(
                    {playDye(method, 2, 0, frames, nullptr), playDye(method, 2, 1, frames, nullptr)}, vp);
                std::printf("%s dye, pieces each alone: mean %.3f gray levels\n", method.c_str(),
                            difference(one, alone, vp).first);
                EXPECT_GT(difference(one, alone, vp).first, 0.5) << method;
            }
        }
    }
}

}  // namespace
