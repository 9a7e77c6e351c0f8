// flowsurf — command-line program: render, info, bench. One catch here maps each error
// type to its exit code (exit_codes.h); the library never exits the process.
#include "bench.h"
#include "commands.h"
#include "session/options/config_file.h"
#include "session/scene_setup.h"
#include "core/errors.h"
#include "exit_codes.h"
#include "view_app.h"
#include "view_state.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>

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

// "isa,ibfvs,hybrid": the methods of the table, comma-separated.
std::string everyMethod() {
    std::string list;
    for (const auto& [m, name] : methods::kMethodNames) list += (list.empty() ? "" : ",") + std::string(name);
    return list;
}

// The subcommands, and what parsing the command line fills in for each.
struct Commands {
    app::RenderOptions render, compare, quality, view, topology;
    std::string compareMethods = everyMethod(), qualityMethods = everyMethod();
    app::QualityOutput renderQuality, compareQuality, qualityOut;
    bool autoTune = false;
    app::view::ViewOptions viewOpts;
    std::string infoPath;
    session::RenderOptions infoRead;  // how info reads the file
    app::BenchCommand bench;
    CLI::App *renderCmd = nullptr, *compareCmd = nullptr, *qualityCmd = nullptr, *viewCmd = nullptr,
             *infoCmd = nullptr, *benchCmd = nullptr, *topologyCmd = nullptr;
};

// render, compare and quality, each with --quality (doc/algorithms.md, "Quality metrics").
void addRenderingCommands(CLI::App& app, Commands& c) {
    c.renderCmd = app.add_subcommand("render", "Render a flow texture image or animation");
    app::addRenderOptions(*c.renderCmd, c.render);

    c.compareCmd = app.add_subcommand("compare", "Methods side by side on one camera, labelled with ms/frame");
    app::addRenderOptions(*c.compareCmd, c.compare);
    c.compareCmd->add_option("--methods", c.compareMethods, "Comma-separated methods to compare")->capture_default_str();

    c.qualityOut.every = 5;
    c.qualityCmd = app.add_subcommand("quality", "How faithful each method's texture is to the field: "
                                                 "orientation error, frame correlation, contrast, feature size");
    app::addRenderOptions(*c.qualityCmd, c.quality);
    c.qualityCmd->add_option("--methods", c.qualityMethods, "Comma-separated methods to measure")->capture_default_str();
    c.qualityCmd->add_flag("--auto-tune", c.autoTune, "Try a small grid of each method's parameters (step, alpha, "
                                                      "filter length, noise scale) on this view; print the trade-off "
                                                      "between orientation error, frame correlation and ms/frame");
    for (auto [cmd, out] : {std::pair{c.renderCmd, &c.renderQuality}, {c.compareCmd, &c.compareQuality},
                            {c.qualityCmd, &c.qualityOut}}) {
        cmd->add_option("--quality", out->file, "Write the quality report (per method: median, worst and every "
                                                "measured frame; the options and the GL renderer) as JSON")
            ->group("Output")->type_name("PATH");
        cmd->add_option("--quality-every", out->every, "Measure every N-th animation frame (a PNG: its last frame)")
            ->group("Output")->capture_default_str()->check(CLI::Range(1, 100000));
    }
}

void addTopologyCommand(CLI::App& app, Commands& c) {
    c.topologyCmd = app.add_subcommand("topology", "Critical points, separation and attachment lines of the shown "
                                                   "field, written as JSON, CSV or VTP (-o OUT.json)");
    c.topology.output.clear();  // required: no image default
    app::addRenderOptions(*c.topologyCmd, c.topology);
}

void addViewCommand(CLI::App& app, Commands& c) {
    CLI::App* viewCmd = c.viewCmd = app.add_subcommand("view", "Interactive viewer: turn, zoom, switch methods, play time");
    app::view::ViewOptions& viewOpts = c.viewOpts;
    app::addRenderOptions(*viewCmd, c.view);
    const std::string gView = "Viewer";
    viewCmd->add_option("--compare", viewOpts.compare, "Methods side by side sharing one camera, e.g. isa,ibfvs,hybrid")
        ->group(gView);
    viewCmd->add_option("--play", viewOpts.play, "Replay an event log (see README, Viewer)")->group(gView);
    viewCmd->add_option("--record-events", viewOpts.recordEvents, "Write this session's events as a log")->group(gView);
    viewCmd->add_option("--stats", viewOpts.stats, "Write per-frame times as JSON on exit")->group(gView);
    viewCmd->add_flag("--headless", viewOpts.headless, "No window: EGL, driven by --play (tests, batch replays)")
        ->group(gView);
    std::string keys = "\nMouse: left drag rotates (turntable; trackball with t), middle drag or shift+left drag "
                       "pans, the wheel zooms towards the cursor, right drag zooms; drop a file to open it.\nKeys:\n";
    for (const auto& k : app::view::keyTable()) keys += "  " + std::string(k.name) + "\t" + k.description + "\n";
    viewCmd->footer(keys);
}

