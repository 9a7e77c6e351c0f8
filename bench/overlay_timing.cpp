// The flow topology overlay's cost per frame (doc/bench/topology.md): a method's frames of
// INPUT with --topology off, each followed by the overlay alone drawn over it with its camera
// (TopologyOverlay::draw: the lines simplified for the view when it moved, their pieces and
// the points), each timed apart (glFinish at both ends), in rounds. Dynamic (default): the
// camera orbits half a degree a frame (ISA's dynamic case, the lines simplified every frame);
// STATIC=1: one camera throughout (the method's static frames, the overlay's pieces of the
// first frame). Prints the median of the rounds, the overlay's share of the frame and its
// line pieces (uploaded, drawn in the last frame). PARTS (points,lines | points | lines) and
// LW (line width, px) in the environment vary what is drawn.
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
    const char* fixed = std::getenv("STATIC");
    const bool still = fixed && std::string(fixed) != "0";
    std::vector<double> frameMs, overlayMs;
    int k = 0;
    // one frame and the overlay over it: what --topology on adds to each frame
    auto frame = [&](double* frameSum, double* overlaySum) {
        glFinish();
        auto t0 = Clock::now();
        playback.render({still ? camera0 : core::orbitCamera(camera0, 0.5f * float(k++))});
        *frameSum += msSince(t0, 1);
        t0 = Clock::now();
        overlay.draw(*playback.views()[0], playback.lastFrame().camera, 0.0);
        *overlaySum += msSince(t0, 1);
    };
    double unused = 0.0;
    for (int i = 0; i < 3; ++i) frame(&unused, &unused);  // shaders, first-touch allocations
    for (int r = 0; r < rounds; ++r) {
        double f = 0.0, o = 0.0;
        for (int i = 0; i < frames; ++i) frame(&f, &o);
        frameMs.push_back(f / frames);
        overlayMs.push_back(o / frames);
    }
    const skeleton::Skeleton& s = overlay.current();
    std::printf("method,size,camera,points,lines,pieces,drawn,frame_ms,overlay_ms,share\n"
                "%s,%s,%s,%zu,%zu,%zu,%zu,%.2f,%.2f,%.1f%%\n",
                argc > 2 ? argv[2] : "isa", argc > 3 ? argv[3] : "1024x1024", still ? "static" : "orbit",
                s.criticalPoints.size(), s.lines.size(), overlay.layer().piecesUploaded(), overlay.layer().piecesDrawn(),
                median(frameMs), median(overlayMs), 100.0 * median(overlayMs) / median(frameMs));
} catch (const std::exception& e) {
    std::fprintf(stderr, "flowsurf_overlay_timing: %s\n", e.what());
    return 1;
}
