// flowsurf — what the option table's rows are made with (internal to session/options): the
// builders of the common value types (numbers, choices, flags, text, ranges), each taking
// the row's name, role (group, effect, front ends) and help, and the lists of rows of each
// group (rows_*.cpp) that options.cpp joins into the table.
#pragma once

#include "core/errors.h"
#include "session/options/options.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace flowsurf::session::rows {

// --- the groups' rows, in --help order --------------------------------------------------
std::vector<OptionSpec> inputRows();    // rows_data.cpp
std::vector<OptionSpec> outputRows();   // rows_data.cpp
std::vector<OptionSpec> dataRows();     // rows_data.cpp
std::vector<OptionSpec> methodRows();   // rows_method.cpp
std::vector<OptionSpec> overlayRows();  // rows_overlay.cpp
std::vector<OptionSpec> dyeRows();      // rows_dye_camera.cpp
std::vector<OptionSpec> cameraRows();   // rows_dye_camera.cpp

// The rows' spelling of their roles: {G::Method, E::Rebuild, CommandLine | Config | Panel},
// and kMethodRole.onlyFor({Isa, Ibfvs}) for a row of some methods.
using G = OptionGroup;
using E = OptionEffect;
using enum FrontEnd;
using enum methods::Method;

// The roles most rows share. A setting of the picture: every front end that renders takes it.
inline constexpr FrontEnd kPictureFrontEnds = CommandLine | Config | Panel | Renderer | ParaView;
inline constexpr OptionRole kMethodRole{G::Method, E::Rebuild, kPictureFrontEnds};
inline constexpr OptionRole kOverlayRole{G::Overlay, E::Rebuild, kPictureFrontEnds};
// What ParaView does itself (its own colour map, lighting and background).
inline constexpr OptionRole kOverlayRoleNotParaView{G::Overlay, E::Rebuild, CommandLine | Config | Panel | Renderer};

// A field of RenderOptions as a reference the builders' set/get reach through.
#define FS_REF(expr) [](RenderOptions& o) -> auto& { return o.expr; }

// --- helpers (option_rows.cpp) -----------------------------------------------------------
std::string dashed(const std::string& name);
std::string vec3Text(const glm::vec3& v);
glm::vec2 parseRange(const std::string& text, const std::string& what);  // MIN:MAX with MIN < MAX
OptionSpec shortNamed(std::string shortName, OptionSpec spec);
// An optional x,y,z (unset: fitted to the bounds).
OptionSpec vec3(std::string name, OptionRole role, std::string help, std::optional<glm::vec3> RenderOptions::*field);

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
    if (std::is_integral_v<T> && v != std::floor(v))
        throw ConfigError(dashed(name) + ": '" + t + "' is not an integer");
    if (v < lo || v > hi)
        throw ConfigError(dashed(name) + ": " + t + " is out of range " + formatDouble(lo) + ".." + formatDouble(hi));
    return T(v);
}

// --- builders ------------------------------------------------------------------------------

// A number reached through `ref` (a field of RenderOptions or of its MethodParams).
template <typename T, typename Ref>
OptionSpec param(std::string name, OptionRole role, std::string help, Ref ref, double lo, double hi) {
    const std::string n = name;
    return {.name = std::move(name),
            .role = role,
            .help = std::move(help),
            .kind = std::is_integral_v<T> ? OptionKind::Int : OptionKind::Float,
            .min = lo,
            .max = hi,
            .set = [n, ref, lo, hi](RenderOptions& o, const std::string& t) {
                ref(o) = checkedNumber<T>(n, t, lo, hi);
            },
            .get = [ref](const RenderOptions& o) { return numberText(ref(const_cast<RenderOptions&>(o))); }};
}

// A number field of RenderOptions.
template <typename T>
OptionSpec number(std::string name, OptionRole role, std::string help, T RenderOptions::*field, double lo, double hi) {
    auto ref = [field](RenderOptions& o) -> T& { return o.*field; };
    return param<T>(std::move(name), role, std::move(help), ref, lo, hi);
}

template <typename Enum, size_t N, typename Ref>
OptionSpec choice(std::string name, OptionRole role, std::string help, const methods::EnumNames<Enum, N>& names,
                  Ref ref) {
    std::vector<std::string> choices;
    for (const auto& [value, text] : names) choices.emplace_back(text);
    const std::string n = name;
    return {.name = std::move(name),
            .role = role,
            .help = std::move(help),
            .kind = OptionKind::Choice,
            .choices = std::move(choices),
            .set = [n, &names, ref](RenderOptions& o, const std::string& t) { ref(o) = parseName(names, t, dashed(n)); },
            .get = [&names, ref](const RenderOptions& o) {
                for (const auto& [value, text] : names)
                    if (ref(const_cast<RenderOptions&>(o)) == value) return std::string(text);
                return std::string();
            }};
}

// An integer restricted to `values` (a choice of the panel, --help and ParaView).
template <typename Ref>
OptionSpec intChoice(std::string name, OptionRole role, std::string help, Ref ref, const std::vector<int>& values) {
    OptionSpec s = param<int>(std::move(name), role, std::move(help), ref, values.front(), values.back());
    s.kind = OptionKind::Choice;
    for (int v : values) s.choices.push_back(std::to_string(v));
    s.set = [number = s.set, what = dashed(s.name), choices = s.choices](RenderOptions& o, const std::string& v) {
        if (std::find(choices.begin(), choices.end(), v) == choices.end()) {
            std::string list;
            for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
            throw ConfigError(what + ": '" + v + "' is not one of " + list);
        }
        number(o, v);
    };
    return s;
}

