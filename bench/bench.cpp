#include "bench.h"

#include "calibration.h"

#include "core/builtin_scenes.h"
#include "methods/common/gl_path.h"
#include "methods/common/stages.h"
#include "methods/make_renderer.h"
#include "session/playback.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

namespace flowsurf::bench {

namespace {

// Table columns; each method's stages count towards one.
struct Column {
    const char* title;
    std::vector<methods::Stage> stages;
};
using S = methods::Stage;
const std::vector<Column> kColumns = {
    {"surface", {S::VelocityImage, S::SeedTextures}},  // N-dependent pass of ISA / hybrid
    {"adv.mesh", {S::AdvectionMesh}},                  // ISA, M-dependent
    {"advect", {S::TextureAdvection, S::ParticleTracing}},  // IBFVS: includes the mesh projection; ISA, IBFVS: and the noise blend
    {"noise", {S::SolidNoise}},
    {"overlay", {S::Overlay, S::EdgeMask}},
    {"contrast", {S::ContrastTexture, S::ContrastColour}},  // --enhance-contrast
};

double columnMs(const BenchRow& r, const Column& c) {
    double sum = 0;
    for (const auto& [name, ms] : r.stageMs)
        for (methods::Stage s : c.stages)
            if (name == methods::stageName(s)) sum += ms;
    return sum;
}

// Times `frames` frames of one case: first pipelined (total), then per stage. Each frame is
// rendered `renders` times (1; more only to prove the speed check fails), the extra
// renders of a dynamic frame from cameras between it and the next, so all stay dynamic.
BenchRow timeCase(session::Playback& playback, const core::Camera& camera0, bool dynamic, int frames,
                  bool stageTimes, int renders) {
    methods::FlowMethod& method = playback.view(0);
    auto frame = [&](int k) {
        for (int r = 0; r < renders; ++r) {
            const float degrees = 0.5f * (float(k) + float(r) / float(renders));
            core::Camera cam = dynamic ? core::orbitCamera(camera0, degrees) : camera0;
            playback.render({cam});  // the frame loop every front end runs; its clock counts on
        }
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
    if (!stageTimes) return row;
    method.timer().reset();
    method.timer().setSynchronous(true);  // each stage its own work, also on llvmpipe
    method.timer().setEnabled(true);
    for (int k = 0; k < frames; ++k) frame(dynamic ? k + 3 + frames : 0);
    method.timer().setEnabled(false);
    row.stageMs = method.timer().meanMs();
    return row;
}

// The parameter sweep of one method: ISA grids, hybrid filter lengths, else one run.
std::vector<std::pair<std::string, methods::MethodParams>> variants(methods::Method m, const BenchOptions& o) {
    std::vector<std::pair<std::string, methods::MethodParams>> v;
    if (m == methods::Method::Isa)
        for (int r : o.gridRes) {
            methods::MethodParams p;
            p.isa.gridRes = r;
            v.emplace_back("R=" + std::to_string(r), p);
        }
    else if (m == methods::Method::Hybrid)
        for (int l : o.filterLengths) {
            methods::MethodParams p;
            p.hybrid.filterLength = l;
            v.emplace_back("L=" + std::to_string(l), p);
        }
    else
        v.emplace_back("-", methods::MethodParams{});
    return v;
}

std::string glPathName(methods::GlPath path) {
    for (const auto& [value, name] : methods::kGlPathNames)
        if (value == path) return std::string(name);
    return "?";
}

// The paths asked for as they resolve on this renderer, each once, in the order asked.
std::vector<methods::GlPath> resolvedGlPaths(const std::vector<methods::GlPath>& requested) {
    std::vector<methods::GlPath> paths;
    for (methods::GlPath p : requested) {
        methods::GlPath r = methods::resolveGlPath(p);
        if (std::find(paths.begin(), paths.end(), r) == paths.end()) paths.push_back(r);
    }
    return paths;
}

// The same for the surface raster of a `triangles` x `vp` row: Gl or Compute, each once.
std::vector<methods::SurfaceRaster> resolvedRasters(const std::vector<methods::SurfaceRaster>& requested,
                                                    size_t triangles, const core::Viewport& vp) {
    std::vector<methods::SurfaceRaster> rasters;
    for (methods::SurfaceRaster r : requested) {
        const methods::SurfaceRaster resolved =
            methods::useComputeRaster(r, triangles, size_t(vp.width) * size_t(vp.height)) ? methods::SurfaceRaster::Compute
                                                                                         : methods::SurfaceRaster::Gl;
        if (std::find(rasters.begin(), rasters.end(), resolved) == rasters.end()) rasters.push_back(resolved);
    }
    return rasters;
}

}  // namespace

std::vector<BenchRow> runBench(const BenchOptions& o) {
    std::vector<BenchRow> rows;
    std::vector<double> calibration;  // ms, one per method group
    std::fputs(tableHeader().c_str(), stdout);
    for (long tris : o.triangles) {
        core::DatasetSteps steps(core::makeBuiltin("builtin:sphere:" + std::to_string(tris)));
        const core::Bounds bounds = steps.bounds();
        const long triangles = long(steps.load(0).triangleCount());
        for (const core::Viewport& vp : o.imageSizes) {
            core::Camera camera = core::fitCamera(bounds, vp, {0.3f, 0.4f, 1.0f});
            if (o.camera == BenchCamera::ParaView) {
                const float r = bounds.radius();
                camera.fovDeg = 30.0f;
                camera.eye = camera.target + glm::normalize(glm::vec3(0.3f, 0.4f, 1.0f)) * (r / std::sin(glm::radians(15.0f)));
                core::fitClipPlanes(camera, bounds);
            }
            for (methods::Method m : o.methods) {
                const std::string name(methods::nameOf(methods::kMethodNames, m));
                if (o.calibration) calibration.push_back(calibrationMs(o.frames, 1));
                for (const auto& [param, variantParams] : variants(m, o))
                    for (methods::GlPath path : resolvedGlPaths(o.glPaths))
                    for (methods::SurfaceRaster raster : resolvedRasters(o.surfaceRasters, size_t(triangles), vp))
                    for (methods::EnhanceContrast enhance : o.enhanceContrast) {
                        methods::MethodParams params = variantParams;
                        params.common.glPath = path;
                        params.common.surfaceRaster = raster;
                        params.common.enhanceContrast = enhance;
                        session::RenderOptions options;
                        options.method = m;
                        options.params = params;
                        options.size = vp;
                        session::Playback playback(options, steps);
                        const int renders = m == o.slowdownMethod ? o.slowdownFactor : 1;
                        for (bool dynamic : {false, true}) {
                            if (o.dynamicOnly && !dynamic) continue;
                            BenchRow r = timeCase(playback, camera, dynamic, o.frames, o.stageTimes, renders);
                            r.method = name;
                            r.triangles = triangles;
                            r.image = vp;
                            r.param = param;
                            if (enhance != methods::EnhanceContrast::Off)
                                r.param += "+" + std::string(methods::nameOf(methods::kEnhanceContrastNames, enhance));
                            r.glPath = glPathName(path);
                            r.raster = raster == methods::SurfaceRaster::Compute ? "compute" : "gl";
                            std::fputs(formatRow(r).c_str(), stdout);
                            std::fflush(stdout);
                            rows.push_back(std::move(r));
                        }
                    }
            }
        }
    }
    if (!calibration.empty()) {
        BenchRow r;
        r.caseName = r.param = r.glPath = r.raster = "-";
        r.method = "calib";
        r.image = {512, 512};
        r.triangles = 80'000;
        std::nth_element(calibration.begin(), calibration.begin() + calibration.size() / 2, calibration.end());
        r.frameMs = calibration[calibration.size() / 2];
        std::fputs(formatRow(r).c_str(), stdout);
        rows.push_back(std::move(r));
    }
    return rows;
}

std::string tableHeader() {
    char line[512];
    int n = std::snprintf(line, sizeof line, "%-6s %-8s %9s %10s %7s %-8s %-7s | %9s %7s |", "method", "case",
                          "triangles", "image", "param", "gl path", "raster", "ms/frame", "fps");
    for (const auto& c : kColumns) n += std::snprintf(line + n, sizeof line - n, " %9s", c.title);
    std::snprintf(line + n, sizeof line - n, "\n");
    return line;
}

std::string formatRow(const BenchRow& r) {
    char line[512], image[32];
    std::snprintf(image, sizeof image, "%dx%d", r.image.width, r.image.height);
    int n = std::snprintf(line, sizeof line, "%-6s %-8s %9ld %10s %7s %-8s %-7s | %9.2f %7.1f |", r.method.c_str(),
                          r.caseName.c_str(), r.triangles, image, r.param.c_str(), r.glPath.c_str(), r.raster.c_str(),
                          r.frameMs, 1000.0 / r.frameMs);
    for (const auto& c : kColumns)
        n += r.stageMs.empty() ? std::snprintf(line + n, sizeof line - n, " %9s", "-")
                               : std::snprintf(line + n, sizeof line - n, " %9.2f", columnMs(r, c));
    std::snprintf(line + n, sizeof line - n, "\n");
    return line;
}

std::string formatCsv(const std::vector<BenchRow>& rows) {
    std::ostringstream s;
    s << "method,case,triangles,width,height,param,gl_path,frame_ms,fps,raster";
    for (const auto& c : kColumns) s << ',' << c.title << "_ms";
    s << '\n';
    for (const auto& r : rows) {
        s << r.method << ',' << r.caseName << ',' << r.triangles << ',' << r.image.width << ',' << r.image.height
          << ',' << r.param << ',' << r.glPath << ',' << r.frameMs << ',' << 1000.0 / r.frameMs << ',' << r.raster;
        for (const auto& c : kColumns) {
            s << ',';
            if (!r.stageMs.empty()) s << columnMs(r, c);  // empty: stages not timed
        }
        s << '\n';
    }
    return s.str();
}

}  // namespace flowsurf::bench
