#include "bench.h"

#include "core/builtin_scenes.h"
#include "core/camera.h"
#include "methods/common/frame.h"

#include <epoxy/gl.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <sstream>

namespace flowsurf::bench {

namespace {

const char* kStages[] = {"velocity image", "advection mesh", "texture advection", "noise blend", "overlay"};

// Times `frames` frames of one case: first pipelined (total), then per stage.
BenchRow timeCase(methods::FlowMethod& method, const methods::SurfaceGpu& surface, const core::Camera& camera0,
                  bool dynamic, int frames, uint32_t& clock) {
    auto frame = [&](int k) {
        core::Camera cam = dynamic ? core::orbitCamera(camera0, 0.5f * float(k)) : camera0;
        method.renderFrame({&surface, cam, clock++});
    };
    // Warm-up: shader compilation, first-touch allocations, and the static cache.
    for (int k = 0; k < 3; ++k) frame(dynamic ? k : 0);
    glFinish();
    auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < frames; ++k) frame(dynamic ? k + 3 : 0);
    glFinish();
    auto t1 = std::chrono::steady_clock::now();
    BenchRow row;
    row.caseName = dynamic ? "dynamic" : "static";
    row.frameMs = std::chrono::duration<double, std::milli>(t1 - t0).count() / frames;
    method.timer().reset();
    method.timer().setEnabled(true);
    for (int k = 0; k < frames; ++k) frame(dynamic ? k + 3 + frames : 0);
    method.timer().setEnabled(false);
    row.stageMs = method.timer().meanMs();
    return row;
}

double stage(const BenchRow& r, const std::string& name) {
    for (const auto& [n, ms] : r.stageMs)
        if (n == name) return ms;
    return 0.0;
}

}  // namespace

std::vector<BenchRow> runBench(const BenchOptions& o) {
    std::vector<BenchRow> rows;
    std::fputs(formatTable({}).c_str(), stdout);
    for (long tris : o.triangles) {
        core::Dataset data = core::makeBuiltin("builtin:sphere:" + std::to_string(tris));
        const core::SurfaceMesh& mesh = data.steps.front().mesh;
        methods::SurfaceGpu surface(mesh, "velocity");
        for (int size : o.imageSizes) {
            core::Viewport vp{size, size};
            core::Camera camera = core::fitCamera(data.bounds(), vp, {0.3f, 0.4f, 1.0f});
            for (const std::string& name : o.methods)
                for (int grid : o.gridRes) {
                    // Only ISA has an advection mesh: other methods run once per size.
                    if (name != "isa" && grid != o.gridRes.front()) continue;
                    methods::MethodParams params;
                    params.isa.gridRes = grid;
                    auto method = methods::makeMethod(name, params, vp);
                    uint32_t clock = 0;
                    for (bool dynamic : {false, true}) {
                        BenchRow r = timeCase(*method, surface, camera, dynamic, o.frames, clock);
                        r.method = name;
                        r.triangles = long(mesh.triangleCount());
                        r.imageSize = size;
                        r.gridRes = name == "isa" ? grid : 0;
                        std::fputs(formatTable({r}).substr(formatTable({}).size()).c_str(), stdout);
                        std::fflush(stdout);
                        rows.push_back(std::move(r));
                    }
                }
        }
    }
    return rows;
}

std::string formatTable(const std::vector<BenchRow>& rows) {
    std::ostringstream s;
    char line[512];
    std::snprintf(line, sizeof line, "%-6s %-8s %9s %6s %5s | %9s %7s | %9s %9s %9s %9s %9s\n", "method", "case",
                  "triangles", "image", "grid", "ms/frame", "fps", "vel.img", "adv.mesh", "tex.adv", "noise", "overlay");
    s << line;
    for (const auto& r : rows) {
        char grid[16] = "    -";
        if (r.gridRes > 0) std::snprintf(grid, sizeof grid, "%4d²", r.gridRes);
        std::snprintf(line, sizeof line, "%-6s %-8s %9ld %5d² %s | %9.2f %7.1f | %9.2f %9.2f %9.2f %9.2f %9.2f\n",
                      r.method.c_str(), r.caseName.c_str(), r.triangles, r.imageSize, grid, r.frameMs,
                      1000.0 / r.frameMs, stage(r, kStages[0]), stage(r, kStages[1]), stage(r, kStages[2]),
                      stage(r, kStages[3]), stage(r, kStages[4]));
        s << line;
    }
    return s.str();
}

std::string formatCsv(const std::vector<BenchRow>& rows) {
    std::ostringstream s;
    s << "method,case,triangles,image,grid,frame_ms,fps";
    for (const char* st : kStages) s << ',' << st << "_ms";
    s << '\n';
    for (const auto& r : rows) {
        s << r.method << ',' << r.caseName << ',' << r.triangles << ',' << r.imageSize << ',' << r.gridRes << ','
          << r.frameMs << ',' << 1000.0 / r.frameMs;
        for (const char* st : kStages) s << ',' << stage(r, st);
        s << '\n';
    }
    return s.str();
}

}  // namespace flowsurf::bench
