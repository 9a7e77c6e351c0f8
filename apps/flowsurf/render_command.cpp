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

#include <algorithm>
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

// --verbose: what was read and how its colour is mapped.
void describeInput(const RenderOptions& o, Playback& playback) {
    AnimatedSurface& surface = playback.surface();
    std::fprintf(stderr, "flowsurf: %s, field '%s', %zu triangles, method %s%s\n", o.input.c_str(),
                 surface.field().c_str(), surface.at(0).triangleCount(), playback.views()[0]->name(),
                 surface.unsteady() ? ", time series" : "");
    const methods::SurfaceGpu& first = surface.at(0);
    std::fprintf(stderr, "flowsurf: colour %s over %g:%g (--color-range %s; values span %g:%g)\n",
                 first.colorName().c_str(), double(surface.colorRange().x), double(surface.colorRange().y),
                 findOption("color-range")->get(o).c_str(), double(first.colorDataRange().x),
                 double(first.colorDataRange().y));
}

// One PNG: the image after --frames advection frames (frame k = frames). Returns the
// frames rendered.
int renderStill(const RenderOptions& o, const QualityOutput& quality, Playback& playback) {
    // A history-free frame alone; with --quality also the one before it (correlations).
    const int total = o.frames + 1;
    const bool historyFree = std::ranges::all_of(playback.views(), [](const auto& m) { return m->historyFree(); });
    const int stillFrames = !historyFree ? total : quality.file.empty() ? 1 : std::min(2, total);
    int rendered = 0;
    ProgressBar progress("render", stillFrames, !o.quiet);
    playback.onFrame([&] { progress.update(++rendered); });
    playback.still(o.frames);
    progress.finish();
    return rendered;
}

// A movie or PNG sequence: --frames frames, k = 0 .. frames - 1 (12 means
// 12), started converged (the warm-up, see playback.h for the clock), each written as it
// is rendered. Returns the frames rendered, warm-up left out.
int renderMovie(const RenderOptions& o, Playback& playback) {
    std::unique_ptr<io::VideoWriter> video;
    if (outputKind(o.output) == OutputKind::Mp4)
        video = std::make_unique<io::VideoWriter>(o.output, o.size.width, o.size.height, io::VideoOptions{o.fps, o.crf});
    const int warmup = playback.warmupFrames();
    int rendered = 0;
    ProgressBar progress("render", warmup + o.frames, !o.quiet);
    playback.onFrame([&] {
        ++rendered;
        progress.update(rendered, rendered <= warmup ? "warm-up" : "");
    });
    playback.start(true);
    for (int k = 0; k < o.frames; ++k) {
        playback.advance();
        const gl::Texture2D& image = playback.views()[0]->composite();
        if (video) video->addFrame(gl::readRgb8TopDown(image));
        else io::writePngRgb8(sequenceName(o.output, k), o.size.width, o.size.height, 3, gl::readRgb8TopDown(image));
        if (playback.surface().unsteady()) progress.update(rendered, "t = " + std::to_string(playback.lastFrame().time));
    }
    progress.finish();
    if (video) video->finish();
    return rendered - warmup;
}

// The final PNG, the flow texture and the quality log, after the frames.
void writeOutputs(const RenderOptions& o, const QualityOutput& quality, Playback& playback) {
    const methods::FlowMethod& method = *playback.views()[0];
    if (outputKind(o.output) == OutputKind::Png)
        io::writePngRgb8(o.output, o.size.width, o.size.height, 3, gl::readRgb8TopDown(method.composite()));
    if (!o.flowTexture.empty())
        io::writePngGray16(o.flowTexture, o.size.width, o.size.height, gl::readGray16TopDown(method.flowTexture()));
    if (!o.quiet) std::fprintf(stderr, "flowsurf: wrote %s\n", o.output.c_str());
    if (!quality.file.empty()) {
        const MethodQuality q{method.name(), quality::kNoValue, playback.quality().frames(0), playback.quality().summary(0)};
        io::writeTextFile(quality.file, qualityJson(o, "render", reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                                                    quality.every, {q}));
        if (!o.quiet) std::fprintf(stderr, "flowsurf: wrote %s\n", quality.file.c_str());
    }
}

}  // namespace

int runRender(const RenderOptions& o, const QualityOutput& quality) {
    if (o.listBuiltins) return listBuiltins();
    validateRenderOptions(o);
    validateQualityOutput(quality);

    // Data: load and check the field before any GL work.
    std::unique_ptr<core::StepProvider> steps = io::openInput(o.input, sourceOptions(o));
    (void)FrameCameras(o, steps->bounds());  // a bad camera path fails before the context is made
    gl::HeadlessContext context(o.verbose);
    Playback playback(o);
    playback.open(*steps);
    if (!quality.file.empty()) playback.quality().configure(quality.every);
    if (!o.quiet && o.verbose) describeInput(o, playback);

    const auto start = std::chrono::steady_clock::now();
    const int rendered =
        outputKind(o.output) == OutputKind::Png ? renderStill(o, quality, playback) : renderMovie(o, playback);
    if (o.verbose) {
        glFinish();
        double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "flowsurf: %d frames in %.2f s: %.1f ms/frame (%.1f fps), data loading and output included\n",
                     rendered, s, 1000.0 * s / rendered, rendered / s);
    }
    writeOutputs(o, quality, playback);
    return 0;
}

}  // namespace flowsurf::app
