// flowsurf quality: each method's animation (warm-up, then --frames + 1 frames) measured
// against the field every N frames; one row per method on stdout, --quality FILE.json.
#include "commands.h"

#include "core/errors.h"
#include "gl/context.h"
#include "io/series_reader.h"
#include "io/text_writer.h"
#include "progress.h"
#include "session/playback.h"

#include <epoxy/gl.h>

#include <cstdio>

namespace flowsurf::app {

int runQuality(const RenderOptions& o, const std::string& methodList, const QualityOutput& q) {
    validateRenderOptions(o);
    validateQualityOutput(q);
    const std::vector<methods::Method> names = splitMethods(methodList);

    std::unique_ptr<core::StepProvider> steps = io::openInput(o.input, sourceOptions(o));
    (void)FrameCameras(o, steps->bounds());  // a bad camera path fails before the context is made
    gl::HeadlessContext context(o.verbose);
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));

    std::vector<MethodQuality> results;
    for (methods::Method name : names) {
        Playback playback(o, {name});
        playback.open(*steps);
        const int total = playback.warmupFrames() + o.frames + 1;
        ProgressBar progress("quality " + std::string(methods::nameOf(methods::kMethodNames, name)), total, !o.quiet);
        int done = 0;
        playback.onFrame([&] { progress.update(++done); });
        const double ms = advanceMeasured(playback, o.frames, q.every, true);
        progress.finish();
        results.push_back({playback.views()[0]->name(), ms, playback.quality().frames(0), playback.quality().summary(0)});
    }
    if (!o.quiet)
        std::fprintf(stderr, "flowsurf: %s, %dx%d, %d frames after the warm-up, measured every %d; %s\n",
                     o.input.c_str(), o.size.width, o.size.height, o.frames + 1, q.every, renderer.c_str());
    std::fputs(qualityTable(results).c_str(), stdout);
    if (!q.file.empty()) {
        io::writeTextFile(q.file, qualityJson(o, "quality", renderer, q.every, results));
        if (!o.quiet) std::fprintf(stderr, "flowsurf: wrote %s\n", q.file.c_str());
    }
    return 0;
}

}  // namespace flowsurf::app
