// The flow topology overlay's cost per frame (doc/bench/topology.md): a method's dynamic
// frames (an orbiting camera) of INPUT with --topology off, and the overlay alone drawn
// over the same frames (TopologyOverlay::draw: the line pieces and the points), in
// interleaved rounds, each a wall time over `frames` frames ended by glFinish. Prints the
// median of the rounds and the overlay's share of the frame. PARTS (points,lines | points |
// lines) and LW (line width, px) in the environment vary what is drawn.
//   flowsurf_overlay_timing INPUT [METHOD] [WxH] [ROUNDS] [FRAMES]
#include "gl/context.h"
#include "io/series_reader.h"
#include "session/playback.h"
#include "session/scene_setup.h"
#include "session/topology_overlay.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

using namespace flowsurf;

namespace {
using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double msSince(Clock::time_point t0, int frames) {
    glFinish();
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / frames;
}
}  // namespace

int main(int argc, char** argv) try {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s INPUT [METHOD] [WxH] [ROUNDS] [FRAMES]\n", argv[0]);
        return 2;
    }
    const int rounds = argc > 4 ? std::max(1, std::atoi(argv[4])) : 5;
    const int frames = argc > 5 ? std::max(1, std::atoi(argv[5])) : 20;
    gl::HeadlessContext context;
    session::Playback playback;
    playback.set("input", argv[1]);
    playback.set("method", argc > 2 ? argv[2] : "isa");
    playback.set("size", argc > 3 ? argv[3] : "1024x1024");
    std::unique_ptr<core::StepProvider> steps = io::openInput(playback.options().input, session::sourceOptions(playback.options()));
    playback.open(*steps);
    session::RenderOptions withTopology = playback.options();
    withTopology.topology = true;
    if (const char* parts = std::getenv("PARTS")) withTopology.topologyParts = parts;
    if (const char* w = std::getenv("LW")) withTopology.topologyLineWidth = std::stof(w);
    session::TopologyOverlay overlay(*steps, withTopology);
    const core::Camera camera0 = session::makeCamera(playback.options(), steps->bounds());
    std::vector<double> frameMs, overlayMs;
    int k = 0;
    auto frame = [&] { playback.render({core::orbitCamera(camera0, 0.5f * float(k++))}); };
    for (int i = 0; i < 3; ++i) frame();  // shaders, first-touch allocations
    for (int r = 0; r < rounds; ++r) {
        auto t0 = Clock::now();
        for (int f = 0; f < frames; ++f) frame();
        frameMs.push_back(msSince(t0, frames));
        // the overlay over the last frame, as often: what --topology on adds to each frame
        const core::Camera camera = playback.lastFrame().camera;
        glFinish();
        t0 = Clock::now();
        for (int f = 0; f < frames; ++f) overlay.draw(*playback.views()[0], camera, 0.0);
        overlayMs.push_back(msSince(t0, frames));
    }
    const skeleton::Skeleton& s = overlay.current();
    size_t pieces = 0;
    for (const skeleton::SkeletonLine& l : s.lines) pieces += l.points.size() > 1 ? l.points.size() - 1 : 0;
    std::printf("method,size,points,lines,pieces,frame_ms,overlay_ms,share\n%s,%s,%zu,%zu,%zu,%.2f,%.2f,%.1f%%\n",
                argc > 2 ? argv[2] : "isa", argc > 3 ? argv[3] : "1024x1024", s.criticalPoints.size(), s.lines.size(),
                pieces, median(frameMs), median(overlayMs), 100.0 * median(overlayMs) / median(frameMs));
} catch (const std::exception& e) {
    std::fprintf(stderr, "flowsurf_overlay_timing: %s\n", e.what());
    return 1;
}
