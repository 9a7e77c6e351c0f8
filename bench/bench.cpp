#include "bench.h"

#include "calibration.h"

#include "core/builtin_scenes.h"
#include "core/time_series.h"
#include "gl/context.h"
#include "gpu/gl_path.h"
#include "methods/make_renderer.h"
#include "methods/stages.h"
#include "parallel/agreeing_group.h"
#include "parallel/thread_group.h"
#include "session/playback.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>
#include <exception>
#include <thread>

namespace flowsurf::bench {

static_assert(session::namesEveryValue(kBenchCameraNames));

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
    {"exchange", {S::TileExchange, S::TileReturn}},         // --ranks: the tiles' transfers, waits for peers included
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
    methods::FlowMethod& method = *playback.views()[0];
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

// The static (unless dynamicOnly) and the dynamic case of one playback.
std::vector<BenchRow> timeCases(session::Playback& playback, const core::Camera& camera, const BenchOptions& o,
                                int renders) {
    std::vector<BenchRow> rows;
    for (bool dynamic : {false, true})
        if (dynamic || !o.dynamicOnly) rows.push_back(timeCase(playback, camera, dynamic, o.frames, o.stageTimes, renders));
    return rows;
}

// `mesh` cut into `n` slabs along x with equal triangle counts (by centroid), one per rank.
std::vector<core::SurfaceMesh> slabs(const core::SurfaceMesh& mesh, int n) {
    std::vector<float> xs;
    xs.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) xs.push_back((mesh.positions[t.x].x + mesh.positions[t.y].x + mesh.positions[t.z].x) / 3.0f);
    std::sort(xs.begin(), xs.end());
    std::vector<float> cuts;  // slab r holds centroids in [cuts[r - 1], cuts[r])
    for (int r = 1; r < n; ++r) cuts.push_back(xs[xs.size() * size_t(r) / size_t(n)]);
    std::vector<core::SurfaceMesh> pieces;
    for (int r = 0; r < n; ++r)
        pieces.push_back(core::pieceOf(mesh, [&cuts, r](glm::vec3 c) {
            return std::upper_bound(cuts.begin(), cuts.end(), c.x) - cuts.begin() == r;
        }));
    return pieces;
}

