// flowsurf — the option table: the rows of each group (rows_*.cpp, each row declaring its
// group, effect and front ends) joined in --help order, and what is looked up in it.
#include "session/options/options.h"

#include "core/errors.h"
#include "session/options/option_rows.h"

#include <cctype>

namespace flowsurf::session {

const std::vector<OptionSpec>& renderOptionTable() {
    static const std::vector<OptionSpec> table = [] {
        std::vector<OptionSpec> t;
        for (auto group : {rows::inputRows, rows::outputRows, rows::dataRows, rows::methodRows, rows::overlayRows,
                           rows::dyeRows, rows::cameraRows})
            for (OptionSpec& s : group()) t.push_back(std::move(s));
        return t;
    }();
    return table;
}

std::string groupName(OptionGroup group) { return std::string(methods::nameOf(kOptionGroupNames, group)); }

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
    return s->role.effect;
}

OptionEffect changeEffect(const RenderOptions& a, const RenderOptions& b) {
    OptionEffect e = OptionEffect::None;
    for (const OptionSpec& s : renderOptionTable())
        if (s.role.effect > e && s.get(a) != s.get(b)) e = s.role.effect;
    return e;
}

std::string paraviewProperty(const OptionSpec& s) {
    if (!s.takes(FrontEnd::ParaView)) return "";
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
