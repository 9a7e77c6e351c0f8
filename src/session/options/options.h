// flowsurf — the options of `flowsurf render`, `compare` and `view` as one table of data
// (name, group, effect, front ends, help, kind, range, choices, how to set and read the
// value): the command line (CLI11, --help), config files, the viewer's panel and its event
// logs, flowsurf::Renderer and Python, ParaView and the manual read it. The rows are listed
// by group in rows_*.cpp.
// Also the parsers of the value syntaxes. Free of GL so unit tests cover it.
#pragma once

#include "core/camera.h"
#include "core/errors.h"
#include "params/dye_source.h"
#include "params/params.h"
#include "skeleton/skeleton.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace flowsurf::session {

// True when entry i of a name table names value i, E(0) .. E(N - 1) in order, each by a name
// of its own: with N the enum's count, a table one short (its last entry left {E(0), ""})
// or out of order fails the static_assert beside it.
template <typename E, size_t N>
constexpr bool namesEveryValue(const methods::EnumNames<E, N>& names) {
    for (size_t i = 0; i < N; ++i) {
        if (names[i].first != E(i)) return false;
        for (size_t j = 0; j < i; ++j)
            if (names[j].second == names[i].second) return false;
    }
    return true;
}

// --view: ParaView's camera buttons (look along that direction), iso, or the default view
// (front, a little above and to the right; its name is empty).
enum class ViewPreset { Default, PlusX, MinusX, PlusY, MinusY, PlusZ, MinusZ, Iso };
inline constexpr size_t kViewPresets = size_t(ViewPreset::Iso) + 1;  // the last one + 1
inline constexpr methods::EnumNames<ViewPreset, kViewPresets> kViewPresetNames{{{ViewPreset::Default, ""},
                                                                    {ViewPreset::PlusX, "+x"},
                                                                    {ViewPreset::MinusX, "-x"},
                                                                    {ViewPreset::PlusY, "+y"},
                                                                    {ViewPreset::MinusY, "-y"},
                                                                    {ViewPreset::PlusZ, "+z"},
                                                                    {ViewPreset::MinusZ, "-z"},
                                                                    {ViewPreset::Iso, "iso"}}};
static_assert(namesEveryValue(kViewPresetNames));

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
    ViewPreset view = ViewPreset::Default;  // --view +x|-x|+y|-y|+z|-z|iso
    int upAxis = 1;                     // --up-axis x|y|z: 0, 1, 2
    float curvatureRadius = 0.0f;       // --curvature-radius: smoothing of curvature tensors (0: 1-ring)
    // --reverse-field auto|on|off: show the field reversed (the texture, the topology, the
    // dye); auto: reversed where it is OpenFOAM's wallShearStress (see fieldShownReversed).
    std::string reverseField = "auto";
    // The flow topology: drawn over the texture with --topology on, written by `flowsurf topology`.
    bool topology = false;
    std::string topologyParts = "points,lines";  // --topology-parts points,lines | points | lines
    skeleton::SkeletonParams topologyParams;     // --topology-scale, -cancel-speed, -line-strength, -line-length
    float topologyGlyphSize = 11.0f;             // px, 4..64
    float topologyLineWidth = 2.5f;              // px, 1..16
    std::string patches;                // --patches REGEX: OpenFOAM boundary patches to read
    std::string foamCase = "auto";      // --foam-case auto|reconstructed|decomposed
    bool foamZeroTime = false;          // --foam-zero-time: 0/ a step also when solved times exist
    double viscosity = 0.0;             // --viscosity: kinematic m²/s for --field skin-friction (0: the case's own)
    // Dye [doc/algorithms.md §10]: sources (--dye, repeatable) and those of --dye-file, each emitting from
    // its start frame for --dye-release frames (0: continuously) unless its stop frame says.
    std::vector<methods::DyeSource> dye;
    int dyeRelease = 0;
    float dyeDecay = 0.0f;              // per data time unit
    std::string dyeFile;
    std::vector<methods::DyeSource> dyeFileSources;  // read from dyeFile
    methods::MethodParams params;
};