// timeCases with `pieces.size()` threads as one group, each rendering its piece with its own
// GL context, as the plugin's ranks do (an AgreeingGroup over the group, every rank's error
// the same on all). Each case's row: the slowest rank's frame and stage times.
std::vector<BenchRow> timeRanks(const std::vector<core::SurfaceMesh>& pieces, const session::RenderOptions& options,
                                const core::Camera& camera, const BenchOptions& o, int renders) {
    const int n = int(pieces.size());
    methods::ThreadGroup group(n);
    std::vector<std::vector<BenchRow>> perRank(static_cast<size_t>(n));
    std::vector<std::exception_ptr> errors(static_cast<size_t>(n));
    std::vector<std::thread> threads;
    for (int r = 0; r < n; ++r)
        threads.emplace_back([&, r] {
            methods::ThreadGroup::Member member(group, r);
            methods::AgreeingGroup agreeing(member);
            try {
                methods::collectiveSection(&agreeing, [&] {
                    gl::HeadlessContext context;
                    core::DatasetSteps steps(core::Dataset{"bench slab " + std::to_string(r), {{0.0, pieces[size_t(r)]}}});
                    session::Playback playback(options, {}, &agreeing);
                    playback.open(steps);
                    perRank[size_t(r)] = timeCases(playback, camera, o, renders);
                });
            } catch (...) {
                errors[size_t(r)] = std::current_exception();  // the same PeerFailure on every rank
            }
        });
    for (auto& t : threads) t.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
    std::vector<BenchRow> rows = perRank[0];
    for (size_t c = 0; c < rows.size(); ++c)
        for (int r = 1; r < n; ++r) {
            const BenchRow& other = perRank[size_t(r)][c];
            rows[c].frameMs = std::max(rows[c].frameMs, other.frameMs);
            for (auto& [name, ms] : rows[c].stageMs)
                for (const auto& [otherName, otherMs] : other.stageMs)
                    if (otherName == name) ms = std::max(ms, otherMs);
            for (const auto& [otherName, otherMs] : other.stageMs)  // a stage rank 0 did not run
                if (std::none_of(rows[c].stageMs.begin(), rows[c].stageMs.end(),
                                 [&](const auto& st) { return st.first == otherName; }))
                    rows[c].stageMs.emplace_back(otherName, otherMs);
        }
    for (BenchRow& row : rows) {
        row.ranks = n;
        row.parallel = std::string(methods::nameOf(methods::kParallelModeNames, options.params.common.parallel));
    }
    return rows;
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
    const bool withRanks = o.ranks != std::vector<int>{1};
    std::fputs(tableHeader(withRanks).c_str(), stdout);
    for (long tris : o.triangles) {
        core::DatasetSteps steps(core::makeBuiltin("builtin:sphere:" + std::to_string(tris)));
        const core::Bounds bounds = steps.bounds();
        const long triangles = long(steps.load(0).triangleCount());
        std::map<int, std::vector<core::SurfaceMesh>> pieces;  // by rank count, cut once per mesh
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
                    for (methods::EnhanceContrast enhance : o.enhanceContrast)
                    for (int ranks : o.ranks)
                    for (methods::ParallelMode parallel : o.parallel) {
                        if (ranks == 1 && parallel != o.parallel.front()) continue;  // one rank: no mode
                        methods::MethodParams params = variantParams;
                        params.common.glPath = path;
                        params.common.surfaceRaster = raster;
                        params.common.enhanceContrast = enhance;
                        params.common.parallel = parallel;
                        session::RenderOptions options;
                        options.method = m;
                        options.params = params;
                        options.size = vp;
                        const int renders = m == o.slowdownMethod ? o.slowdownFactor : 1;
                        std::vector<BenchRow> cases;
                        if (ranks == 1) {
                            session::Playback playback(options);
                            playback.open(steps);
                            cases = timeCases(playback, camera, o, renders);
                        } else {
                            if (!pieces.count(ranks)) pieces[ranks] = slabs(steps.load(0), ranks);
                            cases = timeRanks(pieces[ranks], options, camera, o, renders);
                        }
                        for (BenchRow& r : cases) {
                            r.method = name;
                            r.triangles = triangles;
                            r.image = vp;
                            r.param = param;
                            if (enhance != methods::EnhanceContrast::Off)
                                r.param += "+" + std::string(methods::nameOf(methods::kEnhanceContrastNames, enhance));
                            r.glPath = glPathName(path);
                            r.raster = raster == methods::SurfaceRaster::Compute ? "compute" : "gl";
                            std::fputs(formatRow(r, withRanks).c_str(), stdout);
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

std::string tableHeader(bool ranks) {
    char line[512];
    int n = std::snprintf(line, sizeof line, "%-6s %-8s %9s %10s %7s %-8s %-7s | %9s %7s |", "method", "case",
                          "triangles", "image", "param", "gl path", "raster", "ms/frame", "fps");
    for (const auto& c : kColumns) n += std::snprintf(line + n, sizeof line - n, " %9s", c.title);
    if (ranks) n += std::snprintf(line + n, sizeof line - n, " | ranks");
    std::snprintf(line + n, sizeof line - n, "\n");
    return line;
}

std::string formatRow(const BenchRow& r, bool ranks) {
    char line[512], image[32];
    std::snprintf(image, sizeof image, "%dx%d", r.image.width, r.image.height);
    int n = std::snprintf(line, sizeof line, "%-6s %-8s %9ld %10s %7s %-8s %-7s | %9.2f %7.1f |", r.method.c_str(),
                          r.caseName.c_str(), r.triangles, image, r.param.c_str(), r.glPath.c_str(), r.raster.c_str(),
                          r.frameMs, 1000.0 / r.frameMs);
    for (const auto& c : kColumns)
        n += r.stageMs.empty() ? std::snprintf(line + n, sizeof line - n, " %9s", "-")
                               : std::snprintf(line + n, sizeof line - n, " %9.2f", columnMs(r, c));
    if (ranks) n += std::snprintf(line + n, sizeof line - n, " | %d %s", r.ranks, r.ranks > 1 ? r.parallel.c_str() : "");
    std::snprintf(line + n, sizeof line - n, "\n");
    return line;
}

std::string formatCsv(const std::vector<BenchRow>& rows) {
    std::ostringstream s;
    s << "method,case,triangles,width,height,param,gl_path,frame_ms,fps,raster";
    for (const auto& c : kColumns) s << ',' << c.title << "_ms";
    s << ",ranks,parallel\n";
    for (const auto& r : rows) {
        s << r.method << ',' << r.caseName << ',' << r.triangles << ',' << r.image.width << ',' << r.image.height
          << ',' << r.param << ',' << r.glPath << ',' << r.frameMs << ',' << 1000.0 / r.frameMs << ',' << r.raster;
        for (const auto& c : kColumns) {
            s << ',';
            if (!r.stageMs.empty()) s << columnMs(r, c);  // empty: stages not timed
        }
        s << ',' << r.ranks << ',' << r.parallel << '\n';
    }
    return s.str();
}

}  // namespace flowsurf::bench
