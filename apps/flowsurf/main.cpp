// flowsurf — command-line program: render, info, bench. One catch here maps each error
// type to its exit code (exit_codes.h); the library never exits the process.
#include "commands.h"
#include "session/options/config_file.h"
#include "session/scene_setup.h"
#include "core/errors.h"
#include "exit_codes.h"
#include "view_app.h"
#include "view_state.h"

#include <CLI/CLI.hpp>

#include <cstdio>

using namespace flowsurf;

namespace {

// Prints the error that is being handled and returns its exit code (exit_codes.h).
int reportCurrentError() {
    try {
        throw;
    } catch (const ConfigError& e) {
        std::fprintf(stderr, "flowsurf: %s\n", e.what());
        return app::kUsage;
    } catch (const IoError& e) {
        std::fprintf(stderr, "flowsurf: %s\n", e.what());
        return app::kIo;
    } catch (const FormatError& e) {
        std::fprintf(stderr, "flowsurf: %s\n", e.what());
        return app::kFormat;
    } catch (const FieldError& e) {
        std::fprintf(stderr, "flowsurf: %s\n", e.what());
        return app::kField;
    } catch (const GlError& e) {
        std::fprintf(stderr, "flowsurf: %s\n", e.what());
        return app::kGl;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "flowsurf: internal error: %s\n", e.what());
        return app::kInternal;
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"flowsurf — dense, animated flow textures on triangle-mesh surfaces (ISA, IBFVS [L]; hybrid LIC [W])", "flowsurf"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "flowsurf 0.1.0");

    app::RenderOptions render;
    CLI::App* renderCmd = app.add_subcommand("render", "Render a flow texture image or animation");
    app::addRenderOptions(*renderCmd, render);

    app::RenderOptions compare;
    std::string compareMethods = "isa,ibfvs,hybrid";
    CLI::App* compareCmd = app.add_subcommand("compare", "Methods side by side on one camera, labelled with ms/frame");
    app::addRenderOptions(*compareCmd, compare);
    compareCmd->add_option("--methods", compareMethods, "Comma-separated methods to compare")->capture_default_str();

    // Quality reports (doc/algorithms.md, "Quality metrics"): `quality`, and --quality on
    // render and compare.
    app::RenderOptions quality;
    std::string qualityMethods = "isa,ibfvs,hybrid";
    app::QualityOutput renderQuality, compareQuality, qualityOut;
    qualityOut.every = 5;
    CLI::App* qualityCmd = app.add_subcommand("quality", "How faithful each method's texture is to the field: "
                                                         "orientation error, frame correlation, contrast, feature size");
    app::addRenderOptions(*qualityCmd, quality);
    qualityCmd->add_option("--methods", qualityMethods, "Comma-separated methods to measure")->capture_default_str();
    bool autoTune = false;
    qualityCmd->add_flag("--auto-tune", autoTune, "Try a small grid of each method's parameters (step, alpha, "
                                                  "filter length, noise scale) on this view; print the trade-off "
                                                  "between orientation error, frame correlation and ms/frame");
    for (auto [cmd, out] : {std::pair{renderCmd, &renderQuality}, {compareCmd, &compareQuality}, {qualityCmd, &qualityOut}}) {
        cmd->add_option("--quality", out->file, "Write the quality report (per method: median, worst and every "
                                                "measured frame; the options and the GL renderer) as JSON")
            ->group("Output")->type_name("PATH");
        cmd->add_option("--quality-every", out->every, "Measure every N-th animation frame (a PNG: its last frame)")
            ->group("Output")->capture_default_str()->check(CLI::Range(1, 100000));
    }

    app::RenderOptions view;
    app::view::ViewOptions viewOpts;
    CLI::App* viewCmd = app.add_subcommand("view", "Interactive viewer: turn, zoom, switch methods, play time");
    app::addRenderOptions(*viewCmd, view);
    const std::string gView = "Viewer";
    viewCmd->add_option("--compare", viewOpts.compare, "Methods side by side sharing one camera, e.g. isa,ibfvs,hybrid")
        ->group(gView);
    viewCmd->add_option("--play", viewOpts.play, "Replay an event log (see README, Viewer)")->group(gView);
    viewCmd->add_option("--record-events", viewOpts.recordEvents, "Write this session's events as a log")->group(gView);
    viewCmd->add_option("--stats", viewOpts.stats, "Write per-frame times as JSON on exit")->group(gView);
    viewCmd->add_flag("--headless", viewOpts.headless, "No window: EGL, driven by --play (tests, batch replays)")
        ->group(gView);
    {
        std::string keys = "\nMouse: left drag rotates (turntable; trackball with t), middle drag or shift+left drag "
                           "pans, the wheel zooms towards the cursor, right drag zooms; drop a file to open it.\nKeys:\n";
        for (const auto& k : app::view::keyTable()) keys += "  " + std::string(k.name) + "\t" + k.description + "\n";
        viewCmd->footer(keys);
    }

    std::string infoPath;
    CLI::App* infoCmd = app.add_subcommand("info", "List what a file holds: points, triangles, arrays, time steps, "
                                                   "bounds, OpenFOAM patches with their fields");
    infoCmd->add_option("file", infoPath, "Surface file or builtin:NAME")->required();
    // How info reads the file: the table's options of reading an input.
    session::RenderOptions infoRead;
    for (const auto& spec : session::renderOptionTable())
        if (session::isReadOption(spec))
            infoCmd->add_option_function<std::string>(
                "--" + spec.name, [&infoRead, s = &spec](const std::string& v) { s->set(infoRead, v); }, spec.help);