// --reverse-field's rule: on, off, or auto, which reverses OpenFOAM's `wallShearStress`
// (the stress the wall exerts on the fluid, against the near-wall flow) so that the texture,
// the topology and the dye follow the flow. Stored arrays handed to users stay as stored.
bool fieldShownReversed(const RenderOptions& o, const std::string& field);

// What kind of value an option takes (the viewer picks its widget from this).
enum class OptionKind { Flag, Int, Float, Text, Choice, Size, Vec3, Color, Path };
inline constexpr size_t kOptionKinds = size_t(OptionKind::Path) + 1;  // the last one + 1

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
inline constexpr size_t kOptionEffects = size_t(OptionEffect::Reload) + 1;  // the last one + 1
inline constexpr methods::EnumNames<OptionEffect, kOptionEffects> kOptionEffectNames{{{OptionEffect::None, "none"},
                                                                         {OptionEffect::Output, "output-only"},
                                                                         {OptionEffect::Camera, "camera"},
                                                                         {OptionEffect::Rebuild, "rebuild"},
                                                                         {OptionEffect::Reload, "reload"}}};
static_assert(namesEveryValue(kOptionEffectNames));

// The section an option is listed in: --help, the manual's option reference, the viewer's
// panel and the Python/C++ option descriptions.
enum class OptionGroup { Data, Output, Method, Overlay, Dye, Camera };
inline constexpr size_t kOptionGroups = size_t(OptionGroup::Camera) + 1;  // the last one + 1
inline constexpr methods::EnumNames<OptionGroup, kOptionGroups> kOptionGroupNames{{{OptionGroup::Data, "Data"},
                                                                       {OptionGroup::Output, "Output"},
                                                                       {OptionGroup::Method, "Method"},
                                                                       {OptionGroup::Overlay, "Overlay"},
                                                                       {OptionGroup::Dye, "Dye"},
                                                                       {OptionGroup::Camera, "Camera"}}};
static_assert(namesEveryValue(kOptionGroupNames));
std::string groupName(OptionGroup group);

// The front ends that take an option, a set of bits. Every option is also a `set NAME VALUE`
// event of the viewer's logs.
enum class FrontEnd : unsigned {
    CommandLine = 1u << 0,  // --name VALUE of render, compare, quality and view
    Positional = 1u << 1,   // the command line's positional argument instead (the input)
    Config = 1u << 2,       // a key of config files and of the viewer's saved state
    Panel = 1u << 3,        // a widget of the viewer's panel made from the row's kind
    PanelOwn = 1u << 4,     // in the viewer's panel by a widget of its own (method buttons, dye list)
    Renderer = 1u << 5,     // flowsurf::Renderer::set, Python Renderer/render keywords
    Read = 1u << 6,         // Surface::read, flowsurf.read keywords, `flowsurf info`
    ParaView = 1u << 7,     // a property of the ParaView representation (see paraviewProperty)
};
constexpr FrontEnd operator|(FrontEnd a, FrontEnd b) { return FrontEnd(unsigned(a) | unsigned(b)); }

// A set of methods, a bit 1 << Method each.
struct MethodSet {
    unsigned bits = 0;
    constexpr bool has(methods::Method m) const { return ((bits >> unsigned(m)) & 1u) != 0; }
};
// Every method of methods::kMethodNames.
inline constexpr MethodSet kEveryMethod = [] {
    MethodSet all;
    for (const auto& [m, name] : methods::kMethodNames) all.bits |= 1u << unsigned(m);
    return all;
}();

// What a row is besides its value, declared in the row: its section, what a change means
// after the start (the viewer, flowsurf::Renderer, ParaView), the front ends that take it
// and the methods whose images it changes (the panel hides the others' rows; Jupyter's
// sliders and auto-tune's grid take each method's).
struct OptionRole {
    OptionGroup group = OptionGroup::Data;
    OptionEffect effect = OptionEffect::Rebuild;
    FrontEnd frontEnds = FrontEnd::CommandLine;
    MethodSet methods = kEveryMethod;

