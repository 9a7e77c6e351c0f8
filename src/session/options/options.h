// flowsurf — the options of `flowsurf render`, `compare` and `view` as one table of data
// (name, group, help, kind, range, choices, how to set and read the value): the command
// line (CLI11, --help), config files, the viewer's panel and its event logs all use it.
// Also the parsers of the value syntaxes. Free of GL so unit tests cover it.
#pragma once

#include "core/camera.h"
#include "methods/common/dye_source.h"
#include "methods/common/params.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace flowsurf::session {

struct RenderOptions {
    std::string input;                  // file or builtin:NAME
    methods::Method method = methods::Method::Isa;
    std::string field;                  // empty: first 3-component point array
    core::Viewport size{800, 600};      // --size WxH
    int frames = 90;                    // advection frames before the output frame
    std::string output = "flowsurf.png";
    std::string flowTexture;            // --flow-texture FILE.png (16-bit gray F_a)
    // Camera; unset means "fit the bounds".
    std::optional<glm::vec3> eye, target, up;
    float fov = 30.0f;
    float ortho = 0.0f;                 // > 0: orthographic view height
    float orbit = 0.0f;                 // degrees per frame about the up axis
    std::string cameraPath;             // --camera-path FILE (JSON keyframes)
    size_t timeStep = 0;                // --time-step: render this one step, steady
    bool timeStepGiven = false;
    std::optional<std::pair<double, double>> timeRange;  // --time START:END (data time)
    double timePerFrame = 0.0;          // --time-per-frame DT (0: see framesPerStep)
    int framesPerStep = 0;              // --frames-per-step N (0: the range over --frames)
    std::optional<double> traceDt;      // --trace-dt: hybrid data time per particle step
    int fps = 30;
    int crf = 18;
    bool quiet = false;
    bool verbose = false;
    bool listBuiltins = false;
    // Frames advected before the first written frame of an MP4 or PNG sequence (and the
    // viewer's start); -1: enough to look converged (3 / alpha for ISA/IBFVS, 0 hybrid).
    int warmup = -1;
    std::string view;                   // --view +x|-x|+y|-y|+z|-z|iso (empty: the default view)
    int upAxis = 1;                     // --up-axis x|y|z: 0, 1, 2
    float curvatureRadius = 0.0f;       // --curvature-radius: smoothing of curvature tensors (0: 1-ring)
    std::string patches;                // --patches REGEX: OpenFOAM boundary patches to read
    std::string foamCase = "auto";      // --foam-case auto|reconstructed|decomposed
    // Dye [issue 20]: sources (--dye, repeatable) and those of --dye-file, each emitting from
    // its start frame for --dye-release frames (0: continuously) unless its stop frame says.
    std::vector<methods::DyeSource> dye;
    int dyeRelease = 0;
    float dyeDecay = 0.0f;              // per data time unit
    std::string dyeFile;
    std::vector<methods::DyeSource> dyeFileSources;  // read from dyeFile
    methods::MethodParams params;
};

// What kind of value an option takes (the viewer picks its widget from this).
enum class OptionKind { Flag, Int, Float, Text, Choice, Size, Vec3, Color, Path };

// What changing an option means for a running session (session::Playback::set and every
// front end that changes options after the start: the viewer, flowsurf::Renderer, ParaView).
// Ordered: a change of several options needs the largest.
enum class OptionEffect {
    None,     // messages only (quiet, verbose)
    Output,   // what a front end writes from the frames (file names, MP4 settings): no new frame
    Camera,   // the camera of each frame: new cameras from the next frame; textures and clock go on
    Rebuild,  // new surface upload and renderers: the clock restarts, with the warm-up again
    Reload,   // what is read from the input (file, field, patches): open it again, then rebuild
};
inline constexpr methods::EnumNames<OptionEffect, 5> kOptionEffectNames{{{OptionEffect::None, "none"},
                                                                         {OptionEffect::Output, "output-only"},
                                                                         {OptionEffect::Camera, "camera"},
                                                                         {OptionEffect::Rebuild, "rebuild"},
                                                                         {OptionEffect::Reload, "reload"}}};

struct OptionSpec {
    std::string name;                 // long name without dashes: CLI --name, config key, event `set name`
    std::string shortName;            // one letter (-m) or empty
    std::string group;                // Output, Data, Method, Overlay, Camera
    std::string help;                 // one line; the default is appended from RenderOptions{}
    OptionKind kind = OptionKind::Text;
    double min = 0.0, max = 0.0;      // numeric range, inclusive (Int, Float)
    std::vector<std::string> choices; // Choice
    bool saved = true;                // part of a saved view state (config files)
    // Parses and checks `text` and stores it; throws ConfigError naming the option.
    std::function<void(RenderOptions&, const std::string&)> set;
    // The value as text that set() reads back exactly; empty when unset (e.g. camera
    // "fit the bounds").
    std::function<std::string(const RenderOptions&)> get;
    OptionEffect effect = OptionEffect::Rebuild;  // what a change means after the start
    // Given several times on the command line: the values joined by ';' are set at once.
    bool repeatable = false;
};

// Every option of render/compare/view, in --help order. The positional input is "input".
const std::vector<OptionSpec>& renderOptionTable();
// The option named `name` (long name without dashes), or null.
const OptionSpec* findOption(const std::string& name);
// Sets option `name` from text; throws ConfigError for an unknown name or a bad value.
void setOption(RenderOptions& o, const std::string& name, const std::string& value);
// The default of an option as text (from RenderOptions{}): empty when it has none.
std::string defaultText(const OptionSpec& spec);
// The effect of option `name`; throws ConfigError for an unknown name.
OptionEffect effectOf(const std::string& name);
// The largest effect among the options whose values differ between `a` and `b`.
OptionEffect changeEffect(const RenderOptions& a, const RenderOptions& b);

// Where an option is set besides the command line (render, compare, quality, view), the
// viewer's `set NAME VALUE` events and, when `saved`, config files. The front ends choose
// their options with these, and the manual's option reference lists them from the same.
bool isRendererOption(const OptionSpec& spec);  // flowsurf::Renderer::set, Python Renderer/render keywords
bool isReadOption(const OptionSpec& spec);      // Surface::read, flowsurf.read keywords, `flowsurf info`
bool inViewerPanel(const OptionSpec& spec);     // a widget of the viewer's panel
// The ParaView representation's property ("FlowSurf" + the name in CamelCase), empty when
// ParaView has its own (colormap, lighting, background) or none.
std::string paraviewProperty(const OptionSpec& spec);

// Checks ranges and combinations after parsing; throws ConfigError naming the option.
void validateRenderOptions(const RenderOptions& opt);

// Value syntaxes (throw ConfigError naming `what`):
float parseFloat(const std::string& text, const std::string& what);
double parseNumber(const std::string& text, const std::string& what);
core::Viewport parseSize(const std::string& text, const std::string& what = "--size");
glm::vec3 parseVec3(const std::string& text, const std::string& what);
glm::vec3 parseColor(const std::string& text, const std::string& what = "--background");

// Numbers as text that parse back to the same value.
std::string formatFloat(float value);
std::string formatDouble(double value);

// Output kind from the file name: .png (final frame), .mp4 (all frames), %d pattern.
enum class OutputKind { Png, Mp4, PngSequence };
OutputKind outputKind(const std::string& path);

}  // namespace flowsurf::session
