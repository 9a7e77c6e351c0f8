#include "commands.h"
#include "io/series_reader.h"

#include "core/errors.h"
#include "gl/context.h"
#include "gl/readback.h"
#include "io/image_writer.h"
#include "io/text_writer.h"
#include "present/text.h"
#include "progress.h"
#include "session/playback.h"

#include <epoxy/gl.h>

#include <chrono>
#include <cstdio>

namespace flowsurf::app {

std::vector<methods::Method> splitMethods(const std::string& list) {
    const std::vector<methods::Method> out = parseMethodList(list, "--methods");
    if (out.empty()) throw ConfigError("--methods: give at least one method, e.g. isa,ibfvs");
    return out;
}

double advanceMeasured(Playback& playback, int frames, int every, bool warmUp) {
    playback.quality().configure(every);
    playback.start(warmUp);
    double ms = 0.0;
    for (int k = 0; k <= frames; ++k) {
        glFinish();
        const auto t0 = std::chrono::steady_clock::now();
        playback.advance();
        glFinish();
        ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() -
              playback.quality().msLastFrame();
    }
    return ms / (frames + 1);
}

int runCompare(const RenderOptions& o, const std::string& methodList, const QualityOutput& quality) {
    validateRenderOptions(o);
    validateQualityOutput(quality);
    if (outputKind(o.output) != OutputKind::Png) throw ConfigError("compare: --output must be a .png file");
    const std::vector<methods::Method> names = splitMethods(methodList);

    std::unique_ptr<core::StepProvider> steps = io::openInput(o.input, sourceOptions(o));
    (void)FrameCameras(o, steps->bounds());  // a bad camera path fails before the context is made
    gl::HeadlessContext context(o.verbose);

    // Same camera path, frame count and seed for every method ([L] Fig. 1).
    const int label = std::max(24, o.size.height / 16), gap = 4;
    methods::RgbImage sheet;
    sheet.width = int(names.size()) * o.size.width + int(names.size() - 1) * gap;
    sheet.height = o.size.height + label;
    sheet.pixels.assign(size_t(sheet.width) * sheet.height * 3, 255);
    ProgressBar progress("compare", int(names.size()) * (o.frames + 1), !o.quiet);
    int done = 0;
    std::vector<MethodQuality> qualities;
    for (size_t m = 0; m < names.size(); ++m) {
        // One method at a time, each timed alone; each sees the same data times.
        Playback playback(o, {names[m]});
        playback.open(*steps);
        playback.onFrame([&] { progress.update(++done); });
        double ms = 0.0;
        if (quality.file.empty()) {
            glFinish();
            auto t0 = std::chrono::steady_clock::now();
            playback.start(false);  // every frame 0..frames is timed, as a PNG render without warm-up
            for (int k = 0; k <= o.frames; ++k) playback.advance();
            glFinish();
            ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() /
                 (o.frames + 1);
        } else {
            ms = advanceMeasured(playback, o.frames, quality.every, false);  // as above: no warm-up
            qualities.push_back({playback.views()[0]->name(), ms, playback.quality().frames(0), playback.quality().summary(0)});
        }
        const methods::FlowMethod* method = playback.views()[0].get();
        std::vector<uint8_t> img = gl::readRgb8TopDown(method->composite());
        const int x0 = int(m) * (o.size.width + gap);
        for (int y = 0; y < o.size.height; ++y)
            std::copy_n(&img[size_t(y) * o.size.width * 3], size_t(o.size.width) * 3,
                        &sheet.pixels[(size_t(y + label) * sheet.width + x0) * 3]);
        char text[128];
        std::string upper(methods::nameOf(methods::kMethodNames, names[m]));
        for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
        std::snprintf(text, sizeof text, "%s  %.1f ms/frame (%.0f fps)", upper.c_str(), ms, 1000.0 / ms);
        const uint8_t black[3] = {20, 20, 20};
        methods::drawText(sheet, text, x0 + 8, label * 3 / 4, label * 3 / 5, black);
        if (!o.quiet) std::fprintf(stderr, "\nflowsurf: %s %.2f ms/frame\n", method->name(), ms);
    }
    progress.finish();
    if (!quality.file.empty())
        io::writeTextFile(quality.file, qualityJson(o, "compare", reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                                                    quality.every, qualities));
    io::writePngRgb8(o.output, sheet.width, sheet.height, 3, sheet.pixels);
    if (!o.quiet) std::fprintf(stderr, "flowsurf: wrote %s\n", o.output.c_str());
    return 0;
}

}  // namespace flowsurf::app