    // This role for `only` of the methods.
    constexpr OptionRole onlyFor(std::initializer_list<methods::Method> only) const {
        OptionRole r = *this;
        r.methods.bits = 0;
        for (methods::Method m : only) r.methods.bits |= 1u << unsigned(m);
        return r;
    }
};

// The rescale buttons the viewer's panel offers for a range option (robust | data | auto |
// MIN:MAX) [docs/cfd.md, colour ranges].
enum class RangeRescale {
    None,         // not a range option
    Data,         // "robust" and "data": the data's bulk or whole range
    DataAndView,  // also "visible": the range of the values the view shows, resolved by the viewer
};

// One row of the table. Every member has a default so that rows can name only theirs.
struct OptionSpec {
    std::string name = {};                 // long name without dashes: CLI --name, config key, event `set name`
    std::string shortName = {};            // one letter (-m) or empty
    OptionRole role = {};
    std::string help = {};                 // one line; the default is appended from RenderOptions{}
    OptionKind kind = OptionKind::Text;
    double min = 0.0, max = 0.0;           // numeric range, inclusive (Int, Float, Size, Color)
    std::vector<std::string> choices = {}; // Choice
    // Parses and checks `text` and stores it; throws ConfigError naming the option.
    std::function<void(RenderOptions&, const std::string&)> set = {};
    // The value as text that set() reads back exactly; empty when unset (e.g. camera
    // "fit the bounds").
    std::function<std::string(const RenderOptions&)> get = {};
    // Given several times on the command line: the values joined by ';' are set at once.
    bool repeatable = false;
    // Config files: the numbers of a JSON array joined by this into the option's text
    // ([800, 600]: "800x600").
    std::string arraySeparator = ",";
    RangeRescale rescale = RangeRescale::None;

    bool takes(FrontEnd f) const { return (unsigned(role.frontEnds) & unsigned(f)) != 0; }
    bool appliesTo(methods::Method m) const { return role.methods.has(m); }
};

// Every option of render/compare/view, in --help order.
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

// The ParaView representation's property of an option that ParaView takes: "FlowSurf" + the
// name in CamelCase (--filter-length: FlowSurfFilterLength); empty for the others.
std::string paraviewProperty(const OptionSpec& spec);

// Checks ranges and combinations after parsing; throws ConfigError naming the option.
void validateRenderOptions(const RenderOptions& opt);

// Value syntaxes (throw ConfigError naming `what`):
float parseFloat(const std::string& text, const std::string& what);
double parseNumber(const std::string& text, const std::string& what);
core::Viewport parseSize(const std::string& text, const std::string& what = "--size");
glm::vec3 parseVec3(const std::string& text, const std::string& what);
glm::vec3 parseColor(const std::string& text, const std::string& what = "--background");

// A name of `names` as its value: the one parse of an enum's text, for the option rows and
// the lists outside the table (--methods, bench's lists); ConfigError naming `what` and
// the names it takes.
template <typename E, size_t N>
E parseName(const methods::EnumNames<E, N>& names, std::string_view text, const std::string& what) {
    E value{};
    if (!methods::valueOf(names, text, &value))
        throw ConfigError(what + ": '" + std::string(text) + "' is not one of " + methods::nameList(names));
    return value;
}
// Method names separated by commas (isa,hybrid), empty items skipped: compare's and bench's
// --methods, the viewer's --compare. ConfigError naming `what` for a name it does not know.
std::vector<methods::Method> parseMethodList(const std::string& text, const std::string& what);

// Numbers as text that parse back to the same value.
std::string formatFloat(float value);
std::string formatDouble(double value);

// Output kind from the file name: .png (final frame), .mp4 (all frames), %d pattern.
enum class OutputKind { Png, Mp4, PngSequence };
OutputKind outputKind(const std::string& path);

}  // namespace flowsurf::session
