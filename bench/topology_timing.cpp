// The flow topology's cost (doc/bench/topology.md): skeleton::analyze on the built-in sphere
// of N triangles with a field of sources, sinks, saddles and foci, wall time per call (the
// median of R runs) and the process's peak memory against the mesh's own size.
//   flowsurf_topology_timing [TRIANGLES,...] [RUNS]
#include "core/builtin_scenes.h"
#include "skeleton/skeleton.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using namespace flowsurf;

int main(int argc, char** argv) {
    std::vector<long> sizes{100'000, 1'000'000};
    if (argc > 1) {
        sizes.clear();
        std::stringstream list(argv[1]);
        for (std::string item; std::getline(list, item, ',');) sizes.push_back(std::stol(item));
    }
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
    std::printf("triangles,vertices,mesh_MiB,analyze_ms,points,lines,peak_rss_MiB\n");
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
        for (int r = 0; r < runs; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            s = skeleton::analyze(m, f, {}, "bench");
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        }
        std::sort(ms.begin(), ms.end());
        rusage u{};
        getrusage(RUSAGE_SELF, &u);
        std::printf("%zu,%zu,%.1f,%.0f,%zu,%zu,%.0f\n", m.triangleCount(), m.vertexCount(), meshMiB, ms[ms.size() / 2],
                    s.criticalPoints.size(), s.lines.size(), double(u.ru_maxrss) / 1024.0);
        std::fflush(stdout);
    }
}