void addInfoCommand(CLI::App& app, Commands& c) {
    CLI::App* infoCmd = c.infoCmd = app.add_subcommand("info", "List what a file holds: points, triangles, arrays, "
                                                               "time steps, bounds, OpenFOAM patches with their fields");
    infoCmd->add_option("file", c.infoPath, "Surface file or builtin:NAME")->required();
    // How info reads the file: the table's options of reading an input.
    session::RenderOptions& infoRead = c.infoRead;
    for (const auto& spec : session::renderOptionTable()) {
        if (!spec.takes(session::FrontEnd::Read)) continue;
        if (spec.kind == session::OptionKind::Flag)
            infoCmd->add_flag_callback("--" + spec.name, [&infoRead, s = &spec] { s->set(infoRead, "true"); }, spec.help);
        else
            infoCmd->add_option_function<std::string>(
                "--" + spec.name, [&infoRead, s = &spec](const std::string& v) { s->set(infoRead, v); }, spec.help);
    }
}

// A list of names of `table` kept as their values in `values` (bench's --methods,
// --gl-paths, ...); the default shown is the names of what `values` holds.
template <typename E, size_t N>
CLI::Option* addNameList(CLI::App& cmd, const std::string& flag, std::vector<E>& values,
                         const methods::EnumNames<E, N>& table, const std::string& help) {
    std::vector<std::string> shown;
    for (E v : values) shown.emplace_back(methods::nameOf(table, v));
    return cmd
        .add_option_function<std::vector<std::string>>(
            flag,
            [&values, &table, flag](const std::vector<std::string>& names) {
                values.clear();
                for (const std::string& n : names) values.push_back(session::parseName(table, n, flag));
            },
            help)
        ->delimiter(',')
        ->default_str(CLI::detail::to_string(shown))
        ->check(CLI::IsMember(methods::names(table)));
}

CLI::App* addBenchCommand(CLI::App& app, app::BenchCommand& bench) {
    bench::BenchOptions& b = bench.suite;
    CLI::App* benchCmd = app.add_subcommand("bench", "Print ms/frame per stage, static and dynamic case");
    benchCmd->add_option("--csv", b.csv, "Also write the table as CSV to this file");
    benchCmd->add_option("--frames", b.frames, "Timed frames per row")->check(CLI::Range(1, 10000));
    benchCmd->add_flag("--quick", bench.quick, "A small subset of rows (smoke test)");
    addNameList(*benchCmd, "--methods", b.methods, methods::kMethodNames, "Methods to time");
    benchCmd->add_option("--triangles", b.triangles, "Sphere mesh sizes (triangles)")->delimiter(',')
        ->capture_default_str()->check(CLI::Range(8L, 20'000'000L));
    {
        std::vector<std::string> sizes;
        for (const core::Viewport& v : b.imageSizes) sizes.push_back(std::to_string(v.width) + "x" + std::to_string(v.height));
        benchCmd->add_option_function<std::vector<std::string>>("--sizes", [&b](const std::vector<std::string>& given) {
            b.imageSizes.clear();
            for (const std::string& s : given) b.imageSizes.push_back(session::parseSize(s, "--sizes"));
        }, "Image sizes WxH")->delimiter(',')->default_str(CLI::detail::to_string(sizes));
    }
    benchCmd->add_option("--grids", b.gridRes, "ISA advection mesh resolutions")->delimiter(',')
        ->capture_default_str()->check(CLI::Range(64, 1024));
    benchCmd->add_flag("--dynamic-only", b.dynamicOnly, "Only the dynamic case (the cost while animating)");
    benchCmd->add_option_function<std::string>("--camera", [&b](const std::string& name) {
        b.camera = session::parseName(bench::kBenchCameraNames, name, "--camera");
    }, "Camera placement: fit, or paraview (ParaView's ResetCamera framing)")
        ->default_str(std::string(methods::nameOf(bench::kBenchCameraNames, b.camera)))
        ->check(CLI::IsMember(methods::names(bench::kBenchCameraNames)));
    benchCmd->add_option("--lengths", b.filterLengths, "Hybrid filter lengths L")->delimiter(',')
        ->capture_default_str()->check(CLI::Range(1, 1001));
    addNameList(*benchCmd, "--gl-paths", b.glPaths, methods::kGlPathNames, "Per-pixel passes as compute or fragment "
                "shaders: each path listed, one gl_path column (auto: the renderer's)");
    addNameList(*benchCmd, "--surface-rasters", b.surfaceRasters, methods::kSurfaceRasterNames, "Who rasterises the "
                "surface: each listed, one raster column (auto: by renderer, its cores and triangles per pixel)");
    addNameList(*benchCmd, "--enhance-contrast", b.enhanceContrast, methods::kEnhanceContrastNames,
                "Contrast enhancement variants to time, each a row (off, texture, color, both)");
    benchCmd->add_option("--ranks", b.ranks, "Ranks rendering each row together, each count a row: above 1, that "
                                             "many threads with a GL context and a slab of the sphere each, as "
                                             "ParaView's ranks with memory for MPI (the slowest rank's times)")
        ->delimiter(',')->capture_default_str()->check(CLI::Range(1, 64));
    addNameList(*benchCmd, "--parallel", b.parallel, methods::kParallelModeNames,
                "The ranks' parallel modes, each a row (tiles, replicate)");
    benchCmd->add_flag_callback("--no-stage-times", [&b] { b.stageTimes = false; },
                                "Time whole frames only (skips the second, synchronised pass per stage)");
    benchCmd->add_flag("--calibration", b.calibration, "Also time a fixed GL frame no flowsurf change touches "
                                                       "(the machine's speed; scripts/bench-check.sh)");
    benchCmd->add_flag("--transfers", bench.transfers, "Only time host read-backs and uploads of full-image layers "
                                                        "at --sizes (what the tiled parallel mode adds per frame)");
    benchCmd->add_option("--slowdown", bench.slowdown, "METHOD:K renders each frame of METHOD K times (tests the "
                                                       "speed check, scripts/bench-check.sh)")
        ->group("");  // hidden: not a measurement
    return benchCmd;
}

