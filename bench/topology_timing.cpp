// The flow topology's cost (doc/bench/topology.md): skeleton::analyze on the built-in sphere
// of N triangles with a field of sources, sinks, saddles and foci, wall time per call (the
// median of R runs), the process's peak memory, and what the analysis adds to what the process
// held before it (the peak over the last run, from /proc/self/status after resetting it
// through /proc/self/clear_refs), against the mesh's own size.
//   flowsurf_topology_timing [TRIANGLES,...] [RUNS]
#include "core/builtin_scenes.h"
#include "skeleton/skeleton.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace flowsurf;

namespace {
// VmRSS or VmHWM of this process in MiB (0 where /proc does not say).
double procStatusMiB(const std::string& key) {
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);)
        if (line.rfind(key + ":", 0) == 0) return std::stod(line.substr(key.size() + 1)) / 1024.0;
    return 0.0;
}
}  // namespace

int main(int argc, char** argv) {
    std::vector<long> sizes{100'000, 1'000'000};
    if (argc > 1) {
        sizes.clear();
        std::stringstream list(argv[1]);
        for (std::string item; std::getline(list, item, ',');) sizes.push_back(std::stol(item));
    }
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
    std::printf("triangles,vertices,mesh_MiB,analyze_ms,points,lines,peak_rss_MiB,analysis_added_MiB\n");
    for (long n : sizes) {
        core::Dataset d = core::makeBuiltin("builtin:sphere:" + std::to_string(n));
        const core::SurfaceMesh& m = d.steps.front().mesh;
        // the tangential part of a constant direction plus a swirl about x: nodes, foci, saddles
        std::vector<glm::vec3> f(m.vertexCount());
        for (size_t i = 0; i < f.size(); ++i) {
            const glm::vec3 p = m.positions[i], nrm = m.normals[i];
            glm::vec3 v = glm::vec3(0, 0, 1) + 1.5f * glm::vec3(0.0f, -p.z, p.y) + 0.6f * std::sin(5.0f * p.x) * glm::vec3(1, 0, 0);
            f[i] = v - glm::dot(v, nrm) * nrm;
        }
        const double meshMiB = double(m.vertexCount() * (sizeof(glm::vec3) * 3) + m.triangleCount() * sizeof(glm::uvec3)) /
                               (1024.0 * 1024.0);
        std::vector<double> ms;
        skeleton::Skeleton s;
        double before = 0.0, added = 0.0;
        for (int r = 0; r < runs; ++r) {
            s = {};
            std::ofstream("/proc/self/clear_refs") << "5";  // the peak from here
            before = procStatusMiB("VmRSS");
            const auto t0 = std::chrono::steady_clock::now();
            s = skeleton::analyze(m, f, {}, "bench");
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
            added = std::max(added, procStatusMiB("VmHWM") - before);
        }
        std::sort(ms.begin(), ms.end());
        rusage u{};
        getrusage(RUSAGE_SELF, &u);
        std::printf("%zu,%zu,%.1f,%.0f,%zu,%zu,%.0f,%.0f\n", m.triangleCount(), m.vertexCount(), meshMiB,
                    ms[ms.size() / 2], s.criticalPoints.size(), s.lines.size(), double(u.ru_maxrss) / 1024.0, added);
        std::fflush(stdout);
    }
}
