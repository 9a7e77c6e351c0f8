// The timing behind doc/bench/isa_ibfvs_gl_path_llvmpipe.txt: frames of one surface through
// the public C++ API (as the Python module renders them: advance() then readImage() per
// frame, the API's stage timer on), each option set ("variant") on a fresh renderer from
// the defaults, timed `reps` times interleaved with the others; prints the minimum over the
// reps of the wall and process-CPU ms per frame and of each stage's mean ms. Built as
// build/bench/flowsurf_api_timing:
//   build/bench/flowsurf_api_timing windAroundBuildings_wss.vtp wallShearStress 800x600 3 orbit=0 orbit=1
// INPUT FIELD (- : the default) WxH REPS VARIANT...; VARIANT = option=value[,option=value...]
#include <flowsurf/flowsurf.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <sstream>
#include <string>
#include <vector>

static double cpuMs() {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

int main(int argc, char** argv) {
    if (argc < 6) {
        std::fprintf(stderr, "usage: %s INPUT FIELD WxH REPS VARIANT...\n", argv[0]);
        return 2;
    }
    const std::string input = argv[1], field = argv[2], size = argv[3];
    const int reps = std::atoi(argv[4]);
    const std::vector<std::string> variants(argv + 5, argv + argc);
    const flowsurf::Surface surface = flowsurf::Surface::read(input, field == "-" ? "" : field);
    const int frames = 10, warmup = 3;
    std::map<std::string, std::map<std::string, double>> bestStage;
    std::map<std::string, double> bestWall, bestCpu;
    std::vector<std::string> stageOrder;
    std::string renderer;
    std::vector<uint8_t> rgb;
    auto keepMin = [](auto& m, const std::string& k, double v) { m[k] = m.count(k) ? std::min(m[k], v) : v; };
    for (int rep = 0; rep < reps; ++rep)
        for (const std::string& v : variants) {
            flowsurf::Renderer r;  // each variant from the defaults: no option carries over
            renderer = r.glRenderer();
            r.set("method", "isa");
            r.set("size", size);
            r.set("orbit", "0");
            r.set("gl-path", "auto");
            std::stringstream items(v);
            for (std::string item; std::getline(items, item, ',');) {
                const size_t eq = item.find('=');
                r.set(item.substr(0, eq), item.substr(eq + 1));
            }
            r.begin(surface);
            rgb.resize(size_t(r.width()) * r.height() * 3);
            for (int k = 0; k < warmup; ++k) r.advance(), r.readImage(rgb.data());
            std::map<std::string, double> stages;
            const auto t0 = std::chrono::steady_clock::now();
            const double c0 = cpuMs();
            for (int k = 0; k < frames; ++k) {
                r.advance();
                r.readImage(rgb.data());
                for (const auto& [name, ms] : r.stageMs()) {
                    if (std::find(stageOrder.begin(), stageOrder.end(), name) == stageOrder.end())
                        stageOrder.push_back(name);
                    stages[name] += ms / frames;
                }
            }
            keepMin(bestCpu, v, (cpuMs() - c0) / frames);
            keepMin(bestWall, v,
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / frames);
            for (const auto& [name, ms] : stages) keepMin(bestStage[v], name, ms);
        }
    std::printf("%s on %s, min over %d reps of %d frames\n", input.c_str(), renderer.c_str(), reps, frames);
    for (const std::string& v : variants) {
        std::printf("%-36s wall %7.1f  cpu %7.1f ms/frame |", v.c_str(), bestWall[v], bestCpu[v]);
        for (const std::string& n : stageOrder)
            if (bestStage[v].count(n)) std::printf(" %s %.1f |", n.c_str(), bestStage[v][n]);
        std::printf("\n");
    }
}