// A text option restricted to `choices` (kept as text in RenderOptions); the list the
// panel, --help and ParaView show is the list it checks against.
template <typename Ref>
OptionSpec textChoice(std::string name, OptionRole role, std::string help, std::vector<std::string> choices, Ref ref) {
    const std::string n = name;
    const std::vector<std::string> allowed = choices;
    return {.name = std::move(name),
            .role = role,
            .help = std::move(help),
            .kind = OptionKind::Choice,
            .choices = std::move(choices),
            .set = [n, allowed, ref](RenderOptions& o, const std::string& t) {
                if (std::find(allowed.begin(), allowed.end(), t) == allowed.end()) {
                    std::string list;
                    for (const auto& c : allowed)
                        if (!c.empty()) list += (list.empty() ? "" : ", ") + c;
                    throw ConfigError(dashed(n) + ": '" + t + "' is not one of " + list);
                }
                ref(o) = t;
            },
            .get = [ref](const RenderOptions& o) { return std::string(ref(const_cast<RenderOptions&>(o))); }};
}

// on|off switches kept as choices for the command line's compatibility.
template <typename Ref>
OptionSpec onOff(std::string name, OptionRole role, std::string help, Ref ref) {
    const std::string n = name;
    return {.name = std::move(name),
            .role = role,
            .help = std::move(help),
            .kind = OptionKind::Choice,
            .choices = {"on", "off"},
            .set = [n, ref](RenderOptions& o, const std::string& t) {
                if (t != "on" && t != "off") throw ConfigError(dashed(n) + ": '" + t + "' is not one of on, off");
                ref(o) = t == "on";
            },
            .get = [ref](const RenderOptions& o) {
                return std::string(ref(const_cast<RenderOptions&>(o)) ? "on" : "off");
            }};
}

template <typename Ref>
OptionSpec flag(std::string name, OptionRole role, std::string help, Ref ref) {
    const std::string n = name;
    return {.name = std::move(name),
            .role = role,
            .help = std::move(help),
            .kind = OptionKind::Flag,
            .set = [n, ref](RenderOptions& o, const std::string& t) {
                std::string l = t;
                std::transform(l.begin(), l.end(), l.begin(), [](unsigned char c) { return char(std::tolower(c)); });
                if (l == "true" || l == "1" || l == "on" || l.empty()) ref(o) = true;
                else if (l == "false" || l == "0" || l == "off") ref(o) = false;
                else throw ConfigError(dashed(n) + ": '" + t + "' is not true or false");
            },
            .get = [ref](const RenderOptions& o) {
                return std::string(ref(const_cast<RenderOptions&>(o)) ? "true" : "false");
            }};
}

template <typename Ref>
OptionSpec text(std::string name, OptionRole role, std::string help, Ref ref, OptionKind kind = OptionKind::Text) {
    return {.name = std::move(name),
            .role = role,
            .help = std::move(help),
            .kind = kind,
            .set = [ref](RenderOptions& o, const std::string& t) { ref(o) = t; },
            .get = [ref](const RenderOptions& o) { return ref(const_cast<RenderOptions&>(o)); }};
}

// ARRAY or ARRAY:x|y|z|mag, checked for its syntax when set (empty: none).
template <typename Ref>
OptionSpec scalarSpec(std::string name, OptionRole role, std::string help, Ref ref) {
    OptionSpec s = text(std::move(name), role, std::move(help), ref);
    s.set = [ref](RenderOptions& o, const std::string& v) {
        if (!v.empty()) core::ScalarSpec::parse(v);
        ref(o) = v;
    };
    return s;
}

// A range option [docs/cfd.md, colour ranges]: robust | data | auto | MIN:MAX, kept as a given range (lo > hi
// when unset), the auto flag (each frame's data range) and the mode of the whole-data range;
// the panel's rescale buttons.
template <typename Range, typename Auto, typename Mode>
OptionSpec rangeOption(std::string name, OptionRole role, std::string help, Range range, Auto automatic, Mode mode,
                       RangeRescale rescale) {
    const std::string what = dashed(name);
    return {.name = std::move(name),
            .role = role,
            .help = std::move(help),
            .set = [what, range, automatic, mode](RenderOptions& o, const std::string& v) {
                const bool given = !v.empty() && v != "robust" && v != "data" && v != "auto";
                range(o) = given ? parseRange(v, what) : glm::vec2(1, 0);
                automatic(o) = v == "auto";
                mode(o) = v == "data" ? methods::RangeMode::Data : methods::RangeMode::Robust;
            },
            .get = [range, automatic, mode](const RenderOptions& o) {
                RenderOptions& m = const_cast<RenderOptions&>(o);
                const glm::vec2 r = range(m);
                if (automatic(m)) return std::string("auto");
                if (r.x <= r.y) return formatFloat(r.x) + ":" + formatFloat(r.y);
                return std::string(mode(m) == methods::RangeMode::Data ? "data" : "robust");
            },
            .arraySeparator = ":",  // [0, 1] in a config file, (0, 1) in Python: 0:1
            .rescale = rescale};
}

}  // namespace flowsurf::session::rows