// The config file (--config FILE: its options first, the command line's on top of them),
// then the command line; an exit code when the program is done (help, version, an error).
std::optional<int> parse(CLI::App& app, Commands& c, int argc, char** argv) {
    for (CLI::App* cmd : {c.renderCmd, c.compareCmd, c.viewCmd, c.qualityCmd, c.topologyCmd})
        cmd->add_option("--config", "JSON config (e.g. saved by the viewer); options given here override it")
            ->group("Output");
    try {
        if (auto config = app::findConfigArgument(argc, argv)) {
            app::applyConfigFile(*config, c.render);
            c.compare = c.render;
            c.view = c.render;
            c.quality = c.render;
            const std::string output = c.topology.output;
            c.topology = c.render;
            c.topology.output = output;
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
    return std::nullopt;
}

// Runs the subcommand given.
int run(Commands& c) {
    if (*c.renderCmd) return app::runRender(c.render, c.renderQuality);
    if (*c.infoCmd) return app::runInfo(c.infoPath, session::sourceOptions(c.infoRead));
    if (*c.topologyCmd) return app::runTopology(c.topology);
    if (*c.viewCmd) {
#ifdef FLOWSURF_HAVE_VIEWER
        const app::RenderOptions& view = c.view;
        if (view.input.empty()) throw ConfigError("view: an input file or builtin:NAME is required");
        const core::Viewport standard = app::RenderOptions{}.size;
        c.viewOpts.sizeGiven = c.viewCmd->count("--size") > 0 || view.size.width != standard.width ||
                               view.size.height != standard.height;
        return app::view::runView(view, c.viewOpts);
#else
        throw ConfigError("view: this flowsurf was built without the viewer (FLOWSURF_BUILD_VIEWER=OFF)");
#endif
    }
    if (*c.compareCmd) return app::runCompare(c.compare, c.compareMethods, c.compareQuality);
    if (*c.qualityCmd)
        return c.autoTune ? app::runAutoTune(c.quality, c.qualityMethods, c.qualityOut)
                          : app::runQuality(c.quality, c.qualityMethods, c.qualityOut);
    if (*c.benchCmd) return app::runBench(c.bench);
    return app::kOk;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"flowsurf — dense, animated flow textures on triangle-mesh surfaces (ISA, IBFVS [L]; hybrid LIC [W])", "flowsurf"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "flowsurf 0.1.0");

    Commands c;
    addRenderingCommands(app, c);
    addViewCommand(app, c);
    addInfoCommand(app, c);
    addTopologyCommand(app, c);
    c.benchCmd = addBenchCommand(app, c.bench);
    if (const std::optional<int> done = parse(app, c, argc, argv)) return *done;
    try {
        return run(c);
    } catch (const std::exception&) {
        return reportCurrentError();
    }
}
