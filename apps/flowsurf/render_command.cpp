#include "commands.h"
#include "io/series_reader.h"

#include "core/builtin_scenes.h"
#include "core/errors.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "io/image_writer.h"
#include "io/text_writer.h"
#include "io/video_writer.h"
#include "progress.h"
#include "session/playback.h"

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

int runRender(const RenderOptions& o, const QualityOutput& quality) {
    if (o.listBuiltins) return listBuiltins();
    validateRenderOptions(o);
    validateQualityOutput(quality);
    const OutputKind kind = outputKind(o.output);

    // Data: load and check the field before any GL work.
    std::unique_ptr<core::StepProvider> steps = io::openInput(o.input, sourceOptions(o));
    (void)FrameCameras(o, steps->bounds());  // a bad camera path fails before the context is made
    gl::HeadlessContext context(o.verbose);
    Playback playback(o, *steps);
    if (!quality.file.empty()) playback.setQuality(quality.every);
    AnimatedSurface& surface = playback.surface();

    std::unique_ptr<io::VideoWriter> video;
    if (kind == OutputKind::Mp4) video = std::make_unique<io::VideoWriter>(o.output, o.size.width, o.size.height,
                                                                           io::VideoOptions{o.fps, o.crf});
    if (!o.quiet && o.verbose)
        std::fprintf(stderr, "flowsurf: %s, field '%s', %zu triangles, method %s%s\n", o.input.c_str(),
                     surface.field().c_str(), surface.at(0).triangleCount(), playback.view(0).name(),
                     surface.unsteady() ? ", time series" : "");
    if (!o.quiet && o.verbose) {
        const methods::SurfaceGpu& first = surface.at(0);
        std::fprintf(stderr, "flowsurf: colour %s over %g:%g (--color-range %s; values span %g:%g)\n",
                     first.colorName().c_str(), double(surface.colorRange().x), double(surface.colorRange().y),
                     findOption("color-range")->get(o).c_str(), double(first.colorDataRange().x),
                     double(first.colorDataRange().y));
    }

    // One PNG is the image after --frames advection frames (frame k = frames); movies and
    // sequences are --frames frames, k = 0 .. frames - 1 [issue 28 item 5: 12 means 12], and
    // start converged (the warm-up, see playback.h for the clock).
    const int total = kind == OutputKind::Png ? o.frames + 1 : o.frames;
    const auto start = std::chrono::steady_clock::now();
    int rendered = 0;
    if (kind == OutputKind::Png) {
        // A history-free frame alone; with --quality also the one before it (correlations).
        const int stillFrames = !playback.historyFree() ? total : quality.file.empty() ? 1 : std::min(2, total);
        ProgressBar progress("render", stillFrames, !o.quiet);
        playback.onFrame([&] { progress.update(++rendered); });
        playback.still(o.frames);
        progress.finish();
    } else {
        const int warmup = playback.warmupFrames();
        ProgressBar progress("render", warmup + total, !o.quiet);
        playback.onFrame([&] {
            ++rendered;
            progress.update(rendered, rendered <= warmup ? "warm-up" : "");
        });
        playback.start(true);
        for (int k = 0; k < total; ++k) {
            playback.advance();
            const gl::Texture2D& image = playback.view(0).composite();
            if (video) video->addFrame(gl::readRgb8TopDown(image));
            if (kind == OutputKind::PngSequence)
                io::writePngRgb8(sequenceName(o.output, k), o.size.width, o.size.height, 3, gl::readRgb8TopDown(image));
            if (surface.unsteady()) progress.update(rendered, "t = " + std::to_string(playback.lastTime()));
        }
        progress.finish();
        rendered -= warmup;
    }
    const methods::FlowMethod& method = playback.view(0);
    if (o.verbose) {
        glFinish();
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "flowsurf: %d frames in %.2f s: %.1f ms/frame (%.1f fps), data loading and output included\n",
                     rendered, s, 1000.0 * s / rendered, rendered / s);
    }

    if (video) video->finish();
    if (kind == OutputKind::Png)
        io::writePngRgb8(o.output, o.size.width, o.size.height, 3, gl::readRgb8TopDown(method.composite()));
    if (!o.flowTexture.empty())
        io::writePngGray16(o.flowTexture, o.size.width, o.size.height, gl::readGray16TopDown(method.flowTexture()));
    if (!o.quiet) std::fprintf(stderr, "flowsurf: wrote %s\n", o.output.c_str());
    if (!quality.file.empty()) {
        const MethodQuality q{method.name(), quality::kNoValue, playback.qualityFrames(0), playback.qualitySummary(0)};
        io::writeTextFile(quality.file, qualityJson(o, "render", reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                                                    quality.every, {q}));
        if (!o.quiet) std::fprintf(stderr, "flowsurf: wrote %s\n", quality.file.c_str());
    }
    return 0;
}

}  // namespace flowsurf::app
