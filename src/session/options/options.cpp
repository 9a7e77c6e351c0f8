// flowsurf — the option table: one row per option of render, compare and view (name,
// group, help, kind, range, choices, set/get), built from small row builders.
#include "session/options/options.h"

#include "core/errors.h"
#include "methods/common/gl_path.h"
#include "session/options/colormap_file.h"
#include "session/options/dye_sources.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <type_traits>

namespace flowsurf::session {
namespace {

// --- builders of table rows ------------------------------------------------------------

std::string dashed(const std::string& name) { return "--" + name; }


template <typename T>
std::string numberText(T v) {
    if constexpr (std::is_integral_v<T>) return std::to_string(v);
    else if constexpr (std::is_same_v<T, float>) return formatFloat(v);
    else return formatDouble(v);
}

// Checks range and integrality of a parsed number for option `name`.
template <typename T>
T checkedNumber(const std::string& name, const std::string& t, double lo, double hi) {
    double v = parseNumber(t, dashed(name));
    if (std::is_integral_v<T> && v != std::floor(v)) throw ConfigError(dashed(name) + ": '" + t + "' is not an integer");
    if (v < lo || v > hi)
        throw ConfigError(dashed(name) + ": " + t + " is out of range " + formatDouble(lo) + ".." + formatDouble(hi));
    return T(v);
}

// "on llvmpipe when triangles >= 0.5 x pixels, on H100 when ..." from the auto rule itself.
std::string computeRasterRuleText() {
    std::string text;
    for (const methods::ComputeRasterRule& rule : methods::kComputeRasterRule)
        text += std::string(text.empty() ? "on " : ", on ") + std::string(rule.renderer) + " when triangles >= " +
                formatDouble(rule.trianglesPerPixel) + " x pixels";
    return text;
}

std::string vec3Text(const glm::vec3& v) {
    return formatFloat(v.x) + "," + formatFloat(v.y) + "," + formatFloat(v.z);
}

template <typename T>
OptionSpec number(std::string name, std::string group, std::string help, T RenderOptions::*field, double lo,
                  double hi) {
    OptionSpec s{std::move(name), "", std::move(group), std::move(help),
                 std::is_integral_v<T> ? OptionKind::Int : OptionKind::Float, lo, hi, {}, true, nullptr, nullptr};
    const std::string n = s.name;
    s.set = [n, field, lo, hi](RenderOptions& o, const std::string& t) { o.*field = checkedNumber<T>(n, t, lo, hi); };
    s.get = [field](const RenderOptions& o) { return numberText(o.*field); };
    return s;
}

// A number inside MethodParams, reached through `ref`.
template <typename T, typename Ref>
OptionSpec param(std::string name, std::string group, std::string help, Ref ref, double lo, double hi) {
    OptionSpec s{std::move(name), "", std::move(group), std::move(help),
                 std::is_integral_v<T> ? OptionKind::Int : OptionKind::Float, lo, hi, {}, true, nullptr, nullptr};
    const std::string n = s.name;
    s.set = [n, ref, lo, hi](RenderOptions& o, const std::string& t) { ref(o) = checkedNumber<T>(n, t, lo, hi); };
    s.get = [ref](const RenderOptions& o) { return numberText(ref(const_cast<RenderOptions&>(o))); };
    return s;
}

template <typename E, size_t N, typename Ref>
OptionSpec choice(std::string name, std::string group, std::string help, const methods::EnumNames<E, N>& names,
                  Ref ref) {
    OptionSpec s{std::move(name), "", std::move(group), std::move(help), OptionKind::Choice, 0, 0, {}, true,
                 nullptr, nullptr};
    for (const auto& [value, text] : names) s.choices.emplace_back(text);
    const std::string n = s.name;
    s.set = [n, &names, ref](RenderOptions& o, const std::string& t) {
        for (const auto& [value, text] : names)
            if (t == text) {
                ref(o) = value;
                return;
            }
        throw ConfigError(dashed(n) + ": '" + t + "' is not one of " + methods::nameList(names));
    };
    s.get = [&names, ref](const RenderOptions& o) {
        for (const auto& [value, text] : names)
            if (ref(const_cast<RenderOptions&>(o)) == value) return std::string(text);
        return std::string();
    };
    return s;
}

// A text option restricted to `choices` (kept as text in RenderOptions); the list the
// panel, --help and ParaView show is the list it checks against.
template <typename Ref>
OptionSpec textChoice(std::string name, std::string group, std::string help, std::vector<std::string> choices,
                      Ref ref) {
    OptionSpec s{std::move(name), "", std::move(group), std::move(help), OptionKind::Choice, 0, 0,
                 std::move(choices), true, nullptr, nullptr};
    const std::string n = s.name;
    s.set = [n, allowed = s.choices, ref](RenderOptions& o, const std::string& t) {
        if (std::find(allowed.begin(), allowed.end(), t) == allowed.end()) {
            std::string list;
            for (const auto& c : allowed)
                if (!c.empty()) list += (list.empty() ? "" : ", ") + c;
            throw ConfigError(dashed(n) + ": '" + t + "' is not one of " + list);
        }
        ref(o) = t;
    };
    s.get = [ref](const RenderOptions& o) { return std::string(ref(const_cast<RenderOptions&>(o))); };
    return s;
}

// on|off switches kept as choices for the command line's compatibility.
template <typename Ref>
OptionSpec onOff(std::string name, std::string group, std::string help, Ref ref) {
    OptionSpec s{std::move(name), "", std::move(group), std::move(help), OptionKind::Choice, 0, 0, {"on", "off"},
                 true, nullptr, nullptr};
    const std::string n = s.name;
    s.set = [n, ref](RenderOptions& o, const std::string& t) {
        if (t != "on" && t != "off") throw ConfigError(dashed(n) + ": '" + t + "' is not one of on, off");
        ref(o) = t == "on";
    };
    s.get = [ref](const RenderOptions& o) { return std::string(ref(const_cast<RenderOptions&>(o)) ? "on" : "off"); };
    return s;
}

template <typename Ref>
OptionSpec flag(std::string name, std::string group, std::string help, Ref ref, bool saved = true) {
    OptionSpec s{std::move(name), "", std::move(group), std::move(help), OptionKind::Flag, 0, 0, {}, saved,
                 nullptr, nullptr};
    const std::string n = s.name;
    s.set = [n, ref](RenderOptions& o, const std::string& t) {
        std::string l = t;
        std::transform(l.begin(), l.end(), l.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (l == "true" || l == "1" || l == "on" || l.empty()) ref(o) = true;
        else if (l == "false" || l == "0" || l == "off") ref(o) = false;
        else throw ConfigError(dashed(n) + ": '" + t + "' is not true or false");
    };
    s.get = [ref](const RenderOptions& o) { return std::string(ref(const_cast<RenderOptions&>(o)) ? "true" : "false"); };
    return s;
}

template <typename Ref>
OptionSpec text(std::string name, std::string group, std::string help, Ref ref, OptionKind kind = OptionKind::Text) {
    OptionSpec s{std::move(name), "", std::move(group), std::move(help), kind, 0, 0, {}, true, nullptr, nullptr};
    s.set = [ref](RenderOptions& o, const std::string& t) { ref(o) = t; };
    s.get = [ref](const RenderOptions& o) { return ref(const_cast<RenderOptions&>(o)); };
    return s;
}

// ARRAY or ARRAY:x|y|z|mag, checked for its syntax when set (empty: none).
template <typename Ref>
OptionSpec scalarSpec(std::string name, std::string group, std::string help, Ref ref) {
    OptionSpec s = text(std::move(name), std::move(group), std::move(help), ref);
    s.set = [ref](RenderOptions& o, const std::string& v) {
        if (!v.empty()) core::ScalarSpec::parse(v);
        ref(o) = v;
    };
    return s;
}

// An optional x,y,z (unset: fitted to the bounds).
OptionSpec vec3(std::string name, std::string help, std::optional<glm::vec3> RenderOptions::*field) {
    OptionSpec s{std::move(name), "", "Camera", std::move(help), OptionKind::Vec3, 0, 0, {}, true, nullptr, nullptr};
    const std::string n = s.name;
    s.set = [n, field](RenderOptions& o, const std::string& t) {
        if (t.empty()) o.*field = std::nullopt;
        else o.*field = parseVec3(t, dashed(n));
    };
    s.get = [field](const RenderOptions& o) { return o.*field ? vec3Text(*(o.*field)) : std::string(); };
    return s;
}

// MIN:MAX with MIN < MAX.
glm::vec2 parseRange(const std::string& v, const std::string& what) {
    auto colon = v.find(':', v[0] == '-' ? 1 : 0);
    while (colon != std::string::npos && colon > 0 && (v[colon - 1] == 'e' || v[colon - 1] == 'E'))
        colon = v.find(':', colon + 1);
    if (colon == std::string::npos) throw ConfigError(what + ": '" + v + "' is not MIN:MAX");
    const glm::vec2 r(parseFloat(v.substr(0, colon), what), parseFloat(v.substr(colon + 1), what));
    if (!(r.x < r.y)) throw ConfigError(what + ": '" + v + "': MIN must be less than MAX");
    return r;
}

// A range option [issue 28]: robust | data | auto | MIN:MAX, kept as a given range (lo > hi
// when unset), the auto flag (each frame's data range) and the mode of the whole-data range.
template <typename Range, typename Auto, typename Mode>
OptionSpec rangeOption(std::string name, std::string group, std::string help, Range range, Auto automatic, Mode mode) {
    OptionSpec s{std::move(name), "", std::move(group), std::move(help), OptionKind::Text, 0, 0, {}, true, nullptr,
                 nullptr};
    const std::string what = dashed(s.name);
    s.set = [what, range, automatic, mode](RenderOptions& o, const std::string& v) {
        const bool given = !v.empty() && v != "robust" && v != "data" && v != "auto";
        range(o) = given ? parseRange(v, what) : glm::vec2(1, 0);
        automatic(o) = v == "auto";
        mode(o) = v == "data" ? methods::RangeMode::Data : methods::RangeMode::Robust;
    };
    s.get = [range, automatic, mode](const RenderOptions& o) {
        RenderOptions& m = const_cast<RenderOptions&>(o);
        const glm::vec2 r = range(m);
        if (automatic(m)) return std::string("auto");
        if (r.x <= r.y) return formatFloat(r.x) + ":" + formatFloat(r.y);
        return std::string(mode(m) == methods::RangeMode::Data ? "data" : "robust");
    };
    return s;
}

#define FS_REF(expr) [](RenderOptions& o) -> auto& { return o.expr; }

std::vector<OptionSpec> buildTable() {
    std::vector<OptionSpec> t;
    // Each group's effect; the rows that differ say so after their add().
    auto add = [&t](OptionSpec s, std::string shortName = "") {
        s.shortName = std::move(shortName);
        s.effect = s.group == "Camera" ? OptionEffect::Camera : OptionEffect::Rebuild;
        t.push_back(std::move(s));
    };
    auto effect = [&t](OptionEffect e) { t.back().effect = e; };
    add(text("input", "Data", "Surface file (.vtp .vtu .vtk .ply .obj .stl .foam .e .case .pvd), a file series "
                              "(surf_%04d.vtp, surf_*.vtp) or builtin:NAME", FS_REF(input), OptionKind::Path));
    effect(OptionEffect::Reload);

    // Output
    const std::string gOut = "Output";
    add(text("output", gOut, "FILE.png (final composite), FILE.mp4 (all frames) or frame_%04d.png", FS_REF(output),
             OptionKind::Path), "o");
    effect(OptionEffect::Output);
    {
        OptionSpec s{"size", "", gOut, "Image size WxH in pixels", OptionKind::Size, core::kMinImageSide, core::kMaxImageSide, {},
                     true, nullptr, nullptr};
        s.set = [](RenderOptions& o, const std::string& v) { o.size = parseSize(v); };
        s.get = [](const RenderOptions& o) { return std::to_string(o.size.width) + "x" + std::to_string(o.size.height); };
        add(s);
    }
    add(number("frames", gOut, "PNG: advection frames before the output frame; MP4 or PNG sequence: frames "
               "written", &RenderOptions::frames, 0, 100000));
    add(text("flow-texture", gOut, "Also write the advected texture F_a alone (16-bit gray PNG)", FS_REF(flowTexture),
             OptionKind::Path));
    effect(OptionEffect::Output);
    t.back().saved = false;
    add(number("warmup", gOut, "Frames advected before the first written frame of an MP4 or PNG sequence and the "
               "viewer's start (-1: enough to look converged, 3/alpha for ISA and IBFVS, 0 for the hybrid)",
               &RenderOptions::warmup, -1, 100000));
    add(number("fps", gOut, "MP4 frame rate", &RenderOptions::fps, 1, 240));
    effect(OptionEffect::Output);
    add(number("crf", gOut, "MP4 H.264 quality, 0 = lossless", &RenderOptions::crf, 0, 51));
    effect(OptionEffect::Output);
    add(flag("quiet", gOut, "No progress bar or messages", FS_REF(quiet), false), "q");
    effect(OptionEffect::None);
    add(flag("verbose", gOut, "Log the OpenGL renderer and timings", FS_REF(verbose), false), "v");
    effect(OptionEffect::None);

    // Data
    const std::string gData = "Data";
    add(text("field", gData, "Vector array to show (default: the first 3-component point array that is not zero "
                             "everywhere in the series), or a derived field: curvature-max, curvature-min, "
                             "gradient:ARRAY, down:x,y,z", FS_REF(field)));
    effect(OptionEffect::Reload);
    add(number("curvature-radius", gData, "Derived curvature fields: average the curvature tensor over this "
               "radius (object units; 0: one-ring estimate only)", &RenderOptions::curvatureRadius, 0, 1e30));
    add(text("patches", gData, "OpenFOAM: read the boundary patches whose names match this regular expression "
                               "(default: all)", FS_REF(patches)));
    effect(OptionEffect::Reload);
    add(textChoice("foam-case", gData, "OpenFOAM: read the reconstructed case or the processor* directories "
                   "of a decomposed one (auto: the decomposed one when it has more time directories or the case "
                   "folder has no mesh)", {"auto", "reconstructed", "decomposed"}, FS_REF(foamCase)));
    effect(OptionEffect::Reload);
    {
        OptionSpec s{"time-step", "", gData, "Render only this time step (index), as steady data", OptionKind::Int, 0,
                     1e9, {}, true, nullptr, nullptr};
        s.set = [](RenderOptions& o, const std::string& v) {
            if (v.empty()) { o.timeStepGiven = false; o.timeStep = 0; return; }
            double d = parseNumber(v, "--time-step");
            if (d < 0 || d > 1e9 || d != std::floor(d)) throw ConfigError("--time-step: '" + v + "' is not a step index");
            o.timeStep = size_t(d);
            o.timeStepGiven = true;
        };
        s.get = [](const RenderOptions& o) { return o.timeStepGiven ? std::to_string(o.timeStep) : std::string(); };
        add(s);
    }
    {
        OptionSpec s{"time", "", gData, "Data time range START:END of the animation (default: the whole series)",
                     OptionKind::Text, 0, 0, {}, true, nullptr, nullptr};
        s.set = [](RenderOptions& o, const std::string& v) {
            if (v.empty()) { o.timeRange.reset(); return; }
            auto colon = v.find(':');
            if (colon == std::string::npos) throw ConfigError("--time: '" + v + "' is not START:END");
            o.timeRange = std::make_pair(parseNumber(v.substr(0, colon), "--time"),
                                         parseNumber(v.substr(colon + 1), "--time"));
        };
        s.get = [](const RenderOptions& o) {
            return o.timeRange ? formatDouble(o.timeRange->first) + ":" + formatDouble(o.timeRange->second) : std::string();
        };
        add(s);
    }
    add(number("time-per-frame", gData, "Data time per animation frame (0: see --frames-per-step)",
               &RenderOptions::timePerFrame, 0, 1e30));
    add(number("frames-per-step", gData, "Animation frames per data time step (0: the range over --frames)",
               &RenderOptions::framesPerStep, 0, 100000));
    {
        OptionSpec s{"trace-dt", "", gData, "Hybrid on a time series: data time per particle step, so the LIC follows "
                     "pathlines (default: the data time per frame; 0: streamlines of each frame's field)",
                     OptionKind::Float, 0, 1e30, {}, true, nullptr, nullptr};
        s.set = [](RenderOptions& o, const std::string& v) {
            if (v.empty()) { o.traceDt.reset(); return; }
            double d = parseNumber(v, "--trace-dt");
            if (d < 0) throw ConfigError("--trace-dt: " + v + " must not be negative");
            o.traceDt = d;
        };
        s.get = [](const RenderOptions& o) { return o.traceDt ? formatDouble(*o.traceDt) : std::string(); };
        add(s);
    }

    // Method
    const std::string gMethod = "Method";
    add(choice("method", gMethod, "Visualization method", methods::kMethodNames, FS_REF(method)), "m");
    add(param<float>("alpha", gMethod, "Noise blend alpha [L eq. 9] (papers: 0.1-0.2)", FS_REF(params.common.alpha), 0, 1));
    add(param<float>("beta", gMethod, "Texture strength beta [L eq. 10]", FS_REF(params.common.beta), 0, 1));
    add(param<float>("step-px", gMethod, "ISA/IBFVS: largest displacement per frame in pixels (dt)",
                     FS_REF(params.common.stepPx), 0, 64));
    add(param<float>("lic-step-px", gMethod, "Hybrid: arc length per particle integration step in pixels ([W] dt)",
                     FS_REF(params.hybrid.stepPx), 0.05, 64));
    add(param<float>("speed-percentile", gMethod, "Clamp advection speed at this percentile of the surface's speeds "
                     "(100: no clamp)", FS_REF(params.common.speedPercentile), 1, 100));
    add(onOff("normalize", gMethod, "on: unit-length vectors, uniform streaks; off: streak length shows speed",
              FS_REF(params.common.normalize)));
    add(param<float>("noise-scale", gMethod, "Noise cell size s in pixels (papers: 1-10)", FS_REF(params.common.noise.scale), 1, 64));
    add(param<float>("noise-period", gMethod, "Frames per cycle of each noise cell's profile",
                     FS_REF(params.common.noise.period), 2, 10000));
    add(choice("noise-profile", gMethod, "Periodic profile w of the noise", methods::kNoiseProfileNames,
               FS_REF(params.common.noise.profile)));
    add(param<uint32_t>("seed", gMethod, "Noise seed", FS_REF(params.common.noise.seed), 0, 4294967295.0));
    add(param<int>("grid-res", gMethod, "ISA advection mesh resolution R (R x R cells)", FS_REF(params.isa.gridRes), 64, 1024));
    add(choice("isa-warp", gMethod, "ISA texture advection: pixel (mesh interpolated per pixel) or mesh (draw the "
               "R x R grid)", methods::kIsaWarpNames, FS_REF(params.isa.warp)));
    add(choice("resample", gMethod, "ISA/IBFVS: resampling of the advected texture each frame: bicubic "
               "(Catmull-Rom, clamped) or bilinear ([L])", methods::kResampleNames, FS_REF(params.common.resample)));
    add(choice("noise-injection", gMethod, "ISA/IBFVS: noise G sampled at the pixel (point, [L]) or averaged along "
               "its motion over the frame (swept)", methods::kNoiseInjectionNames, FS_REF(params.common.noiseInjection)));
    add(flag("cull-back-faces", gMethod, "Skip back-facing triangles (closed, outward-oriented surfaces only)",
             FS_REF(params.common.cullBackFaces)));
    add(choice("gl-path", gMethod, "Per-pixel passes as compute or fragment shaders (same images); auto picks "
               "per GL renderer", methods::kGlPathNames, FS_REF(params.common.glPath)));
    add(choice("surface-raster", gMethod, "Who rasterises the surface (ISA's velocity image, the hybrid's seeds): "
               "gl, or compute shaders (a visibility buffer; faster for many small triangles on a software "
               "renderer or on GPUs with few graphics units); auto picks compute " + computeRasterRuleText(),
               methods::kSurfaceRasterNames, FS_REF(params.common.surfaceRaster)));
    add(choice("parallel", gMethod, "Several processes on one view (ParaView under MPI): tiles (each runs the "
               "image stages on its own screen tile) or replicate (each runs them on the whole image); the same "
               "image", methods::kParallelModeNames, FS_REF(params.common.parallel)));
    add(flag("edge-mask", gMethod, "IBFVS silhouette edge mask over the image [L §IV-E.2]", FS_REF(params.ibfvs.edgeMask)));
    add(choice("on-camera-move", gMethod, "When the camera moves: translate (reproject the texture with the "
               "surface), freeze, none [L §IV-I]", methods::kCameraMoveNames, FS_REF(params.common.onCameraMove)));
    add(param<int>("filter-length", gMethod, "Hybrid LIC filter length L in samples ([W] 25-70)",
                   FS_REF(params.hybrid.filterLength), 1, 1001));
    add(choice("kernel", gMethod, "Hybrid LIC kernel", methods::kKernelNames, FS_REF(params.hybrid.kernel)));
    add(choice("integrator", gMethod, "Hybrid particle integrator (euler as in [W])", methods::kIntegratorNames,
               FS_REF(params.hybrid.integrator)));
    {
        OptionSpec s = param<int>("noise-size", gMethod, "Hybrid solid noise texels per side",
                                  FS_REF(params.hybrid.noiseSize), 64, 128);
        s.kind = OptionKind::Choice;
        s.choices = {"64", "128"};
        auto inner = s.set;
        s.set = [inner, choices = s.choices](RenderOptions& o, const std::string& v) {
            if (std::find(choices.begin(), choices.end(), v) == choices.end())
                throw ConfigError("--noise-size: '" + v + "' is not one of " + choices[0] + ", " + choices[1]);
            inner(o, v);
        };
        add(s);
    }
    add(param<float>("edge-epsilon", gMethod, "ISA edge detection eps [L eq. 14], depth range per pixel",
                     FS_REF(params.isa.edgeEpsilon), 0, 10));
    add(onOff("edge-blending", gMethod, "ISA edge blending [L §IV-E.1]", FS_REF(params.isa.edgeBlending)));
    add(choice("edge-fill", gMethod, "ISA edge blending puts at edge points: noise (eq. 9's history, streaks start "
               "at full contrast) or gray ([L])", methods::kEdgeFillNames, FS_REF(params.isa.edgeFill)));

    // Overlay
    const std::string gLook = "Overlay";
    add(choice("overlay", gLook, "blend (eq. 10: texture + colour map x lighting); or [W Fig. 6]: gray, gray-lit, "
               "hue-lit, coolwarm", methods::kOverlayNames, FS_REF(params.common.overlay)));
    add(choice("colormap", gLook, "Colour map",
               methods::kColormapNames, FS_REF(params.common.colormap)));
    {
        OptionSpec s{"colormap-file", "", gLook, "Colour map from a ParaView JSON preset file (RGBPoints); replaces "
                     "--colormap", OptionKind::Path, 0, 0, {}, true, nullptr, nullptr};
        s.set = [](RenderOptions& o, const std::string& v) {
            o.params.common.colormapFile = v;
            o.params.common.colormapTable = v.empty() ? std::vector<glm::vec3>{} : readParaViewColormap(v);
        };
        s.get = [](const RenderOptions& o) { return o.params.common.colormapFile; };
        add(s);
    }
    add(scalarSpec("color-by", gLook, "Colour by ARRAY (a point or cell scalar, or a vector's magnitude) or "
                    "ARRAY:x|y|z|mag (default: the shown field's speed)", FS_REF(params.common.colorBy)));
    add(rangeOption("color-range", gLook, "Values at the ends of the colour map: robust (the bulk of the data over "
                    "all time steps, outliers clamped: Tukey's fences on area-weighted quartiles), data (min:max over "
                    "all time steps), auto (each frame's min:max) or MIN:MAX", FS_REF(params.common.colorRange),
                    FS_REF(params.common.colorRangeAuto), FS_REF(params.common.colorRangeMode)));
    add(choice("color-scale", gLook, "Colour map scale: linear, or log (log10 of the values; the range must be "
               "positive)", methods::kColorScaleNames, FS_REF(params.common.colorScale)));
    add(flag("legend", gLook, "Draw a colour legend (scalar bar with title and ticks) into the image",
             FS_REF(params.common.legend)));
    add(text("title", gLook, "Legend title (default: the colour array's name)", FS_REF(params.common.title)));
    add(scalarSpec("mask-by", gLook, "Texture contrast follows this scalar (ARRAY or ARRAY:x|y|z|mag), as "
                    "--velocity-mask does speed ([L] Fig. 13)", FS_REF(params.common.maskBy)));
    add(rangeOption("mask-range", gLook, "Values of --mask-by at zero and full contrast: robust, data, auto or "
                    "MIN:MAX, as --color-range", FS_REF(params.common.maskRange), FS_REF(params.common.maskRangeAuto),
                    FS_REF(params.common.maskRangeMode)));
    add(onOff("lighting", gLook, "Diffuse lighting", FS_REF(params.common.lighting)));
    add(flag("velocity-mask", gLook, "Texture contrast follows speed [L ref 14]", FS_REF(params.common.velocityMask)));
    add(param<float>("contrast", gLook, "Display gain of the flow texture about its mean (not applied to a texture "
                     "--enhance-contrast stretches)", FS_REF(params.common.contrast), 0, 20));
    add(choice("enhance-contrast", gLook, "Contrast enhancement as ParaView's Surface LIC: stretch the flow "
               "texture's intensity (texture), the surface colour's lightness (color) or both between robust "
               "percentiles of the surface's pixels, smoothed over frames (see doc/contrast.md)",
               methods::kEnhanceContrastNames, FS_REF(params.common.enhanceContrast)));
    add(param<float>("enhance-percentile", gLook, "Contrast enhancement: percent of the surface's pixels clamped "
                     "at each end of the stretch", FS_REF(params.common.enhancePercentile), 0, 25));
    add(param<float>("enhance-smoothing", gLook, "Contrast enhancement: frames over which the stretch's "
                     "percentiles are smoothed (time constant; 1: each frame's own)",
                     FS_REF(params.common.enhanceSmoothing), 1, 1000));
    {
        OptionSpec s{"background", "", gLook, "Background colour: #RRGGBB, r,g,b in 0..1, black, white, gray",
                     OptionKind::Color, 0, 1, {}, true, nullptr, nullptr};
        s.set = [](RenderOptions& o, const std::string& v) { o.params.common.background = parseColor(v); };
        s.get = [](const RenderOptions& o) { return vec3Text(o.params.common.background); };
        add(s);
    }

    // Dye [issue 20]: changes apply live (session::Playback), hence effect None.
    const std::string gDye = "Dye";
    {
        OptionSpec s{"dye", "", gDye, "Dye source X,Y,Z[:RADIUS[:COLOR]] (repeatable, or ';'-separated): ink released "
                     "at the surface point nearest X,Y,Z, RADIUS in object units (0: " + formatFloat(methods::kDyeRadiusPx) + " pixels at the first frame's view), COLOR a name "
                     "(red, green, blue, yellow, cyan, magenta, orange...), #rrggbb or r,g,b",
                     OptionKind::Text, 0, 0, {}, true, nullptr, nullptr};
        s.set = [](RenderOptions& o, const std::string& v) { o.dye = parseDyeSources(v, "--dye"); };
        s.get = [](const RenderOptions& o) { return dyeSourcesText(o.dye); };
        s.repeatable = true;
        add(s);
        effect(OptionEffect::None);
    }
    add(number("dye-release", gDye, "Frames a dye source emits from its start (0: continuously, a streakline; N: a "
               "blob that then travels)", &RenderOptions::dyeRelease, 0, 100000000));
    effect(OptionEffect::None);
    add(number("dye-decay", gDye, "Dye fades at this rate per data time unit (0: never)", &RenderOptions::dyeDecay, 0,
               1e30));
    effect(OptionEffect::None);
    {
        OptionSpec s{"dye-file", "", gDye, "Dye sources from a JSON file: [{\"point\": [x,y,z], \"radius\": r, "
                     "\"color\": \"red\", \"start\": frame, \"stop\": frame}, ...] (see README)",
                     OptionKind::Path, 0, 0, {}, true, nullptr, nullptr};
        s.set = [](RenderOptions& o, const std::string& v) {
            o.dyeFileSources = v.empty() ? std::vector<methods::DyeSource>{} : readDyeFile(v);
            o.dyeFile = v;
        };
        s.get = [](const RenderOptions& o) { return o.dyeFile; };
        add(s);
        effect(OptionEffect::None);
    }

    // Camera
    const std::string gCam = "Camera";
    add(vec3("eye", "Eye position x,y,z (default: fit the bounds)", &RenderOptions::eye));
    add(vec3("target", "Look-at point x,y,z (default: centre of the bounds)", &RenderOptions::target));
    add(vec3("up", "Up vector x,y,z (default 0,1,0)", &RenderOptions::up));
    add(number("fov", gCam, "Vertical field of view in degrees", &RenderOptions::fov, 1, 170));
    add(number("ortho", gCam, "Orthographic view with this view height (object units; 0: perspective)",
               &RenderOptions::ortho, 0, 1e30));
    add(number("orbit", gCam, "Camera turns this many degrees per frame about the up axis (dynamic case)",
               &RenderOptions::orbit, -180, 180));
    add(textChoice("view", gCam, "View preset as ParaView's camera buttons: +x, -x, +y, -y, +z, -z (look along "
                   "that direction) or iso (default: front, a little above and to the right)",
                   {"", "+x", "-x", "+y", "-y", "+z", "-z", "iso"}, FS_REF(view)));
    {
        OptionSpec s{"up-axis", "", gCam, "The data's up axis (many CFD cases are z-up): orients --view and the "
                     "default view", OptionKind::Choice, 0, 0, {"x", "y", "z"}, true, nullptr, nullptr};
        s.set = [](RenderOptions& o, const std::string& v) {
            if (v != "x" && v != "y" && v != "z") throw ConfigError("--up-axis: '" + v + "' is not one of x, y, z");
            o.upAxis = v[0] - 'x';
        };
        s.get = [](const RenderOptions& o) { return std::string(1, char('x' + o.upAxis)); };
        add(s);
    }
    add(text("camera-path", gCam, "Keyframed camera path (JSON); see README", FS_REF(cameraPath), OptionKind::Path));
    return t;
}

#undef FS_REF

}  // namespace

const std::vector<OptionSpec>& renderOptionTable() {
    static const std::vector<OptionSpec> table = buildTable();
    return table;
}

const OptionSpec* findOption(const std::string& name) {
    for (const OptionSpec& s : renderOptionTable())
        if (s.name == name) return &s;
    return nullptr;
}

void setOption(RenderOptions& o, const std::string& name, const std::string& value) {
    const OptionSpec* s = findOption(name);
    if (!s) throw ConfigError("unknown option '" + name + "'");
    s->set(o, value);
}

std::string defaultText(const OptionSpec& spec) {
    static const RenderOptions defaults;
    return spec.get(defaults);
}

OptionEffect effectOf(const std::string& name) {
    const OptionSpec* s = findOption(name);
    if (!s) throw ConfigError("unknown option '" + name + "'");
    return s->effect;
}

OptionEffect changeEffect(const RenderOptions& a, const RenderOptions& b) {
    OptionEffect e = OptionEffect::None;
    for (const OptionSpec& s : renderOptionTable())
        if (s.effect > e && s.get(a) != s.get(b)) e = s.effect;
    return e;
}

bool isRendererOption(const OptionSpec& s) {
    // What is read (Reload) belongs to the surface, what is written (Output) to the caller.
    return s.effect != OptionEffect::Reload && s.effect != OptionEffect::Output;
}

bool isReadOption(const OptionSpec& s) {
    return s.effect == OptionEffect::Reload && s.name != "input" && s.name != "field";
}

bool inViewerPanel(const OptionSpec& s) {
    // Method and overlay sections, the dye section, the camera read-out.
    if (s.group == "Method" || s.group == "Overlay" || s.group == "Dye") return true;
    return s.name == "eye" || s.name == "target" || s.name == "up" || s.name == "fov" || s.name == "ortho";
}

std::string paraviewProperty(const OptionSpec& s) {
    // The method's options, the dye (sources as --dye's text) and the warm-up that the
    // mapper's frame loop runs; colour map, lighting and background are ParaView's own.
    if (s.group != "Method" && s.group != "Overlay" && s.group != "Dye" && s.name != "warmup") return "";
    if (s.name == "colormap" || s.name == "lighting" || s.name == "background") return "";
    std::string out = "FlowSurf";
    bool up = true;
    for (char c : s.name) {
        if (c == '-') { up = true; continue; }
        out += up ? char(std::toupper(static_cast<unsigned char>(c))) : c;
        up = false;
    }
    return out;
}

void validateRenderOptions(const RenderOptions& o) {
    if (o.input.empty()) throw ConfigError("render: an input file or builtin:NAME is required");
    outputKind(o.output);
    if (o.frames < 1 && outputKind(o.output) != OutputKind::Png)
        throw ConfigError("--frames " + std::to_string(o.frames) + ": '" + o.output +
                          "' is a movie or PNG sequence of --frames frames; it needs at least 1");
    if (!o.flowTexture.empty() && outputKind(o.flowTexture) != OutputKind::Png)
        throw ConfigError("--flow-texture: '" + o.flowTexture + "' must be a .png file");
    if (o.timePerFrame > 0.0 && o.framesPerStep > 0)
        throw ConfigError("--time-per-frame and --frames-per-step cannot be combined");
    if (o.timeStepGiven && (o.timeRange || o.timePerFrame > 0.0 || o.framesPerStep > 0))
        throw ConfigError("--time-step renders one step: it cannot be combined with --time, --time-per-frame or --frames-per-step");
    if (!o.cameraPath.empty() && o.orbit != 0.0f) throw ConfigError("--camera-path and --orbit cannot be combined");
    if (o.up && glm::length(*o.up) == 0.0f) throw ConfigError("--up: the up vector must not be zero");
    if (o.eye && o.target && glm::length(*o.eye - *o.target) == 0.0f)
        throw ConfigError("--eye and --target must differ");
    const methods::CommonParams& c = o.params.common;
    if (c.colorScale == methods::ColorScale::Log && c.colorRange.x <= c.colorRange.y && !c.colorRangeAuto &&
        !(c.colorRange.x > 0.0f))
        throw ConfigError("--color-scale log: --color-range " + formatFloat(c.colorRange.x) + ":" +
                          formatFloat(c.colorRange.y) + " is not positive (a log scale needs MIN > 0)");
}

}  // namespace flowsurf::session
