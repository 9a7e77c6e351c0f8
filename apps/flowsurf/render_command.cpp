#include "commands.h"

#include "core/builtin_scenes.h"
#include "core/errors.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "io/image_writer.h"
#include "io/video_writer.h"
#include "methods/common/frame.h"
#include "session/animated_surface.h"
#include "progress.h"
#include "session/scene_setup.h"
#include "methods/make_renderer.h"

#include <epoxy/gl.h>

#include <chrono>
#include <cstdio>
#include <memory>

namespace flowsurf::app {

namespace {

std::string sequenceName(const std::string& pattern, int frame) {
    std::vector<char> buf(pattern.size() + 32);
    std::snprintf(buf.data(), buf.size(), pattern.c_str(), frame);
    return buf.data();
}

int listBuiltins() {
    std::printf("Built-in scenes (use as builtin:NAME or builtin:NAME:TRIANGLES):\n");
    for (const auto& b : core::builtinScenes()) std::printf("  %-16s %s\n", b.name.c_str(), b.description.c_str());
    return 0;
}

}  // namespace

int runRender(const RenderOptions& o) {
    if (o.listBuiltins) return listBuiltins();
    validateRenderOptions(o);
    const OutputKind kind = outputKind(o.output);

    // Data: load and check the field before any GL work.
    std::unique_ptr<core::StepProvider> steps = openInput(o);
    const FrameCameras cameras(o, steps->bounds());
    gl::HeadlessContext context(o.verbose);
    AnimatedSurface surface(o, *steps);
    std::unique_ptr<methods::FlowMethod> method = methods::makeMethod(o.method, surface.paramsFor(o.params), o.size);

    std::unique_ptr<io::VideoWriter> video;
    if (kind == OutputKind::Mp4) video = std::make_unique<io::VideoWriter>(o.output, o.size.width, o.size.height,
                                                                           io::VideoOptions{o.fps, o.crf});
    if (!o.quiet && o.verbose)
        std::fprintf(stderr, "flowsurf: %s, field '%s', %zu triangles, method %s%s\n", o.input.c_str(),
                     surface.field().c_str(), surface.at(0).triangleCount(), method->name(),
                     surface.unsteady() ? ", time series" : "");

    // Movies start converged: --warmup frames of frame 0's data and camera are advected
    // before the first written frame (the clock, which drives the noise, keeps counting).
    const int warmup = kind == OutputKind::Png ? 0 : warmupFrames(o);
    // --frames advection frames, then the output frame.
    const int total = o.frames + 1;
    ProgressBar progress("render", warmup + total, !o.quiet);
    const auto start = std::chrono::steady_clock::now();
    for (int w = 0; w < warmup; ++w) {
        const methods::SurfaceGpu& frameSurface = surface.at(0);
        method->renderFrame({&frameSurface, cameras.at(0), uint32_t(w),
                             method->usesTimeLevels() ? surface.levelsAt(0) : nullptr});
        progress.update(w + 1, "warm-up");
    }
    // One PNG of a history-free method (the hybrid) needs only its last frame.
    const int first = kind == OutputKind::Png && method->historyFree() ? total - 1 : 0;
    for (int k = first; k < total; ++k) {
        const methods::SurfaceGpu& frameSurface = surface.at(k);
        method->renderFrame({&frameSurface, cameras.at(k), uint32_t(warmup + k),
                             method->usesTimeLevels() ? surface.levelsAt(k) : nullptr});
        if (video) video->addFrame(gl::readRgb8TopDown(method->composite()));
        if (kind == OutputKind::PngSequence)
            io::writePngRgb8(sequenceName(o.output, k), o.size.width, o.size.height, 3,
                             gl::readRgb8TopDown(method->composite()));
        progress.update(warmup + k + 1, surface.unsteady() ? "t = " + std::to_string(surface.timeAt(k)) : "");
    }
    progress.finish();
    if (o.verbose) {
        glFinish();
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "flowsurf: %d frames in %.2f s: %.1f ms/frame (%.1f fps), data loading and output included\n",
                     total - first, s, 1000.0 * s / (total - first), (total - first) / s);
    }

    if (video) video->finish();
    if (kind == OutputKind::Png)
        io::writePngRgb8(o.output, o.size.width, o.size.height, 3, gl::readRgb8TopDown(method->composite()));
    if (!o.flowTexture.empty())
        io::writePngGray16(o.flowTexture, o.size.width, o.size.height, gl::readGray16TopDown(method->flowTexture()));
    if (!o.quiet) std::fprintf(stderr, "flowsurf: wrote %s\n", o.output.c_str());
    return 0;
}

}  // namespace flowsurf::app