    app::BenchOptions bench;
    CLI::App* benchCmd = app.add_subcommand("bench", "Print ms/frame per stage, static and dynamic case");
    benchCmd->add_option("--csv", bench.csv, "Also write the table as CSV to this file");
    benchCmd->add_option("--frames", bench.frames, "Timed frames per row")->check(CLI::Range(1, 10000));
    benchCmd->add_flag("--quick", bench.quick, "A small subset of rows (smoke test)");
    benchCmd->add_option("--methods", bench.methods, "Methods to time")->delimiter(',')->capture_default_str()
        ->check(CLI::IsMember(methods::names(methods::kMethodNames)));
    benchCmd->add_option("--triangles", bench.triangles, "Sphere mesh sizes (triangles)")->delimiter(',')
        ->capture_default_str()->check(CLI::Range(8L, 20'000'000L));
    benchCmd->add_option("--sizes", bench.sizes, "Image sizes WxH")->delimiter(',')->capture_default_str();
    benchCmd->add_option("--grids", bench.grids, "ISA advection mesh resolutions")->delimiter(',')
        ->capture_default_str()->check(CLI::Range(64, 1024));
    benchCmd->add_flag("--dynamic-only", bench.dynamicOnly, "Only the dynamic case (the cost while animating)");
    benchCmd->add_option("--camera", bench.camera, "Camera placement: fit, or paraview (ParaView's ResetCamera framing)")
        ->capture_default_str()->check(CLI::IsMember({"fit", "paraview"}));
    benchCmd->add_option("--lengths", bench.lengths, "Hybrid filter lengths L")->delimiter(',')
        ->capture_default_str()->check(CLI::Range(1, 1001));
    {
        std::vector<std::string> paths;
        for (const auto& [value, name] : methods::kGlPathNames) paths.emplace_back(name);
        benchCmd->add_option("--gl-paths", bench.glPaths, "Per-pixel passes as compute or fragment shaders: each "
                                                         "path listed, one gl_path column (auto: the renderer's)")
            ->delimiter(',')->capture_default_str()->check(CLI::IsMember(paths));
        std::vector<std::string> rasters;
        for (const auto& [value, name] : methods::kSurfaceRasterNames) rasters.emplace_back(name);
        benchCmd->add_option("--surface-rasters", bench.surfaceRasters, "Who rasterises the surface: each listed, "
                                                                       "one raster column (auto: by renderer and triangles per pixel)")
            ->delimiter(',')->capture_default_str()->check(CLI::IsMember(rasters));
    }
    benchCmd->add_option("--enhance-contrast", bench.enhanceContrast,
                         "Contrast enhancement variants to time, each a row (off, texture, color, both)")
        ->delimiter(',')->capture_default_str()->check(CLI::IsMember(methods::names(methods::kEnhanceContrastNames)));
    benchCmd->add_flag("--no-stage-times", bench.noStageTimes,
                       "Time whole frames only (skips the second, synchronised pass per stage)");
    benchCmd->add_flag("--calibration", bench.calibration, "Also time a fixed GL frame no flowsurf change touches "
                                                            "(the machine's speed; scripts/bench-check.sh)");
    benchCmd->add_flag("--transfers", bench.transfers, "Only time host read-backs and uploads of full-image layers "
                                                        "at --sizes (what the tiled parallel mode adds per frame)");
    benchCmd->add_option("--slowdown", bench.slowdown, "METHOD:K renders each frame of METHOD K times (tests the "
                                                       "speed check, scripts/bench-check.sh)")
        ->group("");  // hidden: not a measurement

    // --config FILE: the file's options first, the command line's on top of them.
    for (CLI::App* cmd : {renderCmd, compareCmd, viewCmd, qualityCmd})
        cmd->add_option("--config", "JSON config (e.g. saved by the viewer); options given here override it")
            ->group("Output");
    try {
        if (auto config = app::findConfigArgument(argc, argv)) {
            app::applyConfigFile(*config, render);
            compare = render;
            view = render;
            quality = render;
        }
    } catch (const std::exception&) {
        return reportCurrentError();
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return app::kUsage;
    } catch (const ConfigError& e) {  // thrown by our value parsers inside CLI11 callbacks
        std::fprintf(stderr, "flowsurf: %s\n", e.what());
        return app::kUsage;
    } catch (const std::exception&) {  // a file an option reads (--colormap-file, --dye-file)
        return reportCurrentError();
    }

    try {
        if (*renderCmd) return app::runRender(render, renderQuality);
        if (*infoCmd) return app::runInfo(infoPath, session::sourceOptions(infoRead));
        if (*viewCmd) {
#ifdef FLOWSURF_HAVE_VIEWER
            if (view.input.empty()) throw ConfigError("view: an input file or builtin:NAME is required");
            const core::Viewport standard = app::RenderOptions{}.size;
            viewOpts.sizeGiven = viewCmd->count("--size") > 0 || view.size.width != standard.width ||
                                 view.size.height != standard.height;
            return app::view::runView(view, viewOpts);
#else
            throw ConfigError("view: this flowsurf was built without the viewer (FLOWSURF_BUILD_VIEWER=OFF)");
#endif
        }
        if (*compareCmd) return app::runCompare(compare, compareMethods, compareQuality);
        if (*qualityCmd)
            return autoTune ? app::runAutoTune(quality, qualityMethods, qualityOut)
                            : app::runQuality(quality, qualityMethods, qualityOut);
        if (*benchCmd) return app::runBench(bench);
    } catch (const std::exception&) {
        return reportCurrentError();
    }
    return app::kOk;
}
